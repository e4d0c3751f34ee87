// Soft impact orbits: the monodromy from the contacts' variational equations
// (model/contact_tangent_system.hpp, simulation/orbits/stroboscopic_map.hpp) against differences,
// and against the instantaneous map's saltation matrices as the contact stiffens.
//
// The law: hunt-crossley, F = K x^{3/2} (1 + chi xdot), chi = 3 (1 - e)/(2 v0). Its restitution
// e* depends on chi v0 alone, so on e alone (model/damping/hertz_proportional_dashpot.hpp): as the
// contact stiffens at fixed e, the soft rig tends to the instantaneous one with restitution e*, and
// its multipliers to the map's. The body is the paper's steel rod on a steel hemisphere whose
// moduli are multiplied by k (validation/common/steel_rod_setups.hpp). The tangents and the
// monodromy against differences are checked with the paper's law too (hongo: its tau = 2 zeta/omega_n
// set from v0 by eq. 11, so the force depends on v0 through omega_n ~ v0^{1/5}).
#include "hertzdash/simulation/orbits/periodic_orbit.hpp"
#include "hertzdash/simulation/orbits/section_guess.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"
#include "validation/common/steel_rod_setups.hpp"
#include "monodromy_differences.hpp"
#include "stiffening_convergence.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <string>

using namespace hertzdash;

namespace {

constexpr double e = 0.5, f_Hz = 20, gamma = 1.1;

SolverSettings tight() { return gbs8_regularized_solver(1e-11); }

ShakerOptions shaker(ShakerImpactModel model) {
  ShakerOptions o;
  o.wall = {.amplitude_m = shaker_amplitude_m(gamma, f_Hz, stiffened_steel_pair(1, e).gravity_mps2), .frequency_Hz = f_Hz};
  o.impact_model = model;
  return o;
}

/// The shaker's scales: g T^2 for the position, g T for the speed.
Eigen::Vector2d scales() {
  const double g = stiffened_steel_pair(1, e).gravity_mps2, T = 1 / f_Hz;
  return {g * T * T, g * T};
}

/// The period-1 orbit of `spec`, the section in the middle of its flight.
PeriodicOrbit orbit_of(const ImpactSequenceSpec& spec) {
  const SectionGuess g = section_guess(spec, std::nullopt, std::nullopt);
  REQUIRE(g.failure.empty());
  REQUIRE(g.period == 1);
  return find_periodic_orbit(StroboscopicMap(spec, g.section_phase, 1), g.state, scales());
}

/// hunt-crossley's e* at e: the rebound of a contact with nothing else acting (no gravity, no
/// wall motion), at an arbitrary speed (e* does not depend on it).
double hunt_crossley_restitution(const DropTestSetup& s) {
  const ContactTangentRun<HarmonicForcing> contact = make_contact_tangent<HarmonicForcing>("hunt-crossley", s, tight());
  const ContactTangent c = contact(HarmonicForcing{}, 0.3, 1.0);
  REQUIRE(c.separated);
  return c.rebound_speed_mps / 0.3;
}

}  // namespace

TEST_CASE("soft contact tangents: d(t_c, v_sep)/d(t_on, v0) from the variational equations equals differences",
          "[orbit][soft]") {
  // A contact with the shaker's table (gravity, the wall's acceleration, so the onset time
  // matters) at v0 = g T/(1 + e), its tangents against central differences of the same contact
  // (its value columns) with steps 1e-4 of the contact time and of v0: truncation O(1e-8)
  // relative, the integration's error rtol = 1e-11 over the step 1e-4 gives 1e-7; 1e-5 of each
  // entry's scale holds any correct tangent (a missing dF/dv0 term moves d v_sep/d v0 by O(1)).
  const std::string law = GENERATE("hunt-crossley", "hongo");
  CAPTURE(law);
  const DropTestSetup s = stiffened_steel_pair(1, e);
  const ContactTangentRun<HarmonicForcing> contact = make_contact_tangent<HarmonicForcing>(law, s, tight());
  REQUIRE(contact);
  const ShakerOptions o = shaker(ShakerImpactModel::soft);
  const double g = s.gravity_mps2, T = 1 / f_Hz, v0 = g * T / (1 + e), t_on = 0.1 * T;
  auto at = [&](double t, double v) { return contact(harmonic_wall(o.wall, g, 1.0, t), v, 2 * T); };
  const ContactTangent c = at(t_on, v0);
  REQUIRE(c.separated);
  const double dt = 1e-4 * c.contact_time_s, dv = 1e-4 * v0;
  const ContactTangent tp = at(t_on + dt, v0), tm = at(t_on - dt, v0), vp = at(t_on, v0 + dv), vm = at(t_on, v0 - dv);
  const Eigen::Vector2d scale(c.contact_time_s, v0);  // of t_c and v_sep
  const Eigen::Matrix2d fd{{(tp.contact_time_s - tm.contact_time_s) / (2 * dt), (vp.contact_time_s - vm.contact_time_s) / (2 * dv)},
                           {(tp.rebound_speed_mps - tm.rebound_speed_mps) / (2 * dt),
                            (vp.rebound_speed_mps - vm.rebound_speed_mps) / (2 * dv)}};
  const Eigen::Vector2d column_scale(T, v0);  // of t_on and v0
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      CHECK(std::abs(c.jacobian(i, j) - fd(i, j)) * column_scale(j) / scale(i) < 1e-5);
  // The rebound's sensitivity to v0 is close to e* (a speed-independent restitution) and its
  // sensitivity to the onset is the table's acceleration acting for t_c: small, not zero. (Both
  // laws' restitution is speed-independent: hongo's damping term over its spring, tau xdot/x, scales
  // as tau v0/X ~ v0^{-1/5} v0 / v0^{4/5}, a constant.)
  CHECK(c.jacobian(1, 1) == Approx(c.rebound_speed_mps / v0).epsilon(0.01));
}

TEST_CASE("soft orbit: the shaker's soft monodromy equals central differences of its map", "[orbit][soft]") {
  // Steps 1e-6 of the scales: the map's own error (contacts to rtol 1e-11, impacts to 1e-13 T)
  // over the step is ~1e-6 relative, the truncation 1e-12; so 1e-4 of M's O(1) scaled entries.
  const std::string law = GENERATE("hunt-crossley", "hongo");
  CAPTURE(law);
  const ImpactSequenceSpec spec = make_shaker_sequence(stiffened_steel_pair(1, e), law, tight(),
                                                       shaker(ShakerImpactModel::soft)).spec;
  const PeriodicOrbit o = orbit_of(spec);
  REQUIRE(o.converged);
  const SectionGuess g = section_guess(spec, std::nullopt, std::nullopt);
  const StroboscopicMap map(spec, g.section_phase, 1);
  test::require_monodromy_matches_differences(map, o.state, scales(), 1e-4);
}

TEST_CASE("soft orbit: the multipliers converge to the instantaneous map's as the contact stiffens, at order 1 in t_c/T",
          "[orbit][soft]") {
  // The soft period-1 orbit's multipliers against the instantaneous orbit's with hunt-crossley's
  // e* (the rigid limit), the table moving and accelerating and gravity acting during the contact
  // (tests/stiffening_convergence.hpp).
  const double e_star = hunt_crossley_restitution(stiffened_steel_pair(1, e));
  std::printf("shaker: e* = %.9f\n", e_star);
  DropTestSetup rigid_setup = stiffened_steel_pair(1, e);
  rigid_setup.restitution = e_star;
  const PeriodicOrbit rigid = orbit_of(make_shaker_sequence(rigid_setup, "hunt-crossley", tight(),
                                                            shaker(ShakerImpactModel::instantaneous)).spec);
  test::check_stiffening_convergence(rigid, f_Hz, 1, [](double k) {
    return orbit_of(make_shaker_sequence(stiffened_steel_pair(k, e), "hunt-crossley", tight(), shaker(ShakerImpactModel::soft)).spec);
  });
}
