// The undamped Hertz impact against its closed forms, for every integrator.
//
// A mass m hits a rigid-backed Hertz contact at v0 with no gravity and no damping
// (law "none"). Energy conservation, (1/2) m v^2 + (2/5) K x^{5/2} = (1/2) m v0^2,
// gives
//   X   = (5 m v0^2 / (4 K))^{2/5}                maximum deformation
//   F   = K X^{3/2}                               peak force
//   t_c = 2 int_0^X dx / v(x) = (4/5) B(2/5, 1/2) X / v0   contact time
//   rebound speed = v0                            (e_effective = 1)
// model/hertz.cpp evaluates these with GSL's beta function; here the contact time
// is also checked against an independent quadrature of the same integral.
#include "hertzdash/model/hertz.hpp"
#include "undamped_hertz_errors.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <catch2/catch.hpp>
#include <gsl/gsl_integration.h>

#include <cmath>

using namespace hertzdash;

namespace {

DropTestSetup undamped_setup() {
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.0);
  s.impact_velocity_mps = 0.626;
  s.gravity_mps2 = 0.0;
  s.restitution = 1.0;
  return s;
}

using testing::UndampedHertzErrors;

UndampedHertzErrors relative_errors(const SolverSettings& solver, long* steps = nullptr) {
  const DropTestSetup s = undamped_setup();
  const ImpactSummary r = ImpactSimulator(solver).run(s, "none");
  REQUIRE(r.separated);
  if (steps) *steps = r.work.steps;
  return testing::undamped_hertz_errors(r, undamped_hertz_impact(r.K, s.mass_kg, *s.impact_velocity_mps));
}

/// Every relative error below `bound` (each CHECK reported on its own).
void check_all_below(const UndampedHertzErrors& err, double bound) {
  CHECK(err.X < bound);
  CHECK(err.F < bound);
  CHECK(err.contact_time < bound);
  CHECK(err.e < bound);
}

double contact_time_s() {
  const DropTestSetup s = undamped_setup();
  return undamped_hertz_impact(hertz_stiffness(s), s.mass_kg, *s.impact_velocity_mps).contact_time_s;
}

}  // namespace

TEST_CASE("Undamped contact time: beta-function closed form equals direct quadrature", "[hertz]") {
  // t_c = (2X/v0) int_0^1 ds / sqrt(1 - s^{5/2}); the integrand has an inverse
  // square-root singularity at s = 1, which QAGS handles to ~1e-12.
  gsl_integration_workspace* w = gsl_integration_workspace_alloc(1000);
  gsl_function f{[](double s, void*) { return 1.0 / std::sqrt(1.0 - std::pow(s, 2.5)); }, nullptr};
  double I = 0, abserr = 0;
  REQUIRE(gsl_integration_qags(&f, 0.0, 1.0, 0.0, 1e-12, 1000, w, &I, &abserr) == 0);
  gsl_integration_workspace_free(w);
  const UndampedHertzImpact u = undamped_hertz_impact(3.54e8, 0.778, 0.626);
  CHECK(u.contact_time_s == Approx(2.0 * u.max_deformation_m / 0.626 * I).epsilon(1e-10));
  // Energy balance at the turning point: (2/5) K X^{5/2} = (1/2) m v0^2.
  CHECK(0.4 * 3.54e8 * std::pow(u.max_deformation_m, 2.5) == Approx(0.5 * 0.778 * 0.626 * 0.626).epsilon(1e-12));
}

TEST_CASE("Undamped Hertz impact: CVODE matches the closed forms", "[hertz][cvode]") {
  // CVODE keeps each step's local error below rtol |y| + atol, so after N steps the
  // global relative error is at most ~N rtol (errors of a conservative oscillation
  // do not grow faster than they add up). Events are located by CVODE's root
  // finder to near roundoff. Bound: N rtol with N the run's own step count.
  for (CvodeMethod method : {CvodeMethod::adams, CvodeMethod::bdf}) {
    SolverSettings solver;
    solver.cvode_method = method;
    solver.rtol = 1e-10;
    solver.atol = 1e-15;
    long steps = 0;
    const UndampedHertzErrors err = relative_errors(solver, &steps);
    const double bound = static_cast<double>(steps) * solver.rtol;
    INFO("method " << to_string(method) << ", " << steps << " steps, bound " << bound);
    check_all_below(err, bound);
  }
}

TEST_CASE("Undamped Hertz impact: RK4 with located events matches the closed forms", "[hertz][rk4]") {
  // With h = t_c/1000 the smooth part of the RK4 error is O((h/t_c)^4) ~ 1e-12. The
  // force K x^{3/2} is not smooth at x = 0: on the step that starts at onset,
  // x ~ v0 t and the acceleration ~ (K/m) v0^{3/2} t^{3/2}, which the RK4 stages
  // (weights 1/6, 4/6, 1/6 at t = 0, h/2, h) integrate to h^{5/2} (0.4024) instead of
  // h^{5/2} (0.4): a velocity error 0.0024 (K/m) v0^{3/2} h^{5/2}. Relative to v0, with
  // K/m = 5 v0^2/(4 X^{5/2}) and h = 2.94e-3 X/v0, that is
  // 0.0024 * 1.25 * (2.94e-3)^{5/2} = 1.4e-9 per kink; onset and separation make
  // ~3e-9 (F carries 3/2 of X's relative error). Bound: 1e-8.
  SolverSettings solver;
  solver.integrator = IntegratorKind::rk4;
  solver.dt_s = contact_time_s() / 1000;
  const UndampedHertzErrors err = relative_errors(solver);
  check_all_below(err, 1e-8);
}

TEST_CASE("Undamped Hertz impact: explicit Euler with located events matches the closed forms", "[hertz][euler]") {
  // Explicit Euler multiplies the energy of an oscillation of frequency w by
  // (1 + h^2 w^2) per step: over one contact (t_c/h steps, w = pi/t_c) the relative
  // energy error is pi^2 h / t_c = 9.9e-5 at h = t_c/10^5, so the rebound speed is
  // off by half of it, 4.9e-5; X and F feel the drift of the compression half
  // (2.5e-5 and 1.5 times that). Bound: 1e-4 for every quantity.
  SolverSettings solver;
  solver.integrator = IntegratorKind::euler;
  solver.dt_s = contact_time_s() / 1e5;
  const UndampedHertzErrors err = relative_errors(solver);
  check_all_below(err, 1e-4);
}
