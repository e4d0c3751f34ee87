// A body between two walls (simulation/shaker/two_walls.hpp): the impact damper's energy balance,
// its limits (a vanishing gap: the mass-augmented oscillator; a vanishing body: the bare one), its
// symmetric two-impacts-per-cycle orbit against the closed form of Masri and Caughey (1966),
// and the driven box's orbits against their closed forms (the shaker's period-1 orbit with the
// ceiling out of reach; the symmetric orbit between both walls, instantaneous and soft).
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/shaker/safe_root.hpp"
#include "hertzdash/simulation/shaker/two_walls.hpp"
#include "masri_caughey.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

using namespace hertzdash;
using hertzdash::test::masri_caughey;
using hertzdash::test::SymmetricOrbit;

namespace {

constexpr double pi = std::numbers::pi;

/// The paper's steel rod (m = 0.778 kg) with input e and gravity g, instantaneous impacts.
DropTestSetup body(double e, double g) {
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.restitution = e;
  s.gravity_mps2 = g;
  if (!(g > 0)) s.impact_velocity_mps = 1.0;  // the drop test's representative speed; not read by the walls
  return s;
}

/// The impact damper: M = 10 kg, k = 157914 N/m (20 Hz), zeta, F0 sin(2 pi f t).
TwoWallsOptions damper(double gap_m, double zeta, double F0_N, double f_Hz, int transient, int impacts) {
  TwoWallsOptions o;
  o.rig = TwoWallsRig::damper;
  o.gap_m = gap_m;
  o.drive.frequency_Hz = f_Hz;
  o.primary = {.mass_kg = 10.0, .stiffness_N_per_m = 157914.0, .damping_ratio = zeta, .force_amplitude_N = F0_N};
  o.transient = transient;
  o.impacts = impacts;
  o.impact_model = ShakerImpactModel::instantaneous;
  return o;
}

/// The driven box X(t) = A sin(2 pi f t).
TwoWallsOptions box(double gap_m, double A_m, double f_Hz, int transient, int impacts, ShakerImpactModel model) {
  TwoWallsOptions o;
  o.rig = TwoWallsRig::box;
  o.gap_m = gap_m;
  o.drive = {.amplitude_m = A_m, .frequency_Hz = f_Hz};
  o.transient = transient;
  o.impacts = impacts;
  o.impact_model = model;
  return o;
}

}  // namespace

TEST_CASE("two walls: the damper's drive work equals its damping, impact losses and change of energy", "[walls]") {
  // Energy of the rig E = M X'^2/2 + k X^2/2 + m u^2/2 + m g y (X from the primary's static
  // equilibrium, so the primary's weight drops out). Between impacts dE/dt = F0 sin(w t) X' - c X'^2
  // (the primary's equation times X'; the body's energy is constant in flight, and a carried body
  // adds (M + m) X' X'' + m g X' = X'(F0 sin - c X' - k X), the same); at an instantaneous impact
  // with relative speed v the energy falls by (1 - e^2) m M v^2 / (2 (m + M)) (momentum conserved,
  // Newton's law). So W - D - L = E(end) - E(0), W and D integrated over the run by the run
  // (Gauss-Legendre, error far below 1e-12 of W on pieces of T/16), L recomputed here from the
  // impacts' speeds, independently of the run's own sum. Errors: the impact times (1e-13 T) and
  // roundoff over ~1000 impacts: 1e-9 of the work is loose. Vertical (g > 0) and horizontal box,
  // and a vertical one with e = 0.3 and gap 5 mm in which the body comes to rest on the floor and
  // is carried (the carried oscillator of mass M + m) hundreds of times.
  struct Case {
    double g, e, gap;
  };
  for (const Case c : {Case{9.80665, 0.6, 0.01}, Case{0.0, 0.6, 0.01}, Case{9.80665, 0.3, 0.005}}) {
    const double g = c.g, e = c.e;
    INFO("gravity " << g << ", e " << e);
    const DropTestSetup s = body(e, g);
    const TwoWallsRun r = run_two_walls(s, "hongo", {}, damper(c.gap, 0.02, 100.0, 20.0, 0, 1000));
    REQUIRE(r.impacts.size() == 1000);
    if (e == 0.3) CHECK(r.sticking_episodes > 50);
    const double m = s.mass_kg, M = 10.0;
    double L = 0;
    for (const TwoWallsImpact& i : r.impacts)
      L += 0.5 * (1 - e * e) * m * M / (m + M) * i.impact_speed_mps * i.impact_speed_mps;
    const EnergyAccount& a = r.energy;
    std::printf("g %g: W %.9g J, D %.9g J, L %.9g J (recomputed %.9g), E0 %.6g J, E1 %.6g J, sticks %ld\n", g,
                a.drive_work_J, a.damping_dissipation_J, a.impact_loss_J, L, a.initial_J, a.final_J,
                r.sticking_episodes);
    CHECK(a.drive_work_J > 100);  // the balance is not trivially 0 = 0
    CHECK(a.impact_loss_J > 10);
    // A carried body joins the box with the momentum-conserving velocity: an extra loss of at most
    // m stick_speed^2 / 2 per episode, 1e-9 J here; none when nothing sticks.
    CHECK(std::abs(a.impact_loss_J - L) <= 1e-9 * L + 1e-9 * static_cast<double>(r.sticking_episodes));
    CHECK(std::abs(a.drive_work_J - a.damping_dissipation_J - L - (a.final_J - a.initial_J)) <= 1e-9 * a.drive_work_J);
  }
}

TEST_CASE("two walls: an undriven, undamped damper with e = 1 conserves its energy", "[walls]") {
  // F0 = 0, zeta = 0, e = 1: W = D = L = 0, so E(end) = E(0) = m g gap / 2 (the body released at
  // rest at mid-gap, the primary at rest): the body's fall sets the primary ringing, and the
  // exchanges at the impacts move the energy between them. Conserved to the root search's error
  // (impact times to 1e-13 T) and roundoff over 2000 impacts: 1e-9 relative.
  const DropTestSetup s = body(1.0, 9.80665);
  const TwoWallsRun r = run_two_walls(s, "hongo", {}, damper(0.01, 0.0, 0.0, 20.0, 0, 2000));
  REQUIRE(r.impacts.size() == 2000);
  CHECK(r.energy.initial_J == Approx(s.mass_kg * 9.80665 * 0.005).epsilon(1e-12));
  CHECK(r.energy.drive_work_J == 0);
  CHECK(r.energy.damping_dissipation_J == 0);
  CHECK(r.energy.impact_loss_J == 0);
  CHECK(r.energy.final_J == Approx(r.energy.initial_J).epsilon(1e-9));
  CHECK(r.floor_impacts + r.ceiling_impacts == 2000);
}

TEST_CASE("two walls: as the gap closes the damper becomes the oscillator of mass M + m", "[walls]") {
  // A plastic body (e = 0.01: it comes to rest on the wall after two impacts) in a horizontal box
  // (g = 0) of clearance d: it is carried, leaves the wall where the box decelerates, crosses the
  // gap in t_f ~ sqrt(2 d / a) (a ~ |Q| w^2 the box's acceleration) and is caught by the other
  // wall. While it flies the primary lacks its inertia: the primary's velocity departs from the
  // carried motion's by O(a t_f) (m/M times it) and its displacement by O(a t_f^2) = O(d), restored
  // at the catch. So the steady amplitude tends to the closed form of mass M + m,
  // |Q| = F0 / sqrt((k - (M + m) w^2)^2 + (c w)^2), to first order in d: |A - A_rigid| <= d and the
  // difference falls tenfold per decade of d (observed ratios 0.101-0.096; margin 0.02). The
  // amplitude is read at X's extremes (roots of X' refined to roundoff). The transient (2000
  // impacts, 500 cycles, 25 s) is 60 decay times of the primary (1/(zeta wn) = 0.4 s).
  const DropTestSetup s = body(0.01, 0.0);
  double last = 0;
  for (const double d : {1e-3, 1e-4, 1e-5}) {
    const TwoWallsRun r = run_two_walls(s, "hongo", {}, damper(d, 0.02, 100.0, 20.0, 2000, 200));
    REQUIRE(r.impacts.size() == 200);
    const double difference = r.primary_amplitude_m - r.primary_amplitude_rigid_m;
    std::printf("gap %g m: amplitude %.9g m, M + m closed form %.9g m, difference %+.3e m\n", d,
                r.primary_amplitude_m, r.primary_amplitude_rigid_m, difference);
    CHECK(std::abs(difference) <= d);
    if (last != 0) CHECK(difference / last == Approx(0.1).margin(0.02));
    last = difference;
  }
  // The closed form itself: M + m = 10.778 kg, k = 157914 N/m, c = 2 0.02 sqrt(k M) (the primary's
  // own dashpot), F0 = 100 N, w = 40 pi.
  const double w = 40 * pi, Mm = 10.0 + s.mass_kg, c = 0.04 * std::sqrt(157914.0 * 10.0);
  CHECK(run_two_walls(s, "hongo", {}, damper(1e-3, 0.02, 100.0, 20.0, 10, 10)).primary_amplitude_rigid_m ==
        Approx(100.0 / std::hypot(157914.0 - Mm * w * w, c * w)).epsilon(1e-12));
}

TEST_CASE("two walls: a vanishing body leaves the damper's primary at its bare amplitude", "[walls]") {
  // m -> 0: each impact changes the primary's velocity by m (1 + e) v / (m + M) = O(m/M), so the
  // steady amplitude tends to the bare closed form |Q| = F0 / sqrt((k - M w^2)^2 + (c w)^2)
  // (at resonance here: F0 / (c w) = 15.8 mm) to first order in m/M: the difference falls tenfold
  // per decade of m (observed 0.087-0.097; margin 0.03). Its size: the impacts are a periodic force
  // of mean magnitude at most 2 impacts a cycle times m (1 + e) v f, v <= 2 w |Q| (body and box at
  // most the box's peak speed each), and at resonance the primary answers a force F with F / (c w):
  // |A - |Q|| <= 4 (1 + e) m f |Q| / c. Horizontal box, e = 0.8.
  double last = 0;
  for (const double m : {1e-2, 1e-3, 1e-4}) {
    DropTestSetup s = body(0.8, 0.0);
    s.mass_kg = m;
    const TwoWallsRun r = run_two_walls(s, "hongo", {}, damper(0.01, 0.02, 100.0, 20.0, 2000, 400));
    REQUIRE(r.impacts.size() == 400);
    const double difference = r.primary_amplitude_m - r.primary_amplitude_bare_m;
    std::printf("m %g kg: amplitude %.9g m, bare closed form %.9g m, difference %+.3e m\n", m, r.primary_amplitude_m,
                r.primary_amplitude_bare_m, difference);
    const double c = 0.04 * std::sqrt(157914.0 * 10.0);  // 2 zeta sqrt(k M)
    CHECK(std::abs(difference) <= 4 * 1.8 * m * 20.0 * r.primary_amplitude_bare_m / c);
    if (last != 0) CHECK(difference / last == Approx(0.1).margin(0.03));
    last = difference;
  }
}

TEST_CASE("two walls: the damper settles on the closed-form symmetric orbit of Masri and Caughey", "[walls]") {
  // M = 10 kg, k = 157914 N/m, zeta = 0.05, F0 = 100 N at 20 Hz (resonance), the paper's steel
  // rod (0.778 kg) with e = 0.6 in a horizontal box of clearance 10 mm: one root with u1 > 0
  // (derived above), phase 0.188045, speed 0.785553 m/s; the run reaches it from rest (the orbit
  // attracts). After 4000 impacts only the root search's error (1e-13 T) and the attraction's
  // residue remain: 1e-8 of a cycle and of the speed is loose for both.
  const DropTestSetup s = body(0.6, 0.0);
  TwoWallsOptions o = damper(0.01, 0.05, 100.0, 20.0, 4000, 8);
  ForcedOscillator primary = o.primary;
  primary.omega_rad_per_s = 40 * pi;
  const SymmetricOrbit orbit = masri_caughey(primary, s.mass_kg, 0.6, 0.01, 20.0);
  REQUIRE(orbit.found);
  std::printf("Masri-Caughey symmetric orbit: floor phase %.9f, relative impact speed %.9f m/s\n", orbit.phase,
              orbit.speed_mps);
  const TwoWallsRun r = run_two_walls(s, "hongo", {}, o);
  REQUIRE(r.impacts.size() == 8);
  CHECK(r.pattern.period == 1);
  CHECK(r.pattern.impacts_per_period == 2);
  CHECK(r.impacts_per_cycle == 2);
  CHECK(r.floor_impacts == 4);
  CHECK(r.ceiling_impacts == 4);
  for (const TwoWallsImpact& i : r.impacts) {
    const double expected = i.wall == Wall::floor ? orbit.phase : orbit.phase + 0.5 - std::floor(orbit.phase + 0.5);
    const double d = std::abs(i.phase - expected);
    CHECK(std::min(d, 1 - d) < 1e-8);
    CHECK(i.impact_speed_mps == Approx(orbit.speed_mps).epsilon(1e-8));
    CHECK(i.rebound_speed_mps == Approx(0.6 * orbit.speed_mps).epsilon(1e-8));
  }
}

TEST_CASE("two walls: a driven box whose ceiling is out of reach is the shaker", "[walls]") {
  // Gap 20 mm, the body released at mid-gap: it falls 10 mm onto the floor of a box driven at
  // Gamma = 1.1, 20 Hz, with e = 0.7, and settles on the bouncing ball's period-1 orbit (stable:
  // pi (1 - e)/(1 + e) = 0.554 < Gamma < Gamma_2 = 1.171; from this start the body does not fall
  // into the coexisting chattering orbit), whose apex g T^2 / 8 + A = 3.8 mm above the mean floor
  // is far below the ceiling. Closed form (tests/test_shaker.cpp): cos theta* = pi (1 - e) /
  // (Gamma (1 + e)), relative impact speed g T / (1 + e). The orbit attracts with |eigenvalues|
  // <= 0.95 here (det J = e^2), so after 2000 impacts the root search's error (1e-13 T) alone
  // remains: 1e-9 is loose. The soft contact (the paper's rod on nylon, gbs8-regularized at 1e-10)
  // must land on the shaker's soft orbit, the same fixed point of the same contact code: the same
  // impact to 1e-9, whatever the start. At Gamma = 0.9: the soft contact's e_effective 0.749 puts
  // its own doubling near Gamma_2(0.749) = 1.115, too close to 1.1 to settle within the run.
  const double g = 9.80665, e = 0.7, f = 20.0, T = 1 / f, gamma = 1.1;
  const DropTestSetup s = body(e, g);
  const double A = shaker_amplitude_m(gamma, f, g);
  const TwoWallsRun r = run_two_walls(s, "hongo", {}, box(0.02, A, f, 2000, 10, ShakerImpactModel::instantaneous));
  REQUIRE(r.impacts.size() == 10);
  CHECK(r.pattern.period == 1);
  CHECK(r.ceiling_impacts == 0);
  const double theta = std::acos(pi * (1 - e) / (gamma * (1 + e)));
  for (const TwoWallsImpact& i : r.impacts) {
    CHECK(i.phase == Approx(theta / (2 * pi)).epsilon(1e-9));
    CHECK(i.impact_speed_mps == Approx(g * T / (1 + e)).epsilon(1e-9));
  }
  SolverSettings gbs8;
  gbs8.integrator = IntegratorKind::gbs8_regularized;
  gbs8.rtol = gbs8.atol = 1e-10;
  const double A_soft = shaker_amplitude_m(0.9, f, g);
  ShakerOptions shaker;
  shaker.wall = {.amplitude_m = A_soft, .frequency_Hz = f};
  shaker.transient = 2000;
  shaker.impacts = 2;
  const ShakerRun expected_run = run_shaker(s, "hongo", gbs8, shaker);
  REQUIRE(expected_run.pattern.period == 1);
  const ShakerImpact& expected = expected_run.impacts.back();
  const TwoWallsRun soft = run_two_walls(s, "hongo", gbs8, box(0.02, A_soft, f, 2000, 2, ShakerImpactModel::soft));
  REQUIRE(soft.impacts.size() == 2);
  CHECK(soft.integrator_used == IntegratorKind::gbs8_regularized);
  const TwoWallsImpact& i = soft.impacts.back();
  CHECK(i.phase == Approx(expected.phase).epsilon(1e-9));
  CHECK(i.impact_speed_mps == Approx(expected.impact_speed_mps).epsilon(1e-9));
  CHECK(i.rebound_speed_mps == Approx(expected.rebound_speed_mps).epsilon(1e-9));
  CHECK(i.contact_time_s == Approx(expected.contact_time_s).epsilon(1e-9));
}

TEST_CASE("two walls: a stiff soft contact on floor and ceiling converges to the map of its e_effective", "[walls]") {
  // The driven box at Gamma = 3, 20 Hz, gap 8 mm: with instantaneous impacts (e = 0.7) a period-1
  // orbit hitting the floor and the ceiling once a cycle each. The paper's steel rod against a
  // steel pair (E = 200 GPa times `stiffening`, nu 0.3; contact time t_c ~ 1e-4 s, a few 1e-3 of
  // T, shrinking as stiffening^{-2/5}), input e = 0.7, the ceiling's contact the floor's with its
  // signs reversed: its orbit must be the map's with e = the soft run's own e_effective, to O(t_c
  // / T) (the onset precedes the equivalent instantaneous impact by about half the contact, the
  // box accelerating the body meanwhile), on both walls, the difference falling by 10^{-2/5} =
  // 0.398 per decade of stiffness (margin 0.1 for the second-order residue and the spread of e
  // between impacts). Integration (gbs8-regularized, 1e-10) and root search errors: far below.
  const double g = 9.80665, f = 20.0, T = 1 / f;
  const double A = shaker_amplitude_m(3.0, f, g);
  SolverSettings gbs8;
  gbs8.integrator = IntegratorKind::gbs8_regularized;
  gbs8.rtol = gbs8.atol = 1e-10;
  std::array<double, 2> last{0, 0};
  std::printf("stiffening  t_c/T (floor)  e_effective  phase error floor  ceiling\n");
  for (const double k : {1.0, 10.0, 100.0}) {
    DropTestSetup s = body(0.7, g);
    s.ball = {2.0e11 * k, 0.3};
    s.rod = {2.0e11 * k, 0.3};
    const TwoWallsRun soft = run_two_walls(s, "hongo", gbs8, box(0.008, A, f, 3000, 4, ShakerImpactModel::soft));
    REQUIRE(soft.pattern.period == 1);
    REQUIRE(soft.pattern.impacts_per_period == 2);
    DropTestSetup map = s;
    map.restitution = soft.e_effective;
    const TwoWallsRun inst = run_two_walls(map, "hongo", {}, box(0.008, A, f, 3000, 4, ShakerImpactModel::instantaneous));
    REQUIRE(inst.pattern.period == 1);
    REQUIRE(inst.pattern.impacts_per_period == 2);
    std::array<double, 2> error{0, 0};
    double tc = 0;
    for (const Wall w : {Wall::floor, Wall::ceiling}) {
      auto of = [&](const TwoWallsRun& r) {
        for (const TwoWallsImpact& i : r.impacts)
          if (i.wall == w) return i;
        FAIL("no impact on the " << to_string(w));
        return TwoWallsImpact{};
      };
      const TwoWallsImpact a = of(soft), b = of(inst);
      const double d = a.phase - b.phase;
      error[static_cast<int>(w)] = d - std::round(d);
      tc = std::max(tc, a.contact_time_s);
      CHECK(a.impact_speed_mps == Approx(b.impact_speed_mps).epsilon(10 * a.contact_time_s / T));
    }
    std::printf("%10g  %.4e   %.9f  %+.4e       %+.4e\n", k, tc / T, soft.e_effective, error[0], error[1]);
    for (int w = 0; w < 2; ++w) {
      CHECK(std::abs(error[w]) < tc / T);
      if (last[w] != 0) CHECK(error[w] / last[w] == Approx(std::pow(10.0, -0.4)).margin(0.1));
      last[w] = error[w];
    }
  }
}

TEST_CASE("two walls: the damper's stiff soft contact converges to the map of its e_effective", "[walls]") {
  // The symmetric orbit of the Masri-Caughey test above (horizontal box, zeta 0.05, resonance,
  // gap 10 mm, input e = 0.6) with the soft contact of a steel pair (E = 200 GPa times
  // `stiffening`): the contact force acts on the body and the primary, integrated together
  // (model/contact_environments.hpp). Its orbit must be the instantaneous map's with e = the soft run's
  // own e_effective (its closed form, masri_caughey above), to O(t_c / T) in phase and speed, the
  // difference falling by 10^{-2/5} = 0.398 a decade of stiffness (t_c ~ stiffening^{-2/5};
  // margin 0.1). Integration (gbs8-regularized, 1e-10) and root search errors: far below.
  const double f = 20.0, T = 1 / f;
  SolverSettings gbs8;
  gbs8.integrator = IntegratorKind::gbs8_regularized;
  gbs8.rtol = gbs8.atol = 1e-10;
  TwoWallsOptions o = damper(0.01, 0.05, 100.0, f, 4000, 8);
  o.impact_model = ShakerImpactModel::soft;
  ForcedOscillator primary = o.primary;
  primary.omega_rad_per_s = 2 * pi * f;
  double last = 0;
  std::printf("stiffening  t_c/T       e_effective  phase error  speed error (relative)\n");
  for (const double k : {1.0, 10.0, 100.0}) {
    DropTestSetup s = body(0.6, 0.0);
    s.ball = {2.0e11 * k, 0.3};
    s.rod = {2.0e11 * k, 0.3};
    const TwoWallsRun r = run_two_walls(s, "hongo", gbs8, o);
    REQUIRE(r.pattern.period == 1);
    REQUIRE(r.pattern.impacts_per_period == 2);
    CHECK(r.integrator_used == IntegratorKind::gbs8_regularized);
    const SymmetricOrbit orbit = masri_caughey(primary, s.mass_kg, r.e_effective, 0.01, f);
    REQUIRE(orbit.found);
    const TwoWallsImpact& i = r.impacts.front().wall == Wall::floor ? r.impacts[0] : r.impacts[1];
    const double d = i.phase - orbit.phase, error = d - std::round(d);
    const double speed_error = i.impact_speed_mps / orbit.speed_mps - 1;
    std::printf("%10g  %.4e  %.9f  %+.4e  %+.4e\n", k, i.contact_time_s / T, r.e_effective, error, speed_error);
    CHECK(std::abs(error) < i.contact_time_s / T);
    CHECK(std::abs(speed_error) < 10 * i.contact_time_s / T);
    if (last != 0) CHECK(error / last == Approx(std::pow(10.0, -0.4)).margin(0.1));
    last = error;
  }
}

TEST_CASE("two walls: the primary's closed form solves its equation from its initial state", "[walls]") {
  // X(t) = Re(Z e^{lambda (t - t0)}) + Re(Q e^{i w t}) + Fc/k (model/forced_oscillator.hpp) must
  // satisfy M X'' + c X' + k X = F0 sin(w t) + Fc and X(t0) = X0, X'(t0) = V0, and each derivative
  // must lie within its bound |Z| wn^n + |Q| w^n after t0. Residuals are roundoff of terms of size
  // k |X| ~ 1e3 N: 1e-9 N relative to them is loose.
  const ForcedOscillator o{.mass_kg = 10.778, .stiffness_N_per_m = 157914.0, .damping_ratio = 0.07,
                           .force_amplitude_N = 100.0, .omega_rad_per_s = 2 * pi * 17.0, .constant_force_N = -7.6};
  const double t0 = 3.21, X0 = 0.004, V0 = -0.3, c = o.damping_N_s_per_m();
  const OscillatorMotion x(o, t0, X0, V0);
  CHECK(x.position_m(t0) == Approx(X0).epsilon(1e-12));
  CHECK(x.velocity_mps(t0) == Approx(V0).epsilon(1e-12));
  for (int i = 0; i <= 40; ++i) {
    const double t = t0 + 0.0123 * i;
    const double residual = o.mass_kg * x.acceleration_mps2(t) + c * x.velocity_mps(t) +
                            o.stiffness_N_per_m * x.position_m(t) - o.force_amplitude_N * std::sin(o.omega_rad_per_s * t) -
                            o.constant_force_N;
    CHECK(std::abs(residual) < 1e-9 * o.stiffness_N_per_m * 0.01);
    for (int n = 1; n <= 4; ++n) CHECK(std::abs(x.derivative(n, t)) <= x.derivative_bound(n));
  }
  // The steady amplitude |Q| = F0 / sqrt((k - M w^2)^2 + (c w)^2) (Den Hartog).
  const double w = o.omega_rad_per_s;
  CHECK(o.steady_amplitude_m() == Approx(100.0 / std::hypot(157914.0 - 10.778 * w * w, c * w)).epsilon(1e-14));
}

TEST_CASE("two walls: the safe root search finds a straight line's root and a graze", "[walls]") {
  // h(t) = 1 - t with M = 0 (a body at constant speed in a box at rest, no gravity): the steps in
  // the forms without cancellation give the root 1 (a naive (|h'| - sqrt(h'^2 - 2 M h)) / M would
  // divide 0 by 0). A parabola h = d + (t - 1)^2 / 2 (M = 1) touching zero (d = 0) is a graze at
  // t = 1; lowered by d = -1e-12 it crosses at 1 - sqrt(2e-12) = 1 - 1.4e-6, a root no fixed step
  // of 0.1 would see; lifted by 1e-12 it has no root before the limit 2.
  const SafeRoot line = first_safe_root([](double t) { return 1 - t; }, [](double) { return -1.0; }, 0.0, 0.0, 10.0, 1e-15);
  REQUIRE(line.found);
  CHECK(line.time_s == Approx(1.0).epsilon(1e-14));
  for (const double d : {0.0, -1e-12, 1e-12}) {
    INFO("d = " << d);
    const SafeRoot r = first_safe_root([d](double t) { return d + 0.5 * (t - 1) * (t - 1); },
                                       [](double t) { return t - 1; }, 1.0, 0.0, 2.0, 1e-15);
    if (d > 0) {
      CHECK_FALSE(r.found);
      CHECK(r.root_free_to_s == 2.0);
    } else {
      REQUIRE(r.found);
      CHECK(r.time_s == Approx(1 - std::sqrt(-2 * d)).margin(1e-7));
      CHECK(r.time_s <= 1 - std::sqrt(-2 * d) + 1e-12);  // never past the first root
    }
  }
}
