// The pieces the convergence study stands on: the undamped closed-form trajectory,
// the regularised contact system, CVODE on the undamped law without gravity (the
// peak force coincides with maximum compression there), and the simulate warning.
#include "hertzdash/model/damping/laws/undamped.hpp"
#include "hertzdash/model/drop_test.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/contact_environments.hpp"
#include "hertzdash/model/contact_system.hpp"
#include "hertzdash/model/undamped_hertz_trajectory.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"
#include "hertzdash/simulation/run/step_resolution.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

using namespace hertzdash;

namespace {

// The paper's steel rod at h = 20 mm, started at contact without gravity.
DropTestSetup steel_at_contact() {
  const PaperParameters paper = load_paper_parameters();
  DropTestSetup s = paper_setup(paper, "steel", 0.02);
  s.impact_velocity_mps = std::sqrt(2.0 * paper.gravity_mps2 * 0.02);
  s.gravity_mps2 = 0.0;
  return s;
}

std::string run_and_capture_stderr(const std::string& args) {
  const std::string cmd = std::string(HERTZDASH_BIN) + " simulate " + args + " 2>&1 >/dev/null";
  std::string out;
  FILE* pipe = popen(cmd.c_str(), "r");
  REQUIRE(pipe != nullptr);
  std::array<char, 512> buf{};
  while (fgets(buf.data(), buf.size(), pipe)) out += buf.data();
  REQUIRE(pclose(pipe) == 0);
  return out;
}

}  // namespace

TEST_CASE("Undamped Hertz trajectory: end points, energy and velocity are consistent") {
  const DropTestSetup s = steel_at_contact();
  const double K = hertz_stiffness(s), m = s.mass_kg, v0 = *s.impact_velocity_mps;
  const UndampedHertzImpact u = undamped_hertz_impact(K, m, v0);
  // Onset, turning point (tc/2: x = X, x' = 0) and separation (x = 0, x' = -v0). The
  // bisection resolves s = x/X to ~eps, and at the turning point x' = v0 sqrt(1 - s^{5/2})
  // with 1 - s ~ eps is then ~v0 sqrt(2.5 eps) ~ 2e-8 v0: hence the 1e-7 bound.
  const ContactState start = undamped_hertz_state_at(K, m, v0, 0.0);
  CHECK(start.x_m == Approx(0.0).margin(1e-15 * u.max_deformation_m));
  CHECK(start.xdot_mps == Approx(v0).epsilon(1e-14));
  const ContactState turn = undamped_hertz_state_at(K, m, v0, 0.5 * u.contact_time_s);
  CHECK(turn.x_m == Approx(u.max_deformation_m).epsilon(1e-14));
  CHECK(std::abs(turn.xdot_mps) < 1e-7 * v0);
  const ContactState end = undamped_hertz_state_at(K, m, v0, u.contact_time_s);
  CHECK(end.x_m == Approx(0.0).margin(1e-15 * u.max_deformation_m));
  CHECK(end.xdot_mps == Approx(-v0).epsilon(1e-14));

  // Energy (1/2) m x'^2 + (2/5) K x^{5/2} = (1/2) m v0^2 at t* = 0.3 tc (rounding only).
  const double t = 0.3 * u.contact_time_s;
  const ContactState y = undamped_hertz_state_at(K, m, v0, t);
  CHECK(0.5 * m * y.xdot_mps * y.xdot_mps + 0.4 * K * std::pow(y.x_m, 2.5) == Approx(0.5 * m * v0 * v0).epsilon(1e-13));
  // x' = dx/dt: central difference with d = 1e-4 tc, truncation d^2 x'''/6 ~ 1e-8 relative.
  const double d = 1e-4 * u.contact_time_s;
  const double rate = (undamped_hertz_state_at(K, m, v0, t + d).x_m - undamped_hertz_state_at(K, m, v0, t - d).x_m) / (2 * d);
  CHECK(rate == Approx(y.xdot_mps).epsilon(1e-7));
}

TEST_CASE("Regularised contact reproduces the undamped closed forms") {
  // RK4 in tau is order 4 (the system is polynomial); the convergence study finds
  // errors of ~3e-10 at 400 steps per contact, so 1e-8 is a safe bound for any
  // defect of the change of variables (a wrong factor of 2 would give O(1) errors).
  const DropTestSetup s = steel_at_contact();
  const double K = hertz_stiffness(s), m = s.mass_kg, v0 = *s.impact_velocity_mps;
  const UndampedHertzImpact u = undamped_hertz_impact(K, m, v0);
  ContactSystem<Undamped, FixedWall> sys(ImpactConditions{K, m, v0, s.restitution}, s.damping, FixedWall{0.0});
  auto y = sys.initial_state();
  double peak = 0, x_max = 0;
  struct Obs {
    const ContactSystem<Undamped, FixedWall>& sys;
    double &peak, &x_max;
    void on_step(double, const ContactSystem<Undamped, FixedWall>::State& y) {
      peak = std::max(peak, sys.force(y));
      x_max = std::max(x_max, y[0] * y[0]);
    }
    void on_event(int, double, const ContactSystem<Undamped, FixedWall>::State&, EventAction) {}
  } obs{sys, peak, x_max};
  // tau extent of the contact: tc / (2 sqrt(X)) times O(1); 400 steps of a tenth of the scale suffice.
  const double tau_step = u.contact_time_s / (2 * std::sqrt(u.max_deformation_m)) / 400;
  const IntegrationStats st = integrate_fixed_step<ClassicalRk4>(sys, y, 0.0, 1e4 * tau_step,
                                                                  FixedStepOptions{tau_step, true}, obs);
  REQUIRE(st.stopped_by_event);
  CHECK(y[2] == Approx(u.contact_time_s).epsilon(1e-8));
  CHECK(-y[1] == Approx(v0).epsilon(1e-8));  // undamped: e = 1
  CHECK(peak == Approx(u.peak_force_N).epsilon(1e-8));
  CHECK(x_max == Approx(u.max_deformation_m).epsilon(1e-8));
}

TEST_CASE("Under-resolved fixed-step contacts are reported with their step count") {
  // Steps are counted per undamped Hertz contact time t_H of the run's K, m and v0
  // (model/hertz.hpp): the unit of the convergence study's thresholds.
  ImpactSummary s;
  s.K = 3.54e8;
  s.impact_velocity_mps = 0.6;
  const double m = 0.778;
  const double t_hertz = undamped_hertz_impact(s.K, m, s.impact_velocity_mps).contact_time_s;
  SolverSettings solver;
  solver.dt_s = t_hertz / 100;  // 100 steps per t_H
  solver.integrator = IntegratorKind::euler;
  const auto r = under_resolved_contact(s, m, solver);
  REQUIRE(r);
  CHECK(r->steps_per_contact == Approx(100.0));
  CHECK(r->hertz_contact_time_s == t_hertz);
  CHECK(r->required == min_steps_per_contact(IntegratorKind::euler, true));
  solver.integrator = IntegratorKind::rk4;  // located: 100 >= min_steps_per_contact(rk4, true)
  CHECK_FALSE(under_resolved_contact(s, m, solver));
  solver.locate_events = false;
  CHECK(under_resolved_contact(s, m, solver));
  solver.integrator = IntegratorKind::cvode;
  CHECK_FALSE(under_resolved_contact(s, m, solver));
}

TEST_CASE("hertzdash simulate warns on stderr when a fixed step under-resolves the contact") {
  // The CLI's defaults: the paper's steel rod at h = 20 mm, dt = 1e-6 s, a ~1.2e-3 s
  // contact, so about a thousand steps: fewer than Euler needs, enough for RK4.
  SolverSettings solver;
  solver.integrator = IntegratorKind::euler;
  solver.dt_s = 1e-6;
  ImpactSimulator sim(solver);
  const DropTestSetup setup = paper_setup(load_paper_parameters(), "steel", 0.02);
  const ImpactSummary s = sim.run(setup, "hongo");
  const double t_hertz = undamped_hertz_impact(s.K, setup.mass_kg, s.impact_velocity_mps).contact_time_s;
  const std::string steps = fmt::format("only {:.0f} steps per undamped Hertz contact time", t_hertz / solver.dt_s);
  const std::string euler = run_and_capture_stderr("--integrator euler");
  CHECK_THAT(euler, Catch::Contains("warning") && Catch::Contains(steps) &&
                        Catch::Contains(std::to_string(min_steps_per_contact(IntegratorKind::euler, true))));
  // Nothing else on stderr: the elasticity check is off here (the paper's steel contact exceeds
  // nylon's onset of yield, a warning of its own, tests/test_bounce_sequence.cpp).
  CHECK(run_and_capture_stderr("--integrator rk4 --ball-yield-stress inf").empty());
  CHECK(run_and_capture_stderr("--integrator cvode --ball-yield-stress inf").empty());
}
