// The impact damper's periodic orbits (simulation/orbits/, a box of its own): a four-dimensional
// section z = (y, u, X, V), the monodromy from the two oscillators' flights and the momentum-
// conserving impacts' saltation matrices, against
//   - the symmetric two-impact orbit of the horizontal damper in closed form (Masri and Caughey,
//     J. Appl. Mech. 33 (1966) 586; derived in tests/masri_caughey.hpp), flowed a quarter period
//     on from the floor impact to the section by the primary's free and forced responses;
//   - det M = e^(2k) exp(-C N T/M) (derived in simulation/orbits/stroboscopic_map.hpp);
//   - central differences of the map;
//   - the map's own iterates on either side of the Neimark-Sacker point continuation reports;
//   - soft impacts: the contact's 4x4 tangents and the soft map's monodromy against differences, and
//     the soft multipliers against the instantaneous ones as the contact stiffens.
#include "hertzdash/simulation/orbits/continuation.hpp"
#include "hertzdash/simulation/orbits/lyapunov.hpp"
#include "hertzdash/simulation/orbits/periodic_orbit.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/shaker/two_walls.hpp"
#include "masri_caughey.hpp"
#include "monodromy_differences.hpp"
#include "stiffening_convergence.hpp"
#include "validation/common/steel_rod_setups.hpp"

#include <catch2/catch.hpp>

#include <Eigen/LU>  // determinant(): Eigen's, independent of the library's

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <optional>
#include <tuple>
#include <vector>

using namespace hertzdash;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double e = 0.6, gap_m = 0.01;

DropTestSetup setup() {
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.restitution = e;
  s.gravity_mps2 = 0;
  s.impact_velocity_mps = 1;  // as the rig's horizontal set-up: instantaneous impacts have no contact scale
  return s;
}

TwoWallsOptions damper(double f_Hz) {
  TwoWallsOptions o;  // the rig's default primary: M = 10 kg, K = 157914 N/m, zeta = 0.02, F0 = 100 N
  o.rig = TwoWallsRig::damper;
  o.gap_m = gap_m;
  o.drive.frequency_Hz = f_Hz;
  o.primary = {.mass_kg = 10, .stiffness_N_per_m = 157914, .damping_ratio = 0.02, .force_amplitude_N = 100};
  return o;
}

ImpactSequenceSpec damper_spec(double f_Hz) { return make_two_walls_sequence(setup(), "hongo-paper", {}, damper(f_Hz)).spec; }

/// The free primary's fundamental matrix over tau: x'' + 2 zeta wn x' + wn^2 x = 0 from (1, 0), (0, 1).
Eigen::Matrix2d free_flight(double wn, double zeta, double tau) {
  const double wd = wn * std::sqrt(1 - zeta * zeta), a = std::exp(-zeta * wn * tau);
  const double c = std::cos(wd * tau), s = std::sin(wd * tau), r = zeta * wn / wd;
  Eigen::Matrix2d phi;
  phi << a * (c + r * s), a * s / wd, -a * wn * wn / wd * s, a * (c - r * s);
  return phi;
}

/// The symmetric orbit: the floor impact's phase and relative speed, and the state a quarter
/// period after it (mid-flight), at section phase floor_phase + 1/4.
struct DamperOrbit {
  double floor_phase = 0, impact_speed_mps = 0, section_phase = 0;
  Eigen::Vector4d section;
};

/// Root `which` of Masri and Caughey's (the + sign first) for a body of mass m [kg] and
/// restitution e_r, if it exists: a quarter period after the floor impact at t1 the body is at
/// X(t1) + u1 T/4, the primary at Xp(t1 + T/4) + Phi(T/4) ((X(t1), V+) - P(t1)), P = (Xp, Xp') its
/// particular solution Re(Q e^{iwt}).
std::optional<DamperOrbit> symmetric_orbit(double f_Hz, int which, double m = setup().mass_kg, double e_r = e) {
  ForcedOscillator primary = damper(f_Hz).primary;
  primary.omega_rad_per_s = 2 * pi * f_Hz;
  const std::vector<test::SymmetricOrbit> roots = test::masri_caughey_orbits(primary, m, e_r, gap_m, f_Hz);
  if (which >= static_cast<int>(roots.size())) return std::nullopt;
  const test::SymmetricOrbit& r = roots[static_cast<std::size_t>(which)];
  const double w = primary.omega_rad_per_s, T = 1 / f_Hz, t1 = r.phase * T, tau = T / 4;
  const std::complex<double> Q = primary.particular_amplitude();
  auto particular = [&](double t) {
    const std::complex<double> q = Q * std::exp(std::complex<double>(0, w * t));
    return Eigen::Vector2d(q.real(), (std::complex<double>(0, w) * q).real());
  };
  const Eigen::Vector2d box = particular(t1 + tau) + free_flight(primary.natural_omega_rad_per_s(), primary.damping_ratio, tau) *
                                                        (Eigen::Vector2d(r.X_m, r.V_after_mps) - particular(t1));
  DamperOrbit out{.floor_phase = r.phase, .impact_speed_mps = r.speed_mps, .section_phase = std::fmod(r.phase + 0.25, 1.0),
                  .section = {}};
  out.section << r.X_m + r.u_after_mps * tau, r.u_after_mps, box(0), box(1);
  return out;
}

Eigen::Vector4d scales(const ImpactSequenceSpec& spec) {
  const double v = spec.speed_scale_mps, x = v / spec.frequency_Hz;
  return {x, v, x, v};
}

/// Shooting from the closed form's section state displaced by `offset` of the scales.
PeriodicOrbit shoot(double f_Hz, const DamperOrbit& exact, double offset) {
  const ImpactSequenceSpec spec = damper_spec(f_Hz);
  const Eigen::Vector4d s = scales(spec);
  return find_periodic_orbit(StroboscopicMap(spec, exact.section_phase, 1), exact.section + offset * s, s);
}

}  // namespace

TEST_CASE("orbit damper: shooting finds the horizontal damper's symmetric orbit of the closed form", "[orbit]") {
  // A gap of 10 mm, e = 0.6: at 22 Hz the faster root (the - sign) is a stable orbit (a complex pair of
  // multipliers of modulus 0.85), at 16 Hz the slower one a saddle (a real multiplier near 6),
  // Newton started 1 % and 0.1 % of the scales off them (the saddle's basin is the narrower). Newton stops at 1e-11 of the scales; the state's error is that over the conditioning of
  // M - I (below 1e3 here), so 1e-8 of the scales and of the speed bound it.
  for (const auto& [f, which, stable, offset] : {std::tuple{22.0, 1, true, 1e-2}, std::tuple{16.0, 0, false, 1e-3}}) {
    const std::optional<DamperOrbit> exact = symmetric_orbit(f, which);
    REQUIRE(exact);
    const PeriodicOrbit o = shoot(f, *exact, offset);
    INFO(f << " Hz, root " << which << ": " << o.failure);
    REQUIRE(o.converged);
    REQUIRE(o.impacts.size() == 2);
    const SequenceImpact& floor = o.impacts[0].wall == Wall::floor ? o.impacts[0] : o.impacts[1];
    const SequenceImpact& ceiling = o.impacts[0].wall == Wall::floor ? o.impacts[1] : o.impacts[0];
    REQUIRE(floor.wall != ceiling.wall);
    CHECK(std::abs(floor.phase - exact->floor_phase) < 1e-8);
    CHECK(std::abs(std::fmod(ceiling.phase - floor.phase + 1.0, 1.0) - 0.5) < 1e-8);
    CHECK(std::abs(floor.impact_speed_mps - exact->impact_speed_mps) < 1e-8 * exact->impact_speed_mps);
    CHECK(std::abs(ceiling.impact_speed_mps - exact->impact_speed_mps) < 1e-8 * exact->impact_speed_mps);
    const Eigen::Vector4d s = scales(damper_spec(f));
    CHECK((o.state - exact->section).cwiseQuotient(s).lpNorm<Eigen::Infinity>() < 1e-8);
    CHECK(o.stable == stable);
    // det M = e^4 exp(-C T/M), C/M = 2 zeta wn: the flux of both oscillators and two impacts.
    const double det = std::pow(e, 4) * std::exp(-2 * 0.02 * std::sqrt(15791.4) / f);
    CHECK(std::abs(o.monodromy.determinant() - det) < 1e-12 * det);
  }
}

TEST_CASE("orbit damper: the monodromy against central differences, and det M along a transient", "[orbit]") {
  // Off the orbit (1 % off the symmetric one at 24 Hz, unstable, three periods), the map's Jacobian against
  // central differences with steps 1e-6 of the scales: O(h^2) truncation and O(eps/h) round-off,
  // both below 1e-7 of the O(1) scaled entries, checked at 1e-6 (as tests/test_orbits.cpp).
  const std::optional<DamperOrbit> exact = symmetric_orbit(24, 1);
  REQUIRE(exact);
  const ImpactSequenceSpec spec = damper_spec(24);
  const StroboscopicMap map(spec, exact->section_phase, 3);
  const Eigen::Vector4d s = scales(spec);
  const Eigen::Vector4d z = exact->section + 0.01 * s;
  const SectionImage image = test::require_monodromy_matches_differences(map, z, s, 1e-6);
  REQUIRE(image.impacts.size() >= 4);
  // k impacts in 3 periods: det M = e^(2k) exp(-3 C T/M) whatever the trajectory.
  const double k = static_cast<double>(image.impacts.size());
  const double det = std::pow(e, 2 * k) * std::exp(-3 * 2 * 0.02 * std::sqrt(15791.4) / 24);
  CHECK(std::abs(image.monodromy.determinant() - det) < 1e-11 * det);
  // The Lyapunov exponents' sum is the same identity, accumulated over 64 periods.
  const LyapunovSpectrum l = lyapunov_spectrum(StroboscopicMap(spec, exact->section_phase, 1), z, {.periods = 64});
  INFO(l.failure);
  REQUIRE(l.failure.empty());
  REQUIRE(l.per_impact.size() == 4);
  CHECK(std::abs(l.sum_per_impact - l.expected_sum_per_impact) < 1e-10 * std::abs(l.expected_sum_per_impact));
}

TEST_CASE("orbit damper: continuation in the frequency finds where the symmetric orbit loses stability", "[orbit]") {
  // From the closed form at 22 Hz, whose complex pair lies inside the unit circle, towards 25 Hz:
  // the pair leaves it at a Neimark-Sacker point. There the moduli of the pair are 1, and the
  // map's own iterates decide independently of the multipliers: a start 1e-6 of the scales off the
  // orbit comes back towards it 0.2 Hz below the point and leaves it 0.2 Hz above. The pair's
  // modulus moves by about 0.18 per Hz (0.85 at 22 Hz, 1.12 at 24), about 1 -+ 0.036 there, so
  // over 200 periods the distance shrinks about 1500-fold on one side and grows about 1200-fold on
  // the other, still near the orbit; the test asks for 10-fold.
  const std::optional<DamperOrbit> exact = symmetric_orbit(22, 1);
  REQUIRE(exact);
  const ImpactSequenceSpec spec = damper_spec(22);
  const ContinuationOptions o{.from = 22, .to = 25, .period = 1, .section_phase = exact->section_phase,
                              .start = exact->section, .scale = scales(spec)};
  const Continuation c = continue_periodic_orbits([](double f) { return damper_spec(f); }, o);
  const auto ns = std::ranges::find_if(c.events, [](const BranchEvent& ev) { return ev.type == BranchEventType::neimark_sacker; });
  REQUIRE(ns != c.events.end());
  const double f_ns = ns->parameter;
  INFO("Neimark-Sacker at " << f_ns << " Hz");
  REQUIRE(f_ns > 22.2);
  REQUIRE(f_ns < 24.8);
  CHECK(c.events.size() == 1);  // nothing else on the way: the branch reaches 25 Hz
  const double phase_ns = symmetric_orbit(f_ns, 1)->section_phase;
  const PeriodicOrbit at = find_periodic_orbit(StroboscopicMap(damper_spec(f_ns), phase_ns, 1), ns->state, scales(spec));
  REQUIRE(at.converged);
  // The located point is within 1e-12 in arclength of the crossing: the pair's modulus is 1 to
  // about the multipliers' slope times that, far below 1e-6.
  CHECK(std::abs(std::abs(at.multipliers[0]) - 1) < 1e-6);
  CHECK(at.multipliers[0].imag() != 0);
  for (const double side : {-1.0, 1.0}) {
    const double f = f_ns + 0.2 * side;
    const std::optional<DamperOrbit> orbit = symmetric_orbit(f, 1);
    REQUIRE(orbit);
    const ImpactSequenceSpec at_f = damper_spec(f);
    const Eigen::Vector4d s = scales(at_f);
    const StroboscopicMap map(at_f, orbit->section_phase, 1);
    Eigen::VectorXd z = orbit->section + 1e-6 * s;
    for (int n = 0; n < 200; ++n) {
      const SectionImage image = map(z);
      REQUIRE(image.failure.empty());
      z = image.state;
    }
    const double distance = (z - orbit->section).cwiseQuotient(s).norm(), start = 2e-6;
    if (side < 0) CHECK(distance < 0.1 * start);
    else CHECK(distance > 10 * start);
  }
}

namespace {

// Soft impacts: the paper's steel rod between steel walls whose moduli are multiplied by k
// (validation/common/steel_rod_setups.hpp), horizontal, hunt-crossley (its e* depends on e alone:
// tests/test_orbit_soft.cpp), contacts to rtol 1e-11.
DropTestSetup soft_setup(double k) {
  DropTestSetup s = stiffened_steel_pair(k, e);
  s.gravity_mps2 = 0;
  s.impact_velocity_mps = 1;
  return s;
}

SolverSettings tight() { return gbs8_regularized_solver(1e-11); }

ImpactSequenceSpec soft_damper_spec(double k, double f_Hz) {
  TwoWallsOptions o = damper(f_Hz);
  o.impact_model = ShakerImpactModel::soft;
  return make_two_walls_sequence(soft_setup(k), "hunt-crossley", tight(), o).spec;
}

/// The soft damper's orbit near the symmetric one of restitution e_r at f [Hz].
PeriodicOrbit soft_orbit(const ImpactSequenceSpec& spec, double f_Hz, double e_r) {
  const std::optional<DamperOrbit> start = symmetric_orbit(f_Hz, 1, soft_setup(1).mass_kg, e_r);
  REQUIRE(start);
  return find_periodic_orbit(StroboscopicMap(spec, start->section_phase, 1), start->section, scales(spec));
}

}  // namespace

TEST_CASE("soft contact tangents with the damper's primary: the 4x4 Jacobian equals differences", "[orbit][soft]") {
  // A contact with the primary (SprungPrimary: its spring, dashpot and drive act through it) at
  // v0 = 0.5 m/s, the primary at X0 = 1 mm, V0 = 0.1 m/s. d(t_c, v_sep, X_sep, V_sep)/d(t_on, v0,
  // X0, V0) from the variational equations against central differences of the same contact with
  // steps 1e-4 of each input's scale: truncation O(1e-8), the integration's rtol 1e-11 over the
  // step 1e-7; 1e-5 of each entry's scale holds a correct tangent.
  const DropTestSetup s = soft_setup(1);
  const ContactTangentRun<SprungPrimary> contact = make_contact_tangent<SprungPrimary>("hunt-crossley", s, tight());
  REQUIRE(contact);
  const TwoWallsOptions o = damper(22);
  ForcedOscillator primary = o.primary;
  primary.omega_rad_per_s = 2 * pi * 22;
  const double T = 1 / 22.0;
  const Eigen::Vector4d input(0.1 * T, 0.5, 1e-3, 0.1);
  auto at = [&](const Eigen::Vector4d& p) { return contact(SprungPrimary{primary, 0, 1, p(0), p(2), p(3)}, p(1), T); };
  const ContactTangent c = at(input);
  REQUIRE(c.separated);
  REQUIRE(c.jacobian.rows() == 4);
  const Eigen::Vector4d column_scale(T, 0.5, 1e-3, 0.5), row_scale(c.contact_time_s, 0.5, 1e-3, 0.5);
  auto outputs = [](const ContactTangent& t) {
    return Eigen::Vector4d(t.contact_time_s, t.rebound_speed_mps, t.other_state(0), t.other_state(1));
  };
  for (int j = 0; j < 4; ++j) {
    Eigen::Vector4d step = Eigen::Vector4d::Zero();
    step(j) = 1e-4 * (j == 0 ? c.contact_time_s : column_scale(j));
    const Eigen::Vector4d fd = (outputs(at(input + step)) - outputs(at(input - step))) / (2 * step(j));
    for (int i = 0; i < 4; ++i) CHECK(std::abs(c.jacobian(i, j) - fd(i)) * column_scale(j) / row_scale(i) < 1e-5);
  }
}

TEST_CASE("soft orbit damper: the monodromy equals central differences of the map", "[orbit][soft]") {
  // The soft damper's orbit near the symmetric one at 22 Hz; steps 1e-6 of the scales: the map's
  // own error (contacts to rtol 1e-11, impacts to 1e-13 T) over the step is ~1e-6 relative, so
  // 1e-4 of M's O(1) scaled entries (as tests/test_orbit_soft.cpp).
  const ImpactSequenceSpec spec = soft_damper_spec(1, 22);
  const PeriodicOrbit o = soft_orbit(spec, 22, e);
  INFO(o.failure);
  REQUIRE(o.converged);
  REQUIRE(o.impacts.size() == 2);
  const StroboscopicMap map(spec, symmetric_orbit(22, 1, soft_setup(1).mass_kg, e)->section_phase, 1);
  test::require_monodromy_matches_differences(map, o.state, scales(spec), 1e-4);
  // A state that is not finite (the primary's velocity NaN, which no gap test sees; a Newton step
  // through a singular matrix) is a failed image, not an exception from a contact's scales.
  const Eigen::Vector4d nan_velocity(o.state(0), o.state(1), o.state(2), std::nan(""));
  CHECK_FALSE(map(nan_velocity).failure.empty());
}

TEST_CASE("soft orbit damper: the multipliers converge to the instantaneous map's as the contact stiffens, order 1 in t_c/T",
          "[orbit][soft]") {
  // As for the shaker (tests/stiffening_convergence.hpp): against the instantaneous damper with
  // hunt-crossley's e* (a free two-body contact's, whatever the masses: chi v0 alone sets it), the
  // soft orbit's multipliers err by O(t_c/T), the primary's spring, dashpot and drive acting
  // during the contact.
  const ContactTangent free = make_contact_tangent<HarmonicForcing>("hunt-crossley", soft_setup(1), tight())(HarmonicForcing{}, 0.3, 1.0);
  REQUIRE(free.separated);
  const double e_star = free.rebound_speed_mps / 0.3;
  std::printf("damper: e* = %.9f\n", e_star);
  const std::optional<DamperOrbit> exact = symmetric_orbit(22, 1, soft_setup(1).mass_kg, e_star);
  REQUIRE(exact);
  DropTestSetup rigid_setup = soft_setup(1);
  rigid_setup.restitution = e_star;
  const ImpactSequenceSpec rigid_spec = make_two_walls_sequence(rigid_setup, "hunt-crossley", tight(), damper(22)).spec;
  const PeriodicOrbit rigid = find_periodic_orbit(StroboscopicMap(rigid_spec, exact->section_phase, 1), exact->section,
                                                  scales(rigid_spec));
  test::check_stiffening_convergence(rigid, 22, 2, [&](double k) { return soft_orbit(soft_damper_spec(k, 22), 22, e_star); });
}
