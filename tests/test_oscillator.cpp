// The impact oscillator with a stop (simulation/rigs/oscillator_rig.hpp): while it does not reach the
// stop, the closed-form linear response (its steady amplitude and phase, and from rest the
// transient's extremes, computed here in real form, independently of the run's complex closed
// form); when it does, the energy balance of the run, with and without sticking on the stop.
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/rigs/oscillator_rig.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace hertzdash;

namespace {

constexpr double pi = std::numbers::pi;

/// The paper's steel rod (m = 0.778 kg) with input e.
DropTestSetup body(double e) {
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.restitution = e;
  return s;
}

/// k = 1e4 N/m (wn = 113.4 rad/s for the rod, 18.0 Hz), zeta = 0.05, F = 10 N at f = 20 Hz
/// (r = w / wn = 1.108, above resonance), the stop at d.
OscillatorOptions oscillator(double d_m, int transient, int impacts) {
  OscillatorOptions o;
  o.stiffness_N_per_m = 1e4;
  o.damping_ratio = 0.05;
  o.force_amplitude_N = 10;
  o.frequency_Hz = 20;
  o.stop_distance_m = d_m;
  o.transient = transient;
  o.impacts = impacts;
  o.impact_model = ShakerImpactModel::instantaneous;
  return o;
}

/// The steady response x = A cos(w t - psi) of m x'' + c x' + k x = F cos(w t): with
/// x = Re(X e^{i w t}), X = F / (k - m w^2 + i c w) = (F / k) / ((1 - r^2) + i 2 zeta r), so
/// A = |X| = (F / k) / sqrt((1 - r^2)^2 + (2 zeta r)^2) and psi = -arg X = atan2(2 zeta r, 1 - r^2).
struct Steady {
  double A, psi, w;
};
Steady steady(const OscillatorOptions& o, double m) {
  const double wn = std::sqrt(o.stiffness_N_per_m / m), w = 2 * pi * o.frequency_Hz, r = w / wn;
  const double zeta = o.damping_ratio;
  return {o.force_amplitude_N / o.stiffness_N_per_m / std::hypot(1 - r * r, 2 * zeta * r),
          std::atan2(2 * zeta * r, 1 - r * r), w};
}

double circle_distance(double a, double b) {
  const double d = std::abs(a - b) - std::floor(std::abs(a - b));
  return std::min(d, 1 - d);
}

/// The energy balance W - D - L = E(end) - E(0) of a run, to `tolerance` of W.
void check_balance(const OscillatorRun& r, double tolerance) {
  const EnergyAccount& a = r.energy;
  std::printf("W %.9g J, D %.9g J, L %.9g J, E0 %.6g J, E1 %.6g J, impacts %ld, sticks %ld\n", a.drive_work_J,
              a.damping_dissipation_J, a.impact_loss_J, a.initial_J, a.final_J, r.impacts_run, r.sticking_episodes);
  CHECK(a.drive_work_J > 0.1);  // not trivially 0 = 0
  CHECK(std::abs(a.drive_work_J - a.damping_dissipation_J - a.impact_loss_J - (a.final_J - a.initial_J)) <=
        tolerance * a.drive_work_J);
}

}  // namespace

TEST_CASE("oscillator: short of the stop, the steady motion is the closed-form linear response", "[oscillator]") {
  // Started on the steady response, x(0) = A cos psi, x'(0) = A w sin psi, the motion is that
  // response exactly, A cos(w t - psi): its amplitude A and its maximum at drive phase psi / (2 pi).
  // The stop at 2 A is never reached: the run follows 10000 cycles without an impact and says so.
  // The amplitude is read at x's extremes (roots of x' refined to roundoff) and the closed form is
  // evaluated at w t up to 4e4 rad (roundoff 1e-11 in phase): 1e-9 is loose for both. The energy
  // balance (drive work = damping, pi c w A^2 a cycle, and the change of energy, both
  // Gauss-Legendre integrals of error far below roundoff) to 1e-9.
  const DropTestSetup s = body(0.7);
  OscillatorOptions o = oscillator(1.0, 0, 10);
  const Steady x = steady(o, s.mass_kg);
  o.stop_distance_m = 2 * x.A;
  o.start_position_m = x.A * std::cos(x.psi);
  o.start_velocity_mps = x.A * x.w * std::sin(x.psi);
  const OscillatorRun r = run_oscillator(s, "hongo", {}, o);
  std::printf("steady amplitude %.9g m (closed form %.9g m), peak phase %.9f (psi / 2 pi %.9f)\n", r.amplitude_m, x.A,
              r.peak_phase, x.psi / (2 * pi));
  CHECK(r.impacts.empty());
  REQUIRE(r.warnings.size() == 1);
  CHECK(r.warnings[0].find("never reaches the stop") != std::string::npos);
  CHECK(r.end_time_s == Approx(10000 / o.frequency_Hz).epsilon(0.02));
  CHECK(r.steady_amplitude_m == Approx(x.A).epsilon(1e-12));
  CHECK(r.amplitude_m == Approx(x.A).epsilon(1e-9));
  CHECK(circle_distance(r.peak_phase, x.psi / (2 * pi)) < 1e-9);
  check_balance(r, 1e-9);
}

TEST_CASE("oscillator: from rest, short of the stop, the run's extremes are the transient's closed form", "[oscillator]") {
  // From rest at x = 0: x(t) = A cos(w t - psi) + exp(-sigma t) (a cos(wd t) + b sin(wd t)),
  // sigma = zeta wn, wd = wn sqrt(1 - zeta^2), x(0) = 0: a = -A cos psi, x'(0) = 0:
  // A w sin psi - sigma a + wd b = 0, b = (sigma a - A w sin psi) / wd. Near resonance the two beat
  // (the homogeneous part decays as exp(-zeta wn t), by 1e-6 in 49 cycles here), and x's largest
  // excursion is in the first beats, below A + sqrt(a^2 + b^2) < 3 A: the stop at 3 A is never
  // reached. The run's amplitude (max - min)/2 over the whole run (transient 0) and the phase of
  // its maximum must be this function's, found here on a grid of 2000 points a cycle over the
  // first 200 cycles and refined by golden-section search: the grid's extremes are certain to the
  // refinement, 1e-12 relative in x; the peak time is flat to second order, 1e-7 of a cycle.
  const DropTestSetup s = body(0.7);
  OscillatorOptions o = oscillator(1.0, 0, 10);
  const double m = s.mass_kg, wn = std::sqrt(o.stiffness_N_per_m / m), zeta = o.damping_ratio;
  const Steady st = steady(o, m);
  const double sigma = zeta * wn, wd = wn * std::sqrt(1 - zeta * zeta);
  const double a = -st.A * std::cos(st.psi), b = (sigma * a - st.A * st.w * std::sin(st.psi)) / wd;
  REQUIRE(st.A + std::hypot(a, b) < 3 * st.A);
  o.stop_distance_m = 3 * st.A;
  auto x = [&](double t) {
    return st.A * std::cos(st.w * t - st.psi) + std::exp(-sigma * t) * (a * std::cos(wd * t) + b * std::sin(wd * t));
  };
  auto extreme = [&](double sign) {  // sign +1: max, -1: min; returns (value, time)
    const double T = 1 / o.frequency_Hz, dt = T / 2000;
    double best = -INFINITY, t_best = 0;
    for (int i = 0; i <= 200 * 2000; ++i)
      if (sign * x(i * dt) > best) best = sign * x(i * dt), t_best = i * dt;
    double lo = std::max(0.0, t_best - dt), hi = t_best + dt;
    const double g = (std::sqrt(5.0) - 1) / 2;
    for (int i = 0; i < 200; ++i) {
      const double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
      if (sign * x(c) > sign * x(d)) hi = d;
      else lo = c;
    }
    return std::pair{x(0.5 * (lo + hi)), 0.5 * (lo + hi)};
  };
  const auto [x_max, t_max] = extreme(1.0);
  const auto [x_min, t_min] = extreme(-1.0);
  const OscillatorRun r = run_oscillator(s, "hongo", {}, o);
  std::printf("from rest: amplitude %.12g m (closed form %.12g m), peak phase %.9f (%.9f)\n", r.amplitude_m,
              0.5 * (x_max - x_min), r.peak_phase, t_max * o.frequency_Hz - std::floor(t_max * o.frequency_Hz));
  CHECK(r.impacts.empty());
  CHECK(x_max > st.A * 1.01);  // the transient matters: its maximum exceeds the steady amplitude
  CHECK(r.amplitude_m == Approx(0.5 * (x_max - x_min)).epsilon(1e-12));
  CHECK(circle_distance(r.peak_phase, t_max * o.frequency_Hz) < 1e-7);
  check_balance(r, 1e-9);
}

TEST_CASE("oscillator: at the stop, drive work equals damping, impact losses and change of energy", "[oscillator]") {
  // E = m x'^2/2 + k x^2/2. Between impacts dE/dt = F cos(w t) x' - c x'^2 (the equation of
  // motion times x'); an instantaneous impact at speed v keeps x = d and loses (1 - e^2) m v^2 / 2
  // (v+ = -e v-); a body left on the stop (x' = 0) neither works nor dissipates. So
  // W - D - L = E(end) - E(0), W and D integrated by the run (Gauss-Legendre, error far below
  // 1e-12 of W on pieces of T/16), L recomputed here from the impacts' speeds, independently of
  // the run's sum. Errors: the impact times (1e-13 T) and roundoff over 2000 impacts: 1e-9 of W is
  // loose. At 20 Hz (above resonance) the stop at half the steady amplitude, e = 0.7; at 5 Hz
  // (r = 0.28) the body follows the force nearly statically, x ~ F cos(w t) / k, and meets the stop
  // at 0.3 F / k slowly each cycle: with e = 0.5 its rebounds die out in chatter and it rests on
  // the stop while F cos(w t) >= k d, tens of times. Each rest adds a loss below m stick_speed^2 / 2
  // (stick_speed = 1e-6 (F + k d)/(m f) < 1e-5 m/s), far below 1e-10 J.
  struct Case {
    double e, f_Hz, d_m;
  };
  const DropTestSetup s0 = body(1);
  const double A = steady(oscillator(1.0, 0, 1), s0.mass_kg).A;
  for (const Case c : {Case{0.7, 20.0, 0.5 * A}, Case{0.5, 5.0, 0.3 * 10 / 1e4}}) {
    INFO("e " << c.e << ", f " << c.f_Hz << " Hz, d " << c.d_m << " m");
    const DropTestSetup s = body(c.e);
    OscillatorOptions o = oscillator(c.d_m, 0, 2000);
    o.frequency_Hz = c.f_Hz;
    const OscillatorRun r = run_oscillator(s, "hongo", {}, o);
    REQUIRE(r.impacts.size() == 2000);
    CHECK(r.warnings.empty());
    CHECK(r.e_effective == Approx(c.e).epsilon(1e-12));
    if (c.f_Hz == 5) CHECK(r.sticking_episodes > 10);
    double L = 0;
    for (const SequenceImpact& i : r.impacts) L += 0.5 * (1 - c.e * c.e) * s.mass_kg * i.impact_speed_mps * i.impact_speed_mps;
    CHECK(std::abs(r.energy.impact_loss_J - L) <= 1e-9 * L + 1e-10 * static_cast<double>(r.sticking_episodes));
    CHECK(L > 0.1);
    check_balance(r, 1e-9);
  }
}
TEST_CASE("oscillator: a stiff soft stop converges to the instantaneous map of its own e_effective", "[oscillator]") {
  // The oscillator above with the stop at 2 mm (inside the steady amplitude) and e = 0.7 settles on
  // a period-1 orbit, one impact a cycle. The paper's rod against a steel pair (E = 200 GPa times
  // `stiffening`, nu 0.3; contact time t_c a few 1e-3 of T, shrinking as stiffening^{-2/5}), input
  // e = 0.7: its orbit must be the instantaneous map's with e = the soft run's own e_effective, to
  // O(t_c / T) in phase and speed (the onset precedes the equivalent instantaneous impact by about
  // half the contact, the spring and the force acting meanwhile), the difference falling by
  // 10^{-2/5} = 0.398 per decade of stiffness (margin 0.1 for the second-order residue).
  // Integration (gbs8-regularized, 1e-10) and root search (1e-13 T) errors: far below.
  SolverSettings gbs8;
  gbs8.integrator = IntegratorKind::gbs8_regularized;
  gbs8.rtol = gbs8.atol = 1e-10;
  const double T = 1 / 20.0;
  double last = 0;
  std::printf("stiffening  t_c/T       e_effective  phase error  speed error (relative)\n");
  for (const double k : {1.0, 10.0, 100.0}) {
    DropTestSetup s = body(0.7);
    s.ball = {2.0e11 * k, 0.3};
    s.rod = {2.0e11 * k, 0.3};
    OscillatorOptions o = oscillator(0.002, 2000, 4);
    o.impact_model = ShakerImpactModel::soft;
    const OscillatorRun soft = run_oscillator(s, "hongo", gbs8, o);
    REQUIRE(soft.pattern.period == 1);
    REQUIRE(soft.pattern.impacts_per_period == 1);
    CHECK(soft.integrator_used == IntegratorKind::gbs8_regularized);
    DropTestSetup map = s;
    map.restitution = soft.e_effective;
    const OscillatorRun inst = run_oscillator(map, "hongo", {}, oscillator(0.002, 2000, 4));
    REQUIRE(inst.pattern.period == 1);
    const SequenceImpact &a = soft.impacts.back(), &b = inst.impacts.back();
    const double d = a.phase - b.phase, error = d - std::round(d), tc = a.contact_time_s;
    const double speed_error = a.impact_speed_mps / b.impact_speed_mps - 1;
    std::printf("%10g  %.4e  %.9f  %+.4e  %+.4e\n", k, tc / T, soft.e_effective, error, speed_error);
    CHECK(std::abs(error) < tc / T);
    CHECK(std::abs(speed_error) < 10 * tc / T);
    if (last != 0) CHECK(error / last == Approx(std::pow(10.0, -0.4)).margin(0.1));
    last = error;
  }
}
