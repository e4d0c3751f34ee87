// Periodic orbits (simulation/orbits/): the stroboscopic map's monodromy from saltation matrices
// against the bouncing ball's closed forms (the instantaneous shaker), against the impact
// oscillator's determinant, against central differences of the map itself, and shooting onto
// stable and unstable orbits.
//
// The closed forms (derived in tests/test_shaker.cpp for the exact flights): the period-1 orbit
// leaves the wall at phase theta*/(2 pi) with u+ = g T/2 and meets it one period later, where
//   cos theta* = pi (1 - e) / (Gamma (1 + e)),
// two orbits, sin theta* > 0 (the wall decelerating at impact) and sin theta* < 0. Their
// impact-to-impact Jacobian J has det J = e^2 and trace J = 1 + e^2 - (1 + e)^2 Gamma sin theta*.
// The stroboscopic map over one period with one impact is conjugate to J (the same impact, seen
// from a section half a period later), so its multipliers are J's eigenvalues:
//   lambda = trace/2 +- sqrt(trace^2/4 - e^2).
// Half a period after take-off the body is at its apex: y = A sin theta* + g T^2/8, u = 0.
#include "hertzdash/simulation/orbits/periodic_orbit.hpp"
#include "hertzdash/simulation/orbits/section_guess.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/rigs/oscillator_rig.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"
#include "hertzdash/simulation/shaker/two_walls.hpp"
#include "monodromy_differences.hpp"

#include <catch2/catch.hpp>

#include <Eigen/LU>  // determinant(): Eigen's, independent of the library's closed forms

#include <cmath>
#include <complex>
#include <numbers>

using namespace hertzdash;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double e = 0.5, f_Hz = 20;

double gamma_1() { return pi * (1 - e) / (1 + e); }
// Where the stable orbit's multiplier reaches -1: 1 + trace + det = 0, Gamma sin theta* =
// 2 (1 + e^2)/(1 + e)^2, with the existence relation for cos theta* (tests/test_shaker.cpp).
double gamma_2() { return std::hypot(gamma_1(), 2 * (1 + e * e) / ((1 + e) * (1 + e))); }

DropTestSetup setup() {
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.restitution = e;
  return s;
}

ShakerOptions instantaneous(double gamma) {
  ShakerOptions o;
  o.wall = {.amplitude_m = shaker_amplitude_m(gamma, f_Hz, setup().gravity_mps2), .frequency_Hz = f_Hz};
  o.impact_model = ShakerImpactModel::instantaneous;
  return o;
}

ImpactSequenceSpec shaker_spec(double gamma) { return make_shaker_sequence(setup(), "hongo-paper", {}, instantaneous(gamma)).spec; }

/// A period-1 orbit of the closed form: its impact phase, apex state half a period later, and
/// the multipliers of J. `sign` +1: sin theta* > 0 (stable between Gamma_1 and Gamma_2); -1: the saddle.
struct ClosedFormOrbit {
  double impact_phase;
  Eigen::Vector2d apex;
  std::complex<double> lambda_1, lambda_2;  // |lambda_1| >= |lambda_2|
};
ClosedFormOrbit closed_form(double gamma, double sign) {
  const double g = setup().gravity_mps2, T = 1 / f_Hz, A = shaker_amplitude_m(gamma, f_Hz, g);
  const double c = pi * (1 - e) / (gamma * (1 + e)), s = sign * std::sqrt(1 - c * c);
  const double theta = std::atan2(s, c);
  const double phase = theta / (2 * pi) - std::floor(theta / (2 * pi));
  const double trace = 1 + e * e - (1 + e) * (1 + e) * gamma * s;
  const std::complex<double> root = std::sqrt(std::complex<double>(trace * trace / 4 - e * e));
  std::complex<double> l1 = trace / 2 + root, l2 = trace / 2 - root;
  if (std::abs(l2) > std::abs(l1)) std::swap(l1, l2);
  return {phase, Eigen::Vector2d(A * s + g * T * T / 8, 0), l1, l2};
}

/// The shaker's scales: g T^2 for the position, g T for the speed.
Eigen::Vector2d scales() {
  const double g = setup().gravity_mps2, T = 1 / f_Hz;
  return {g * T * T, g * T};
}

/// Shooting from the closed form's apex displaced by 1 % of the scales, the section half a period
/// after the impact.
PeriodicOrbit shoot(double gamma, double sign, int cycles = 1) {
  const ClosedFormOrbit exact = closed_form(gamma, sign);
  const StroboscopicMap map(shaker_spec(gamma), std::fmod(exact.impact_phase + 0.5, 1.0), cycles);
  return find_periodic_orbit(map, exact.apex + 0.01 * scales(), scales());
}

/// The map's monodromy at z against central differences (tests/monodromy_differences.hpp): the
/// differences err by O(h^2 P''') plus round-off O(eps/h), both below 1e-7 of M's entries, which
/// are O(1) in scaled units; 1e-6 checks it. At least two impacts on the way.
void require_monodromy_matches_differences(const StroboscopicMap& map, const Eigen::Vector2d& z, const Eigen::Vector2d& s) {
  CHECK(test::require_monodromy_matches_differences(map, z, s, 1e-6).impacts.size() >= 2);
}

// lambda sorted by modulus, compared as complex numbers (a conjugate pair in either order).
void require_multipliers(const PeriodicOrbit& o, std::complex<double> l1, std::complex<double> l2, double tol) {
  REQUIRE(o.multipliers.size() == 2);
  const bool same = std::abs(o.multipliers[0] - l1) + std::abs(o.multipliers[1] - l2) <
                    std::abs(o.multipliers[0] - l2) + std::abs(o.multipliers[1] - l1);
  CHECK(std::abs(o.multipliers[same ? 0 : 1] - l1) < tol);
  CHECK(std::abs(o.multipliers[same ? 1 : 0] - l2) < tol);
}

}  // namespace

TEST_CASE("orbit: shooting finds the stable period-1 orbit of the bouncing ball and its complex multipliers",
          "[orbit]") {
  // Gamma = 1.3, e = 0.5: cos theta* = (pi/3)/1.3, the impact phase 0.10093859, trace
  // 1.25 - 2.25 * 1.3 * sin theta* = -0.48319720, so lambda = -0.24159860 +- 0.43775577 i, |lambda| = e.
  const ClosedFormOrbit exact = closed_form(1.3, +1);
  CHECK(exact.impact_phase == Approx(0.10093859).margin(1e-8));
  const PeriodicOrbit o = shoot(1.3, +1);
  REQUIRE(o.converged);
  CHECK(o.residual <= 1e-11);
  // Newton converges quadratically from 1 % off: a handful of steps.
  CHECK(o.iterations <= 6);
  // The root search places impacts to 1e-13 T, so the state to a few 1e-13 of its scales.
  CHECK(std::abs(o.state(0) - exact.apex(0)) < 1e-10 * scales()(0));
  CHECK(std::abs(o.state(1) - exact.apex(1)) < 1e-10 * scales()(1));
  REQUIRE(o.impacts.size() == 1);
  CHECK(o.impacts[0].phase == Approx(exact.impact_phase).margin(1e-10));
  CHECK(o.impacts[0].impact_speed_mps == Approx(setup().gravity_mps2 / f_Hz / (1 + e)).epsilon(1e-10));
  require_multipliers(o, {-0.24159860, 0.43775577}, {-0.24159860, -0.43775577}, 1e-8);
  require_multipliers(o, exact.lambda_1, exact.lambda_2, 1e-9);
  CHECK(o.stable);
}

TEST_CASE("orbit: shooting converges on the unstable period-1 orbit (the saddle) too", "[orbit]") {
  // sin theta* < 0: impact phase 1 - 0.10093859 = 0.89906141, trace 1.25 + 1.73318 = 2.98318,
  // lambda = 2.89689799 and 0.08629921 (product e^2 = 0.25). Brute force never shows it.
  const ClosedFormOrbit exact = closed_form(1.3, -1);
  CHECK(exact.impact_phase == Approx(0.89906141).margin(1e-8));
  const PeriodicOrbit o = shoot(1.3, -1);
  REQUIRE(o.converged);
  CHECK(std::abs(o.state(0) - exact.apex(0)) < 1e-10 * scales()(0));
  require_multipliers(o, 2.89689799, 0.08629921, 1e-8);
  require_multipliers(o, exact.lambda_1, exact.lambda_2, 1e-9);
  CHECK_FALSE(o.stable);
}

TEST_CASE("orbit: at the closed-form period-doubling threshold Gamma_2 a multiplier is -1", "[orbit]") {
  // At Gamma_2 = sqrt((pi/3)^2 + (2 * 1.25/2.25)^2) = 1.5268237: trace = 1.25 - 2.5 = -1.25,
  // so lambda = -1 and -0.25. Just below it the orbit is stable, just above it not.
  CHECK(gamma_2() == Approx(1.5268237).margin(1e-7));
  const PeriodicOrbit at = shoot(gamma_2(), +1);
  REQUIRE(at.converged);
  require_multipliers(at, -1.0, -0.25, 1e-9);
  const PeriodicOrbit below = shoot(0.999 * gamma_2(), +1), above = shoot(1.001 * gamma_2(), +1);
  REQUIRE(below.converged);
  REQUIRE(above.converged);
  CHECK(below.stable);
  CHECK_FALSE(above.stable);
  CHECK(above.multipliers[0].real() < -1);
}

TEST_CASE("orbit: the monodromy's determinant is e^(2k) for k impacts, to round-off", "[orbit]") {
  // The free flight's Phi = [[1, tau], [0, 1]] has det 1 (its flow preserves area: Liouville, the
  // vector field (u, -g) has zero divergence), and each saltation matrix
  // S = [[-e, 0], [(1 + e)(g + X'')/(V - u-), -e]] has det e^2 (the relative speed scales by e,
  // the position passes unchanged). So det M = e^(2k) for any state, periodic or not. Here the
  // period-2 orbit just past Gamma_2 (brute force finds it; two impacts in two periods):
  // det M = e^4 = 0.0625.
  ImpactSequenceSpec spec = shaker_spec(1.01 * gamma_2());
  spec.transient = 2000;
  spec.impacts = 40;
  const SectionGuess guess = section_guess(spec, std::nullopt, std::nullopt);
  REQUIRE(guess.failure.empty());
  REQUIRE(guess.period == 2);
  REQUIRE(guess.impacts_per_period == 2);
  const StroboscopicMap map(spec, guess.section_phase, guess.period);
  const PeriodicOrbit o = find_periodic_orbit(map, guess.state, scales());
  REQUIRE(o.converged);
  REQUIRE(o.impacts.size() == 2);
  CHECK(std::abs(o.monodromy.determinant() - std::pow(e, 4)) < 1e-12);
  CHECK(std::abs(o.multipliers[0] * o.multipliers[1] - std::pow(e, 4)) < 1e-12);
  CHECK(o.stable);
  // A state off any orbit with a different number of impacts on the way: still e^(2k).
  const StroboscopicMap long_map(spec, guess.section_phase, 7);
  const SectionImage image = long_map(guess.state + 0.003 * scales());
  REQUIRE(image.failure.empty());
  REQUIRE(image.impacts.size() >= 3);
  CHECK(std::abs(image.monodromy.determinant() - std::pow(e, 2.0 * static_cast<double>(image.impacts.size()))) < 1e-12);
}

TEST_CASE("orbit: the saltation monodromy equals central differences of the map", "[orbit]") {
  // Over 3 periods from a state off the orbit, with at least two impacts on the way.
  const double gamma = 1.3;
  const ClosedFormOrbit exact = closed_form(gamma, +1);
  const StroboscopicMap map(shaker_spec(gamma), std::fmod(exact.impact_phase + 0.5, 1.0), 3);
  const Eigen::Vector2d s = scales();
  require_monodromy_matches_differences(map, exact.apex + Eigen::Vector2d(0.02 * s(0), -0.01 * s(1)), s);
}

TEST_CASE("orbit: the brute-force guess puts the section in the middle of the widest impact-free arc", "[orbit]") {
  // Phases 0.1 and 0.3: the widest free arc runs from 0.3 round to 1.1 (0.8 wide), its middle 0.7;
  // phases 0.05 and 0.95: the widest is 0.05 .. 0.95, middle 0.5; one phase 0.9: middle 0.4.
  const double a[] = {0.3, 0.1}, b[] = {0.95, 0.05}, c[] = {0.9};
  CHECK(widest_gap_middle(a) == Approx(0.7));
  CHECK(widest_gap_middle(b) == Approx(0.5));
  CHECK(widest_gap_middle(c) == Approx(0.4));
  // Soft contacts occupy their duration: 0.1 for 0.5 cycle and 0.7 for 0.1 cycle leave 0.6 .. 0.7
  // (0.1 wide) and 0.8 round to 1.1 (0.3 wide), its middle 0.95.
  const double lengths[] = {0.5, 0.1}, d[] = {0.1, 0.7};
  CHECK(widest_gap_middle(d, lengths) == Approx(0.95));
}

TEST_CASE("orbit: a sticking attractor or a state inside the wall is refused, not shot", "[orbit]") {
  // e = 0.5 at Gamma = 1.02 < Gamma_1 = pi/3 = 1.0472: no period-1 bouncing orbit exists, the
  // body chatters and is carried every period (test_shaker.cpp's sticking case). The kept impacts,
  // all of one chatter sequence, show no period; with the period given, the map is not smooth
  // there (a carried body), and shooting says so.
  ImpactSequenceSpec spec = shaker_spec(1.02);
  spec.transient = 200;
  spec.impacts = 20;
  CHECK_THAT(section_guess(spec, std::nullopt, std::nullopt).failure, Catch::Contains("settles on no period"));
  CHECK_THAT(section_guess(spec, std::nullopt, 1).failure, Catch::Contains("sticks to the wall"));
  // The map itself from a body in flight: within 5 periods its chatter ends on the wall.
  const SectionImage image = StroboscopicMap(spec, 0.5, 5)(Eigen::Vector2d(0.5 * scales()(0), 0));
  CHECK_THAT(image.failure, Catch::Contains("carried by a wall"));
  // A state below the wall: the map refuses it and Newton cannot start from it.
  const StroboscopicMap map(shaker_spec(1.3), 0.6, 1);
  const PeriodicOrbit o = find_periodic_orbit(map, Eigen::Vector2d(-1.0, 0.0), scales());
  CHECK_FALSE(o.converged);
  CHECK_THAT(o.failure, Catch::Contains("not above the wall"));
}

TEST_CASE("orbit: the impact oscillator's monodromy has det e^(2k) exp(-2 zeta wn N T) and matches central differences",
          "[orbit]") {
  // The flight m y'' + c y' + k y = F(t) has the constant variational matrix A = [[0, 1], [-k/m, -c/m]],
  // so det Phi(tau) = exp(trace A tau) = exp(-2 zeta wn tau) (Liouville); at the stop at rest
  // (V = X'' = 0) the saltation matrix's first column is (1, 0) + (f+ - R f-)/u-, whose first
  // entry is 1 + (u+ - u-)/u- = 1 - (1 + e) = -e (u+ = -e u-); its second column is R's (0, -e).
  // So S = [[-e, 0], [., -e]], det S = e^2, whatever the force and the spring. Over N periods with k impacts,
  // det M = e^(2k) exp(-2 zeta wn N T). The rig's defaults (k = 1e4 N/m, zeta = 0.05, F = 10 N,
  // f = 20 Hz, d = 2 mm) with e = 0.7 settle on a period-1 orbit with one impact (brute force).
  DropTestSetup s = setup();
  s.restitution = 0.7;
  OscillatorOptions o;
  o.impact_model = ShakerImpactModel::instantaneous;
  const ImpactSequenceSpec spec = make_oscillator_sequence(s, "hongo-paper", {}, o).spec;
  const SectionGuess guess = section_guess(spec, std::nullopt, std::nullopt);
  REQUIRE(guess.failure.empty());
  const double v = spec.speed_scale_mps;
  const Eigen::Vector2d scale(v / o.frequency_Hz, v);
  const PeriodicOrbit orbit = find_periodic_orbit(StroboscopicMap(spec, guess.section_phase, guess.period), guess.state, scale);
  REQUIRE(orbit.converged);
  REQUIRE(guess.period == 1);
  REQUIRE(orbit.impacts.size() == 1);
  const double wn = std::sqrt(o.stiffness_N_per_m / s.mass_kg);
  const double expected = 0.49 * std::exp(-2 * o.damping_ratio * wn / o.frequency_Hz);
  CHECK(std::abs(orbit.monodromy.determinant() - expected) < 1e-12);
  // Central differences of the map over 2 periods from a state off the orbit: they check the
  // spring's Phi and the force in the saltation matrix.
  require_monodromy_matches_differences(StroboscopicMap(spec, guess.section_phase, 2),
                                        orbit.state + Eigen::Vector2d(0.01 * scale(0), 0.02 * scale(1)), scale);
}

TEST_CASE("orbit: the driven box's two walls: det M = e^(2k) and central differences, floor and ceiling", "[orbit]") {
  // A body between a floor and a ceiling 10 mm above it (the walls rig's driven box), the box
  // moving as A sin(2 pi f t) with Gamma = 3, e = 0.5, f = 20 Hz: brute force settles on a
  // period-1 orbit with one impact on each wall. Both saltation matrices have det e^2 (the ceiling's
  // sigma = -1 flips n and the denominator together), the free flight's Phi det 1: det M = e^4.
  // The differences check the ceiling's saltation matrix, which the shaker's cases do not reach.
  TwoWallsOptions o;
  o.drive = {.amplitude_m = shaker_amplitude_m(3.0, f_Hz, setup().gravity_mps2), .frequency_Hz = f_Hz};
  const ImpactSequenceSpec spec = make_two_walls_sequence(setup(), "hongo-paper", {}, o).spec;
  const SectionGuess guess = section_guess(spec, std::nullopt, std::nullopt);
  REQUIRE(guess.failure.empty());
  const double v = spec.speed_scale_mps;
  const Eigen::Vector2d scale(v / f_Hz, v);
  const PeriodicOrbit orbit = find_periodic_orbit(StroboscopicMap(spec, guess.section_phase, guess.period), guess.state, scale);
  REQUIRE(orbit.converged);
  REQUIRE(orbit.impacts.size() == 2);
  CHECK(orbit.impacts[0].wall != orbit.impacts[1].wall);
  CHECK(std::abs(orbit.monodromy.determinant() - std::pow(e, 4)) < 1e-12);
  CHECK(orbit.stable);
  require_monodromy_matches_differences(StroboscopicMap(spec, guess.section_phase, 3),
                                        orbit.state + Eigen::Vector2d(0.01 * scale(0), 0.01 * scale(1)), scale);
}
