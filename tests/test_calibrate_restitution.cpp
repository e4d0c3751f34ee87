// Calibration of the input restitution (simulation/run/calibrate_restitution.hpp):
// GSL's Brent solver on e_effective(e_input) = target. Each check compares the input e
// found with one known independently of the solver.
#include "damping_law_test_support.hpp"

#include "hertzdash/model/damping/laws/hunt_crossley.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <catch2/catch.hpp>
#include <gsl/gsl_sf_lambert.h>

#include <cmath>

using namespace hertzdash;
using namespace hertzdash::test;

namespace {

// The paper's steel case at h = 20 mm, solved at rtol 1e-10 (e_effective error ~1e-8).
DropTestSetup steel_case() { return paper_setup(load_paper_parameters(), "steel", 0.02); }
ImpactSimulator accurate_simulator() { return ImpactSimulator(accurate_solver()); }

}  // namespace

TEST_CASE("Calibration of an exact law returns the target itself", "[damping][calibration]") {
  // Kelvin-Voigt with tension allowed has e_effective = e_input (closed form, see
  // test_damping_law_restitution.cpp), so the root is e_input = target. The root is
  // bracketed to 1e-10 and e_effective carries ~1e-8 solver error, whose effect on the
  // root is the same size (slope 1): bound 1e-7.
  ImpactSimulator sim = accurate_simulator();
  for (const double target : {0.1, 0.5, 0.795, 0.95}) {
    const RestitutionCalibration c = calibrate_restitution(sim, steel_case(), "kelvin-voigt", target);
    INFO("target " << target << ": e_input " << c.e_input << " after " << c.iterations << " iterations");
    CHECK(std::abs(c.e_input - target) < 1e-7);
    CHECK(std::abs(c.e_effective - target) < 1e-7);
  }
}

TEST_CASE("Calibrated Hunt-Crossley input satisfies the Lambert-W closed form", "[damping][calibration]") {
  // Hunt-Crossley: chi v0 = 3(1 - e_input)/2, and e_effective = (1 + W0(-(1+a) e^{-(1+a)}))/a
  // with a = chi v0 (derived in test_damping_law_restitution.cpp). The calibrated e_input
  // must give the target through that closed form, without any simulation. The slope
  // de_effective/de_input is about 0.5-1, so the solver's ~1e-8 maps to ~1e-8: bound 1e-7.
  ImpactSimulator sim = accurate_simulator();
  for (const double target : {0.6, 0.795, 0.95}) {
    const RestitutionCalibration c = calibrate_restitution(sim, steel_case(), "hunt-crossley", target);
    const double a = HuntCrossley::chi_v0(c.e_input);
    const double closed_form = (1.0 + gsl_sf_lambert_W0(-(1.0 + a) * std::exp(-(1.0 + a)))) / a;
    INFO("target " << target << ": e_input " << c.e_input << ", closed form gives " << closed_form);
    CHECK(std::abs(closed_form - target) < 1e-7);
  }
}

TEST_CASE("Calibration rejects targets a law cannot reach", "[damping][calibration]") {
  // Hunt-Crossley's chi v0 = 3(1 - e)/2 is at most 3/2, so its e_effective never falls
  // below the closed form at a = 1.5 (about 0.49); "none" is always 1.
  ImpactSimulator sim = accurate_simulator();
  CHECK_THROWS_AS(calibrate_restitution(sim, steel_case(), "hunt-crossley", 0.3), InvalidParameter);
  CHECK_THROWS_AS(calibrate_restitution(sim, steel_case(), "none", 0.5), InvalidParameter);
  CHECK_THROWS_AS(calibrate_restitution(sim, steel_case(), "hongo", 1.5), InvalidParameter);
  CHECK(calibrate_restitution(sim, steel_case(), "none", 1.0).e_input == 1.0);
}
