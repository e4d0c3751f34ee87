#pragma once
// Shared by the damping-law tests: a rigid-wall, gravity-free contact set-up with a prescribed
// K, m and v0, and the e_effective of any law on it. The list of laws every standard check runs
// on is tests/tested_laws.hpp (it includes every law: only the tests that check every law
// include it, so editing one law recompiles few tests).
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/calibrate_restitution.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace hertzdash::test {

/// A contact phase with Hertz stiffness K [N/m^{3/2}], mass m [kg], approach speed v0
/// [m/s], input e: rigid flat, no gravity, nylon-like ball whose modulus is chosen so
/// that eq. (3) gives K: K = (4/3) sqrt(R) E / (1 - nu^2).
inline DropTestSetup contact_setup(double K, double mass_kg, double v0_mps, double e, bool no_tension = false) {
  DropTestSetup s{};
  s.mass_kg = mass_kg;
  s.ball_radius_m = 0.0127;
  s.ball = Material{3.0 * K * (1.0 - 0.4 * 0.4) / (4.0 * std::sqrt(s.ball_radius_m)), 0.4};
  s.rod = Material{std::numeric_limits<double>::infinity(), 0.3};
  s.restitution = e;
  s.height_m = 0.0;
  s.impact_velocity_mps = v0_mps;
  s.gravity_mps2 = 0.0;
  s.no_tension = no_tension;
  validate(s);
  return s;
}

/// The paper's steel case at h = 20 mm as a contact phase: K of the nylon ball on a
/// rigid flat, m = 0.778 kg, v0 = sqrt(2 g h) (Tables 1-3 and data/assumptions.csv).
struct ContactScales {
  double K, mass_kg, v0_mps;
};
inline ContactScales paper_steel_contact() {
  const DropTestSetup s = contact_phase_setup(paper_setup(load_paper_parameters(), "steel", 0.02));
  return {hertz_stiffness(s), s.mass_kg, *s.impact_velocity_mps};
}

/// CVODE at rtol 1e-10 with atol 1e-10 of each state component's scale (X and v0: the
/// atol of SolverSettings is relative to them), so every parameter set is solved to the same
/// relative accuracy. Over the few hundred steps of one contact the global error in
/// e_effective stays below ~1e-8.
inline SolverSettings accurate_solver() {
  SolverSettings s;
  s.rtol = 1e-10;
  s.atol = 1e-10;
  return s;
}

/// The damping settings the simulator builds Law with for the set-up `s`: a law with a material
/// time constant (MaterialTimeConstantLaw) gets the A it would calibrate from s's e.
template <class Law>
DampingSettings settings_for(const DropTestSetup& s) {
  if constexpr (MaterialTimeConstantLaw<Law>) return with_calibrated_time_constant<Law>(s).damping;
  else return s.damping;
}

/// e_effective of Law for the contact phase (K, m, v0, e).
template <class Law>
double effective_restitution_of(double K, double mass_kg, double v0_mps, double e, bool no_tension = false) {
  ImpactSimulator sim(accurate_solver());
  const ImpactSummary r = sim.run<Law>(contact_setup(K, mass_kg, v0_mps, e, no_tension));
  return r.separated ? r.e_effective : 0.0;
}

}  // namespace hertzdash::test
