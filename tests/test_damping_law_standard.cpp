// The checks every damping law gets for free. The test list is every law in
// RegisteredLaws (model/damping/registered_laws.cmake) plus the worked example of
// model/README.md, so registering a law is enough to have it checked here.
//
// All runs are the contact phase alone: a rigid flat, no gravity, approach speed v0
// (tests/damping_law_test_support.hpp), solved by CVODE at rtol 1e-10 with atol
// scaled to the impact, so e_effective carries an error of ~1e-8 (a few hundred
// steps at 1e-10). The bounds below are 1e-7: ten times that, far below any
// physical effect tested.
#include "damping_law_test_support.hpp"
#include "tested_laws.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace hertzdash;
using namespace hertzdash::test;

namespace {
constexpr double solver_bound = 1e-7;
}

HERTZDASH_LAW_TEST_CASE(NoEnergyGain, TestedLaws, "Every law: no energy gain (e_effective <= 1) across e and v0",
                        "[damping][standard]") {
  // A passive contact can only dissipate: with the spring conservative and the rest of
  // the force a damper, the rebound speed is at most the approach speed. A law whose
  // coefficients turn negative somewhere in (e, v0) fails here. The grid spans the
  // e range of the restitution map and v0 three decades apart (K, m of the paper).
  const ContactScales p = paper_steel_contact();
  for (const bool clamp : {false, true})
    for (const double v0 : {0.01, 0.1 * p.v0_mps, p.v0_mps, 10.0})
      for (const double e : {0.05, 0.2, 0.5, 0.8, 0.95, 1.0}) {
        const double e_eff = effective_restitution_of<TestType>(p.K, p.mass_kg, v0, e, clamp);
        INFO(TestType::info.name << ": e = " << e << ", v0 = " << v0 << " m/s, clamp = " << clamp
                                 << ", e_effective = " << e_eff);
        CHECK(e_eff <= 1.0 + solver_bound);
        CHECK(e_eff >= 0.0);
      }
}

HERTZDASH_LAW_TEST_CASE(ConservativeTrait, TestedLaws, "Every law: its ConservativeLaw trait says whether it dissipates",
                        "[damping][standard]") {
  // The result checks (simulation/run/result_checks.hpp) name a law dissipative unless it declares
  // `conservative`. A conservative law returns e_effective = 1 whatever the input e; a dissipative
  // one, given e = 0.5, loses energy: its e_effective is below 1 by far more than the solver's
  // error (each law's deficit at e = 0.5 is of order 1 - e, tens of per cent).
  const ContactScales p = paper_steel_contact();
  const double e_eff = effective_restitution_of<TestType>(p.K, p.mass_kg, p.v0_mps, 0.5);
  INFO(TestType::info.name << ": e_effective = " << e_eff << " at input e = 0.5");
  if constexpr (ConservativeLaw<TestType>) CHECK(std::abs(e_eff - 1.0) < solver_bound);
  else CHECK(e_eff < 0.9);
}

HERTZDASH_LAW_TEST_CASE(OnsetContinuity, TestedLaws, "Every law: force at contact onset agrees with its declared continuity",
                        "[damping][standard]") {
  // LawInfo::force_continuous_at_onset declares whether F(0, v0) = 0. The check uses the
  // law's own force at x = 0 and at x = 1e-9 X* (X* = (m v0^2/K)^{2/5} the contact's
  // length scale), at e = 0.5 where every damper is active:
  //  - declared continuous: F(0, v0) = 0 exactly, and F(1e-9 X*, v0) is small against
  //    the force scale K X*^{3/2}: the Hertz-family laws give ~(1e-9)^{1/4} ~ 6e-3 at
  //    most (the DEM dashpot's x^{1/4} weighting); bound 1e-2;
  //  - declared discontinuous: |F(0, v0)| is a finite fraction of K X*^{3/2} (> 1e-3).
  const ContactScales p = paper_steel_contact();
  const ImpactConditions c{p.K, p.mass_kg, p.v0_mps, 0.5};
  const TestType law(c, settings_for<TestType>(contact_setup(p.K, p.mass_kg, p.v0_mps, 0.5)));
  const double X = std::pow(p.mass_kg * p.v0_mps * p.v0_mps / p.K, 0.4);
  const double F_scale = p.K * std::pow(X, 1.5);
  const double F0 = law.force(0.0, p.v0_mps), F_near = law.force(1e-9 * X, p.v0_mps);
  INFO(TestType::info.name << ": F(0, v0) = " << F0 << " N, F(1e-9 X*, v0) = " << F_near << " N, scale "
                           << F_scale << " N");
  if (TestType::info.force_continuous_at_onset) {
    CHECK(F0 == 0.0);
    CHECK(std::abs(F_near) < 1e-2 * F_scale);
  } else {
    CHECK(std::abs(F0) > 1e-3 * F_scale);
  }
}

HERTZDASH_LAW_TEST_CASE(ElasticLimit, TestedLaws, "Every law: e_effective tends to 1 as e tends to 1", "[damping][standard]") {
  // At e = 1 every law's damper vanishes (zeta = 0, chi = 0, beta = 0), so the contact is
  // conservative and e_effective = 1. Approaching e = 1, every law's damping
  // coefficient is O(1 - e), so 1 - e_effective = O(1 - e): the deficit must shrink
  // with 1 - e. Asserted: e_effective(1) = 1 to solver accuracy, the deficit at
  // 1 - e = 1e-3 is below 1e-2 (slope < 10; the laws' slopes are about 0.5-2), and it
  // is at least 5 times smaller than at 1 - e = 1e-2 (linear convergence gives 10).
  const ContactScales p = paper_steel_contact();
  for (const bool clamp : {false, true}) {
    auto deficit = [&](double e) {
      return 1.0 - effective_restitution_of<TestType>(p.K, p.mass_kg, p.v0_mps, e, clamp);
    };
    const double d0 = deficit(1.0), d2 = deficit(1.0 - 1e-2), d3 = deficit(1.0 - 1e-3);
    INFO(TestType::info.name << ", clamp = " << clamp << ": 1 - e_effective = " << d0 << " (e = 1), " << d2
                             << " (e = 0.99), " << d3 << " (e = 0.999)");
    CHECK(std::abs(d0) < solver_bound);
    CHECK(d3 < 1e-2);
    CHECK(d3 <= d2 / 5 + solver_bound);
  }
}
