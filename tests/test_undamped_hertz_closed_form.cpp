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
#include "model/hertz.hpp"
#include "model/paper_parameters.hpp"
#include "validation/common/impact_simulator.hpp"

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

struct Errors {
  double X, F, tc, e;
};

Errors relative_errors(const SolverSettings& solver) {
  const DropTestSetup s = undamped_setup();
  const ImpactSummary r = ImpactSimulator(solver).run(s, "none");
  const UndampedHertzImpact exact = undamped_hertz_impact(r.K, s.mass_kg, *s.impact_velocity_mps);
  REQUIRE(r.separated);
  return {std::abs(r.max_deformation_m / exact.max_deformation_m - 1), std::abs(r.peak_force_N / exact.peak_force_N - 1),
          std::abs(r.contact_time_s / exact.contact_time_s - 1), std::abs(r.e_effective - 1)};
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
  // CVODE controls the local error to rtol |y| + atol per step; over the ~10^2
  // steps of one contact the global error stays below ~10^2 rtol = 1e-8. Events are
  // located by CVODE's root finder to near roundoff, so 1e-7 bounds every quantity.
  for (CvodeMethod method : {CvodeMethod::adams, CvodeMethod::bdf}) {
    SolverSettings solver;
    solver.cvode.method = method;
    solver.cvode.rtol = 1e-10;
    solver.cvode.atol = 1e-15;
    const Errors err = relative_errors(solver);
    INFO("method " << to_string(method));
    CHECK(err.X < 1e-7);
    CHECK(err.F < 1e-7);
    CHECK(err.tc < 1e-7);
    CHECK(err.e < 1e-7);
  }
}

TEST_CASE("Undamped Hertz impact: RK4 with located events matches the closed forms", "[hertz][rk4]") {
  // With h = t_c/1000 the smooth part of the RK4 error is O(h^4) ~ 1e-12. The force
  // K x^{3/2} is not smooth at x = 0: on the first step after onset x ~ v0 t and the
  // acceleration ~ t^{3/2}, whose quadrature by the RK4 stages has an error
  // ~ (K/m) v0^{3/2} h^{5/2} in velocity. Relative to v0, with K/m = 5 v0^2/(4 X^{5/2})
  // and h = t_c/1000 = 2.94e-3 X/v0, that is 1.25 (2.94e-3)^{5/2} = 5.9e-7: the
  // bound is 1e-6, and the same kink at separation adds as much.
  SolverSettings solver;
  solver.integrator = IntegratorKind::rk4;
  solver.fixed_step.dt = contact_time_s() / 1000;
  const Errors err = relative_errors(solver);
  CHECK(err.X < 1e-6);
  CHECK(err.F < 1e-6);
  CHECK(err.tc < 1e-6);
  CHECK(err.e < 2e-6);
}

TEST_CASE("Undamped Hertz impact: explicit Euler with located events matches the closed forms", "[hertz][euler]") {
  // Explicit Euler multiplies the energy of an oscillation of frequency w by
  // (1 + h^2 w^2) per step: over one contact (t_c/h steps, w ~ pi/t_c) the relative
  // energy error is ~ pi^2 h / t_c, and speeds carry half of it. With
  // h = t_c / 10^5 that is 5e-5 in e and ~1e-4 in X, F, t_c (which feel the
  // drift of the whole compression phase): the bounds are 2e-4.
  SolverSettings solver;
  solver.integrator = IntegratorKind::euler;
  solver.fixed_step.dt = contact_time_s() / 1e5;
  const Errors err = relative_errors(solver);
  CHECK(err.X < 2e-4);
  CHECK(err.F < 2e-4);
  CHECK(err.tc < 2e-4);
  CHECK(err.e < 2e-4);
}
