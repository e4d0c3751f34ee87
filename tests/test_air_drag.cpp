// Air drag in flight (model/air_drag.hpp) and in the bounce sequence: the closed-form flights
// against an independent integration of the drag ODE, their vacuum limit, the energy identity of
// a rise and fall, what drag does to the restitution read from bounce intervals, and the
// refusals where nothing flies.
#include "cli_runner.hpp"

#include "hertzdash/model/air_drag.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/bounce_sequence.hpp"
#include "hertzdash/simulation/run/bounce_trace.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>

using namespace hertzdash;

namespace {

/// u'' = g - sign(v) g v^2 / v_t^2 (downward positive), integrated by classical RK4 with
/// `steps` steps over `duration`: (distance travelled, final velocity). RK4's global error is
/// O(dt^4): with 20000 steps over < 1 s, dt^4 ~ 1e-17 times the derivatives' scale.
std::pair<double, double> integrate_drag(double v_start, double duration, double g, double v_t, int steps = 20000) {
  auto acc = [&](double v) { return g - (v > 0 ? 1.0 : -1.0) * g * v * v / (v_t * v_t); };
  double u = 0, v = v_start;
  const double h = duration / steps;
  for (int i = 0; i < steps; ++i) {
    const double k1u = v, k1v = acc(v);
    const double k2u = v + 0.5 * h * k1v, k2v = acc(v + 0.5 * h * k1v);
    const double k3u = v + 0.5 * h * k2v, k3v = acc(v + 0.5 * h * k2v);
    const double k4u = v + h * k3v, k4v = acc(v + h * k3v);
    u += h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u);
    v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
  }
  return {u, v};
}

/// A 2.7 g ball of 20 mm radius (a ping-pong ball's size and mass) on a rigid flat, e = 0.9.
DropTestSetup ping_pong_ball() {
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.3);
  s.mass_kg = 2.7e-3;
  s.ball_radius_m = 0.020;
  s.restitution = 0.9;
  s.rod.E_Pa = INFINITY;
  return s;
}

}  // namespace

TEST_CASE("air drag: the closed-form fall and rise match an integration of the drag equation", "[air-drag]") {
  // Fall from rest for the closed form's time t_down through D must end at D with the closed
  // form's speed; a rise from v_r for t_up must end at rest (v = 0) at height H. Both to the
  // RK4 integration's error (above: ~1e-12 relative, checked at 1e-9).
  const double g = 9.80665, v_t = 8.6, D = 1.5, v_r = 5.0;
  const Fall fall = fall_from_rest(D, g, v_t);
  const auto [u_fall, v_fall] = integrate_drag(0.0, fall.time_s, g, v_t);
  CHECK(u_fall == Approx(D).epsilon(1e-9));
  CHECK(v_fall == Approx(fall.speed_mps).epsilon(1e-9));
  const Rise rise = rise_to_apex(v_r, g, v_t);
  const auto [u_rise, v_rise] = integrate_drag(-v_r, rise.time_s, g, v_t);
  CHECK(-u_rise == Approx(rise.height_m).epsilon(1e-9));
  CHECK(std::abs(v_rise) < 1e-9 * v_r);
  // A long fall reaches the terminal speed: t -> D / v_t + (v_t / g) ln 2 (acosh(e^a) = a + ln 2
  // + O(e^{-2a})), finite where v has rounded to v_t (D = 2000 m: a = g D / v_t^2 = 265).
  const Fall long_fall = fall_from_rest(2000.0, g, v_t);
  CHECK(long_fall.speed_mps == Approx(v_t).epsilon(1e-15));
  CHECK(long_fall.time_s == Approx(2000.0 / v_t + v_t / g * std::log(2.0)).epsilon(1e-14));
}

TEST_CASE("air drag: without air the flights are the vacuum parabola's", "[air-drag]") {
  // rho = 0 gives v_t = inf and the exact vacuum forms; a huge finite v_t (1e7 m/s, drag 1e-12 of
  // g at 10 m/s) must reach them to rounding through atan, log1p, expm1 and atanh.
  const double g = 9.80665, D = 0.02, v_r = 0.6;
  const AirDrag none;
  REQUIRE(std::isinf(terminal_speed_mps(none, 0.778, 0.0127, g)));
  const double v_vacuum = std::sqrt(2 * g * D);
  CHECK(fall_from_rest(D, g, INFINITY).speed_mps == v_vacuum);
  CHECK(fall_from_rest(D, g, 1e7).speed_mps == Approx(v_vacuum).epsilon(1e-12));
  CHECK(fall_from_rest(D, g, 1e7).time_s == Approx(v_vacuum / g).epsilon(1e-12));
  CHECK(rise_to_apex(v_r, g, 1e7).height_m == Approx(v_r * v_r / (2 * g)).epsilon(1e-12));
  CHECK(rise_to_apex(v_r, g, 1e7).time_s == Approx(v_r / g).epsilon(1e-12));
  CHECK(return_flight(v_r, 0.0, g, INFINITY)->landing_speed_mps == v_r);
}

TEST_CASE("air drag: a rise and fall back lands at 1/v^2 = 1/v_r^2 + 1/v_t^2", "[air-drag]") {
  // H = (v_t^2 / 2g) ln(1 + v_r^2/v_t^2); falling through H: v^2 = v_t^2 (1 - exp(-2 g H / v_t^2))
  // = v_t^2 (1 - 1 / (1 + v_r^2 / v_t^2)) = v_r^2 v_t^2 / (v_t^2 + v_r^2).
  const double g = 9.80665, v_t = 8.6;
  for (const double v_r : {0.5, 2.0, 8.0, 30.0}) {
    const std::optional<ReturnFlight> f = return_flight(v_r, 0.0, g, v_t);
    REQUIRE(f);
    CHECK(1 / (f->landing_speed_mps * f->landing_speed_mps) ==
          Approx(1 / (v_r * v_r) + 1 / (v_t * v_t)).epsilon(1e-13));
    CHECK(f->time_s < 2 * v_r / g);  // drag shortens every flight
  }
  CHECK_FALSE(return_flight(0.1, 1.0, g, v_t));  // an apex below the level never returns
}

TEST_CASE("air drag: the ping-pong ball's terminal speed", "[air-drag]") {
  // v_t = sqrt(2 m g / (rho C_d pi R^2)) with m = 2.7 g, R = 20 mm, rho = 1.204, C_d = 0.47:
  // sqrt(2 * 2.7e-3 * 9.80665 / (1.204 * 0.47 * pi * 4e-4)) = 8.63 m/s (model/air_drag.hpp).
  const AirDrag air{.air_density_kg_per_m3 = 1.204, .drag_coefficient = 0.47};
  CHECK(terminal_speed_mps(air, 2.7e-3, 0.02, 9.80665) == Approx(8.6296).epsilon(1e-4));
}

TEST_CASE("air drag: in a bounce sequence contacts keep their e and flights lose speed", "[air-drag][bounce]") {
  // Drag acts in flight only: each contact's v_r / v0 is the drag-free sequence's at the same v0
  // (same law, same speed), while the approach speed of the next impact follows the rise-and-fall
  // identity above. The first fall from h lands at v_t sqrt(1 - exp(-2 g h / v_t^2)).
  DropTestSetup s = ping_pong_ball();
  s.air_drag = {.air_density_kg_per_m3 = 1.204, .drag_coefficient = 0.47};
  const double g = s.gravity_mps2, v_t = terminal_speed_mps(s.air_drag, s.mass_kg, s.ball_radius_m, g);
  const BounceSequence b = run_bounce_sequence(s, "hunt-crossley", SolverSettings{}, {.impacts = 6});
  REQUIRE(b.impacts.size() == 6);
  CHECK(b.impacts[0].approach_speed_mps ==
        Approx(v_t * std::sqrt(-std::expm1(-2 * g * s.height_m / (v_t * v_t)))).epsilon(1e-14));
  for (std::size_t n = 0; n + 1 < b.impacts.size(); ++n) {
    const double v_r = b.impacts[n].rebound_speed_mps, v_next = b.impacts[n + 1].approach_speed_mps;
    CHECK(1 / (v_next * v_next) == Approx(1 / (v_r * v_r) + 1 / (v_t * v_t)).epsilon(1e-12));
  }
  // The same contact without air, at the drag run's third approach speed, rebounds alike (one
  // impact of the same law at the same speed; CVODE's default tolerance 1e-8).
  DropTestSetup vacuum = ping_pong_ball();
  vacuum.impact_velocity_mps = b.impacts[2].approach_speed_mps;
  const BounceSequence one = run_bounce_sequence(vacuum, "hunt-crossley", SolverSettings{}, {.impacts = 1});
  CHECK(one.impacts[0].rebound_speed_mps == Approx(b.impacts[2].rebound_speed_mps).epsilon(1e-12));
}

TEST_CASE("air drag: the intervals of a light ball read an e below its contacts'", "[air-drag][bounce]") {
  // The paper's method reads e = dt[1] / dt[0] from the intervals between onsets, each a contact
  // (short here: ~1e-4 s against 0.4 s flights) plus a flight. With drag, a flight from v (small
  // d = (v / v_t)^2): t_up = (v_t / g) atan(v / v_t) = (v / g)(1 - d / 3 + O(d^2)), the apex
  // H = (v^2 / 2g)(1 - d / 2 + O(d^2)), the fall back (v_t / g) atanh(v_land / v_t) with
  // v_land = v (1 - d / 2 + O(d^2)) takes (v / g)(1 - d / 6 + O(d^2)): T(v) = (2 v / g)(1 - d / 4).
  // The next rebound is e v_land: T(v_r1) / T(v_r0) = e (1 - d0 / 2)(1 - e^2 d0 / 4)/(1 - d0 / 4)
  // = e (1 - (1 + e^2) d0 / 4 + O(d0^2)), d0 = (v_r0 / v_t)^2. So the intervals read an e lower
  // than the contact's by (1 + e^2) d0 / 4, to O(d0^2) and the contact times' share (~1e-3 of it).
  // Without air the same runs read the contact's e (the law's e does not depend on the speed).
  DropTestSetup s = ping_pong_ball();
  s.air_drag = {.air_density_kg_per_m3 = 1.204};
  const BounceSequence drag = run_bounce_sequence(s, "kelvin-voigt", SolverSettings{}, {.impacts = 4});
  s.air_drag = {};
  const BounceSequence vacuum = run_bounce_sequence(s, "kelvin-voigt", SolverSettings{}, {.impacts = 4});
  const double v_t = terminal_speed_mps({.air_density_kg_per_m3 = 1.204}, s.mass_kg, s.ball_radius_m, s.gravity_mps2);
  const double v_r0 = drag.impacts[0].rebound_speed_mps, d0 = (v_r0 / v_t) * (v_r0 / v_t);
  const double e = drag.e_velocity_ratio[1];
  INFO("d0 = " << d0 << ", e = " << e << ", read " << drag.e_from_intervals[0]);
  CHECK(drag.e_from_intervals[0] == Approx(e * (1 - (1 + e * e) * d0 / 4)).margin(d0 * d0));
  CHECK(e - drag.e_from_intervals[0] > d0 * d0);  // the first-order effect is beyond that margin
  CHECK(std::abs(vacuum.e_from_intervals[0] - vacuum.e_velocity_ratio[1]) < 1e-3 * d0);
}

TEST_CASE("air drag: refused where nothing flies, named", "[air-drag][cli]") {
  // A single impact integrates its fall without drag: refused, not ignored. The drag coefficient
  // without air is read by nothing. The elastic rod integrates its flights without drag.
  auto refused = [](const std::string& args, std::initializer_list<std::string> pieces) {
    const auto r = test::run_cli(args);
    INFO(args << ": " << r.err);
    CHECK(r.exit_code == 2);
    for (const std::string& piece : pieces) CHECK(r.err.find(piece) != std::string::npos);
  };
  refused("simulate --air-density 1.2", {"--air-density", "takes no drag"});
  refused("bounce --drag-coefficient 0.5", {"--drag-coefficient", "--air-density"});
  refused("bounce --rod-model elastic --air-density 1.2 --bounces 2", {"--air-density", "--rod-model is elastic"});
  refused("bounce --air-density -1", {">= 0"});
  const auto bounce = test::run_cli("bounce --air-density 1.204 --json");
  REQUIRE(bounce.exit_code == 0);
  const auto j = nlohmann::json::parse(bounce.out);
  CHECK(j["inputs"]["air_density_kg_per_m3"] == 1.204);
  // The run's approach speed is the fall with drag's (v_t = 230 m/s for the steel rod: 1e-6 below
  // sqrt(2 g h) relative, (v0 / v_t)^2 / 4 to first order: 2e-6).
  const double v_vacuum = std::sqrt(2 * 9.80665 * 0.02);
  CHECK(j["inputs"]["impact_velocity_mps"].get<double>() < v_vacuum);
  CHECK(j["inputs"]["impact_velocity_mps"].get<double>() > v_vacuum * (1 - 1e-5));
}

TEST_CASE("air drag: a single impact of the C++ API refuses a set-up with drag", "[air-drag]") {
  // The front ends refuse the options before a run (above); a set-up built in C++ with drag is
  // refused by the simulator, whose fall is integrated in vacuum, naming the input.
  DropTestSetup s = ping_pong_ball();
  s.air_drag.air_density_kg_per_m3 = 1.2;
  ImpactSimulator simulator{SolverSettings{}};
  try {
    simulator.run(s, "hongo");
    FAIL("accepted and ignored");
  } catch (const InvalidParameter& e) {
    CHECK(e.key == "air-density");
  }
}

TEST_CASE("air drag: the bounce trace's flights follow the drag equation", "[air-drag][bounce]") {
  // `bounce --trace` samples each flight from model/air_drag.hpp's closed forms; an RK4
  // integration of u'' = g - sign(u') g u'^2 / v_t^2 from the separation (x_s, -v_r) must reach
  // the same deformation and rate at each sample (RK4 at 20000 steps: ~1e-12 relative).
  DropTestSetup s = ping_pong_ball();
  s.air_drag = {.air_density_kg_per_m3 = 1.204};
  const double g = s.gravity_mps2, v_t = terminal_speed_mps(s.air_drag, s.mass_kg, s.ball_radius_m, g);
  const BounceSequence b = run_bounce_sequence(s, "kelvin-voigt", SolverSettings{}, {.impacts = 2});
  const std::vector<TraceSample> trace = bounce_trace(b, s, "kelvin-voigt", SolverSettings{});
  const double t_sep = b.impacts[0].separation_time_s, t_next = b.impacts[1].onset_time_s;
  const double v_r = b.impacts[0].rebound_speed_mps;
  int checked = 0;
  double x_s = 0;
  for (const TraceSample& p : trace) {
    if (p.t_s <= t_sep) x_s = p.x_m;  // the last contact sample: the separation
    if (p.t_s <= t_sep || p.t_s >= t_next) continue;
    const auto [u, v] = integrate_drag(-v_r, p.t_s - t_sep, g, v_t);
    CHECK(p.x_m == Approx(x_s + u).margin(1e-10));
    CHECK(p.xdot_mps == Approx(v).margin(1e-10));
    ++checked;
  }
  CHECK(checked == bounce_flight_samples - 1);
}

TEST_CASE("air drag: read where flights are followed, described, and refused elsewhere", "[air-drag][parameters]") {
  // The option table's side of the no-option-ignored matrix (tests/test_parameter_schema.cpp runs
  // without flights, where both are refused): with follows_flights (bounce, fit --bounce-times)
  // air-density and drag-coefficient are read and named in the run's description; the drag
  // coefficient alone is refused naming air-density; the elastic rod refuses both.
  const PaperParameters paper = load_paper_parameters();
  RunOptions base;
  base.follows_flights = true;
  RunOptions air = base;
  air.air_density_kg_per_m3 = 1.2;
  air.drag_coefficient = 0.5;
  const Parameters d = describe_run(resolve_setup(air, paper), air.damping, resolve_solver(air));
  auto listed = [&](const std::string& name) {
    return std::find_if(d.begin(), d.end(), [&](const auto& e) { return e.first == name; }) != d.end();
  };
  CHECK(listed("air_density_kg_per_m3"));
  CHECK(listed("drag_coefficient"));
  CHECK(d != describe_run(resolve_setup(base, paper), base.damping, resolve_solver(base)));
  RunOptions coefficient_only = base;
  coefficient_only.drag_coefficient = 0.5;
  try {
    resolve_setup(coefficient_only, paper);
    FAIL("accepted and ignored");
  } catch (const InvalidParameter& e) {
    CHECK(e.key == "drag-coefficient");
    CHECK_THAT(e.valid_range, Catch::Contains("air-density"));
  }
  RunOptions elastic = air;
  elastic.rod_model = "elastic";
  CHECK_THROWS_AS(resolve_setup(elastic, paper), InvalidParameter);
}
