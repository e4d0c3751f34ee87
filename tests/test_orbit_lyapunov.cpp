// Lyapunov exponents of the stroboscopic map (simulation/orbits/lyapunov.hpp): a chaotic bouncing
// ball, whose exponents sum to 2 ln e per impact, and a stable periodic orbit, whose exponents are
// the logarithms of its multipliers' moduli.
#include "hertzdash/simulation/orbits/lyapunov.hpp"
#include "hertzdash/simulation/orbits/section_guess.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/rigs/oscillator_rig.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace hertzdash;

namespace {

constexpr double f_Hz = 20;

ImpactSequenceSpec shaker_spec(double e, double gamma) {
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.restitution = e;
  ShakerOptions o;
  o.wall = {.amplitude_m = shaker_amplitude_m(gamma, f_Hz, s.gravity_mps2), .frequency_Hz = f_Hz};
  o.impact_model = ShakerImpactModel::instantaneous;
  o.transient = 2000;
  o.impacts = 100;
  return make_shaker_sequence(s, "hongo-paper", {}, o).spec;
}

/// The spectrum over `periods` from the rig's own run's end, one drive period a step.
LyapunovSpectrum spectrum(double e, double gamma, long periods) {
  const ImpactSequenceSpec spec = shaker_spec(e, gamma);
  const SectionGuess start = section_guess(spec, std::nullopt, 1);
  REQUIRE(start.failure.empty());
  return lyapunov_spectrum(StroboscopicMap(spec, start.section_phase, 1), start.state, {.periods = periods});
}

}  // namespace

TEST_CASE("lyapunov: a chaotic bouncing ball's exponents sum to 2 ln e per impact, the largest positive", "[orbit]") {
  // e = 0.95, Gamma = 2.2: chaotic (no period, no sticking over the run). Flights conserve area
  // (det Phi = 1) and each impact scales it by e^2 (det S = e^2, tests/test_orbits.cpp), so the
  // exponents' sum is log det(M_n ... M_1) / impacts = 2 ln e = -0.102587 per impact whatever the
  // trajectory: the QR accumulation must keep it to round-off (20000 logarithms: ~1e-12).
  const LyapunovSpectrum s = spectrum(0.95, 2.2, 20000);
  REQUIRE(s.failure.empty());
  CHECK(s.periods == 20000);
  CHECK(s.impacts > 4000);  // high bounces: several periods a flight
  CHECK(std::abs(s.sum_per_impact - 2 * std::log(0.95)) < 1e-10);
  CHECK(s.expected_sum_per_impact == Approx(2 * std::log(0.95)).epsilon(1e-15));
  // Chaos: the largest exponent positive, well beyond the run's convergence (its halves agree to
  // 2 % of it: 1/sqrt(impacts) fluctuations).
  CHECK(s.per_impact[0] > 10 * s.half_difference);
  CHECK(s.per_impact[0] > 0);
  CHECK(s.converged);
  CHECK(s.running_periods.back() == 20000);
}

TEST_CASE("lyapunov: on a stable periodic orbit the exponents are the logs of its multipliers' moduli", "[orbit]") {
  // e = 0.5, Gamma = 1.3: the period-1 orbit's multipliers are a complex pair of modulus e
  // (tests/test_orbits.cpp), so both exponents are ln 0.5 per period and per impact (one impact a
  // period). With a complex pair the QR diagonal oscillates; its averages converge like 1/n:
  // within 1e-3 after 4000 periods.
  const LyapunovSpectrum s = spectrum(0.5, 1.3, 4000);
  REQUIRE(s.failure.empty());
  CHECK(s.impacts == 4000);
  for (const double l : s.per_period) CHECK(std::abs(l - std::log(0.5)) < 1e-3);
  CHECK(std::abs(s.sum_per_impact - 2 * std::log(0.5)) < 1e-12);
  CHECK(s.converged);
}

TEST_CASE("lyapunov: with a dashpot the sum per impact is 2 ln e - (c/m) T periods/impacts", "[orbit]") {
  // The impact oscillator (the rig's defaults, zeta = 0.05, e = 0.7): each flight's Phi has
  // det exp(-c tau/m) (Liouville), so over the run log det = 2 ln e impacts - (c/m) T periods;
  // the spectrum's sum must equal it to round-off, and the expected value the library states is
  // recomputed here from the oscillator's own constants.
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.restitution = 0.7;
  OscillatorOptions o;
  o.impact_model = ShakerImpactModel::instantaneous;
  const ImpactSequenceSpec spec = make_oscillator_sequence(s, "hongo-paper", {}, o).spec;
  const SectionGuess start = section_guess(spec, std::nullopt, 1);
  REQUIRE(start.failure.empty());
  const LyapunovSpectrum l = lyapunov_spectrum(StroboscopicMap(spec, start.section_phase, 1), start.state, {.periods = 2000});
  REQUIRE(l.failure.empty());
  REQUIRE(l.impacts > 0);
  const double c_over_m = 2 * o.damping_ratio * std::sqrt(o.stiffness_N_per_m / s.mass_kg);
  const double expected = 2 * std::log(0.7) - c_over_m / o.frequency_Hz * static_cast<double>(l.periods) /
                                                  static_cast<double>(l.impacts);
  CHECK(l.expected_sum_per_impact == Approx(expected).epsilon(1e-12));
  CHECK(std::abs(l.sum_per_impact - expected) < 1e-10);
}
