// The impact damper's periodic orbits (simulation/orbits/, a box of its own): a four-dimensional
// section z = (y, u, X, V), the monodromy from the two oscillators' flights and the momentum-
// conserving impacts' saltation matrices, against
//   - the symmetric two-impact orbit of the horizontal damper in closed form (derived below, after
//     Masri and Caughey, J. Appl. Mech. 33 (1966) 586, and Masri, JASA 47 (1970) 229);
//   - det M = e^(2k) exp(-C N T/M) (derived in simulation/orbits/stroboscopic_map.hpp);
//   - central differences of the map;
//   - the map's own iterates on either side of the Neimark-Sacker point continuation reports.
//
// The closed form. A horizontal damper (g = 0): the primary M X'' + C X' + K X = F0 sin(w t), the
// body free between the floor (y = X) and the ceiling (y = X + d). The system is symmetric under
// t -> t + T/2, (X, y - d/2) -> -(X, y - d/2), which swaps the walls; the symmetric orbit strikes
// the floor at t1 and the ceiling at t1 + T/2 at the same relative speed. With the states just
// before the floor impact (X1, V-, u-) and beta = (1 + e)/(m + M), momentum and Newton's law give
//   u+ = u- + M beta (V- - u-),   V+ = V- - m beta (V- - u-);
// the symmetry, the body's velocity constant in flight, u+ = -u-, so u- = k_u V-,
// k_u = -M beta / (2 - M beta), and V+ = k_V V-, k_V = 1 - m beta (1 - k_u). The body crosses the
// gap in T/2: (X(t1 + T/2) + d) - X1 = u+ T/2 with X(t1 + T/2) = -X1, so X1 = (d + u- T/2)/2.
// The primary's flight over T/2, Phi = exp(A T/2) of its free equation and P(t) = (Xp, Xp') its
// particular solution Re(Q e^{iwt}), Q = -i F0/(K - M w^2 + i C w), with P(t + T/2) = -P(t):
//   (-X1, -V-) - P(t1 + T/2) = Phi ((X1, V+) - P(t1))   =>   (I + Phi) P(t1) = (X1, V-) + Phi (X1, V+),
// linear in V-: p(V-) = (I + Phi)^-1 (L0 + L1 V-) = P(t1). P(t1) = (Re q, -w Im q) with q = Q e^{i w t1}
// of modulus |Q|, so p_x^2 + (p_v / w)^2 = |Q|^2, a quadratic in V-, and w t1 = arg(p_x - i p_v/w) - arg Q.
#include "hertzdash/simulation/orbits/continuation.hpp"
#include "hertzdash/simulation/orbits/lyapunov.hpp"
#include "hertzdash/simulation/orbits/periodic_orbit.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/shaker/two_walls.hpp"

#include <catch2/catch.hpp>

#include <Eigen/LU>  // determinant(): Eigen's, independent of the library's

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <optional>
#include <tuple>

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

/// The symmetric orbit (see above): the floor impact's phase and relative speed, and the state a
/// quarter period after it (mid-flight), at section phase floor_phase + 1/4.
struct SymmetricOrbit {
  double floor_phase = 0, impact_speed_mps = 0, section_phase = 0;
  Eigen::Vector4d section;
};

/// The root `which` (0: the larger V-) of the quadratic, if the orbit exists there.
std::optional<SymmetricOrbit> symmetric_orbit(double f_Hz, int which) {
  const TwoWallsOptions o = damper(f_Hz);
  const double M = o.primary.mass_kg, K = o.primary.stiffness_N_per_m, zeta = o.primary.damping_ratio;
  const double m = setup().mass_kg, C = 2 * zeta * std::sqrt(K * M), wn = std::sqrt(K / M);
  const double w = 2 * pi * f_Hz, T = 1 / f_Hz, beta = (1 + e) / (m + M);
  const std::complex<double> Q = std::complex<double>(0, -1) * o.primary.force_amplitude_N / std::complex<double>(K - M * w * w, C * w);
  const double k_u = -M * beta / (2 - M * beta), k_V = 1 - m * beta * (1 - k_u);
  const Eigen::Matrix2d phi = free_flight(wn, zeta, T / 2);
  // X1 = x0 + x1 V-;  L = (X1, V-) + Phi (X1, V+) = L0 + L1 V-.
  const double x0 = gap_m / 2, x1 = k_u * T / 4;
  const Eigen::Vector2d L0 = Eigen::Vector2d(x0, 0) + phi * Eigen::Vector2d(x0, 0);
  const Eigen::Vector2d L1 = Eigen::Vector2d(x1, 1) + phi * Eigen::Vector2d(x1, k_V);
  const Eigen::Matrix2d W = (Eigen::Matrix2d::Identity() + phi).inverse();
  const Eigen::Vector2d p0 = W * L0, p1 = W * L1;
  const double a = p1(0) * p1(0) + p1(1) * p1(1) / (w * w), b = 2 * (p0(0) * p1(0) + p0(1) * p1(1) / (w * w)),
               c = p0(0) * p0(0) + p0(1) * p0(1) / (w * w) - std::norm(Q);
  const double disc = b * b - 4 * a * c;
  if (disc < 0) return std::nullopt;
  const double V = (-b + (which == 0 ? 1 : -1) * std::sqrt(disc)) / (2 * a), u = k_u * V, X1 = x0 + x1 * V;
  if (!(V - u > 0)) return std::nullopt;  // the body must approach the floor
  const Eigen::Vector2d p = p0 + p1 * V;
  const double theta = std::arg(std::complex<double>(p(0), -p(1) / w)) - std::arg(Q);
  SymmetricOrbit out;
  out.floor_phase = theta / (2 * pi) - std::floor(theta / (2 * pi));
  out.impact_speed_mps = V - u;
  out.section_phase = std::fmod(out.floor_phase + 0.25, 1.0);
  // A quarter period after the floor impact: the body at X1 + u+ T/4; the primary from (X1, V+).
  const double t1 = out.floor_phase * T, tau = T / 4;
  auto particular = [&](double t) {
    const std::complex<double> q = Q * std::exp(std::complex<double>(0, w * t));
    return Eigen::Vector2d(q.real(), (std::complex<double>(0, w) * q).real());
  };
  const Eigen::Vector2d primary = particular(t1 + tau) + free_flight(wn, zeta, tau) * (Eigen::Vector2d(X1, k_V * V) - particular(t1));
  out.section << X1 - u * tau, -u, primary(0), primary(1);
  return out;
}

Eigen::Vector4d scales(const ImpactSequenceSpec& spec) {
  const double v = spec.speed_scale_mps, x = v / spec.frequency_Hz;
  return {x, v, x, v};
}

/// Shooting from the closed form's section state displaced by `offset` of the scales.
PeriodicOrbit shoot(double f_Hz, const SymmetricOrbit& exact, double offset) {
  const ImpactSequenceSpec spec = damper_spec(f_Hz);
  const Eigen::Vector4d s = scales(spec);
  return find_periodic_orbit(StroboscopicMap(spec, exact.section_phase, 1), exact.section + offset * s, s);
}

}  // namespace

TEST_CASE("orbit damper: shooting finds the horizontal damper's symmetric orbit of the closed form", "[orbit]") {
  // A gap of 10 mm, e = 0.6: at 22 Hz the larger V- root is a stable orbit (a complex pair of
  // multipliers of modulus 0.85), at 16 Hz the smaller one a saddle (a real multiplier near 6),
  // Newton started 1 % and 0.1 % of the scales off them (the saddle's basin is the narrower). Newton stops at 1e-11 of the scales; the state's error is that over the conditioning of
  // M - I (below 1e3 here), so 1e-8 of the scales and of the speed bound it.
  for (const auto& [f, which, stable, offset] : {std::tuple{22.0, 0, true, 1e-2}, std::tuple{16.0, 1, false, 1e-3}}) {
    const std::optional<SymmetricOrbit> exact = symmetric_orbit(f, which);
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
  const std::optional<SymmetricOrbit> exact = symmetric_orbit(24, 0);
  REQUIRE(exact);
  const ImpactSequenceSpec spec = damper_spec(24);
  const StroboscopicMap map(spec, exact->section_phase, 3);
  const Eigen::Vector4d s = scales(spec);
  const Eigen::Vector4d z = exact->section + 0.01 * s;
  const SectionImage image = map(z);
  REQUIRE(image.failure.empty());
  REQUIRE(image.impacts.size() >= 4);
  for (int j = 0; j < 4; ++j) {
    Eigen::Vector4d dz = Eigen::Vector4d::Zero();
    dz(j) = 1e-6 * s(j);
    const SectionImage plus = map(z + dz), minus = map(z - dz);
    REQUIRE(plus.impacts.size() == image.impacts.size());
    REQUIRE(minus.impacts.size() == image.impacts.size());
    for (int i = 0; i < 4; ++i) {
      const double fd = (plus.state(i) - minus.state(i)) / (2 * dz(j)) * s(j) / s(i);
      CHECK(std::abs(image.monodromy(i, j) * s(j) / s(i) - fd) < 1e-6 * (1 + std::abs(fd)));
    }
  }
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
  const std::optional<SymmetricOrbit> exact = symmetric_orbit(22, 0);
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
  const double phase_ns = symmetric_orbit(f_ns, 0)->section_phase;
  const PeriodicOrbit at = find_periodic_orbit(StroboscopicMap(damper_spec(f_ns), phase_ns, 1), ns->state, scales(spec));
  REQUIRE(at.converged);
  // The located point is within 1e-12 in arclength of the crossing: the pair's modulus is 1 to
  // about the multipliers' slope times that, far below 1e-6.
  CHECK(std::abs(std::abs(at.multipliers[0]) - 1) < 1e-6);
  CHECK(at.multipliers[0].imag() != 0);
  for (const double side : {-1.0, 1.0}) {
    const double f = f_ns + 0.2 * side;
    const std::optional<SymmetricOrbit> orbit = symmetric_orbit(f, 0);
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
