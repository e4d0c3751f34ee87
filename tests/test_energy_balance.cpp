// Energy identities of the drop test.
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace hertzdash;

TEST_CASE("Undamped contact with gravity returns the approach speed", "[energy]") {
  // With law "none" the system is conservative (Hertz potential (2/5) K x^{5/2} plus
  // gravity -m g x); separation happens at x = 0, the height of onset, so the
  // rebound speed equals the approach speed: e_effective = 1 up to solver error
  // (~N rtol with N ~ 200 steps at rtol 1e-11: bound 1e-8).
  DropTestSetup s = paper_setup(load_paper_parameters(), "duralumin-c", 0.05);
  SolverSettings solver;
  solver.rtol = 1e-11;
  solver.atol = 1e-16;
  const ImpactSummary r = ImpactSimulator(solver).run(s, "none");
  REQUIRE(r.separated);
  CHECK(std::abs(r.e_effective - 1) < 1e-8);
}

TEST_CASE("Paper's law: kinetic energy lost equals the work of the dashpot", "[energy]") {
  // Between onset and separation (both at x = 0) the spring and gravity do no net
  // work, so (1/2) m (v0^2 - v1^2) = int (F - K x^{3/2}) x' dt, the dashpot's
  // dissipation. The integral is taken by the trapezoidal rule on an RK4 trace with
  // h = 1e-7 s; the integrand ~ sqrt(x) x'^2 has a sqrt singularity in slope at both
  // ends, so the rule's error is O(h^{3/2}) there: (h/t_c)^{3/2} ~ 1e-6 of the
  // dissipated energy, plus RK4's own ~1e-8. Bound: 1e-5 relative.
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  SolverSettings solver;
  solver.integrator = IntegratorKind::rk4;
  solver.dt_s = 1e-7;
  std::vector<TraceSample> trace;
  ImpactSimulator sim(solver);
  const ImpactSummary r = sim.run(s, "hongo", &trace);
  REQUIRE(r.separated);
  const double K = r.K, m = s.mass_kg;
  auto power = [&](const TraceSample& p) { return (p.force_N - K * std::pow(std::max(p.x_m, 0.0), 1.5)) * p.xdot_mps; };
  double work = 0;
  for (std::size_t i = 1; i < trace.size(); ++i)
    work += 0.5 * (power(trace[i]) + power(trace[i - 1])) * (trace[i].t_s - trace[i - 1].t_s);
  const double lost = 0.5 * m * (r.impact_velocity_mps * r.impact_velocity_mps - r.rebound_velocity_mps * r.rebound_velocity_mps);
  CHECK(lost > 0);
  CHECK(work == Approx(lost).epsilon(1e-5));
}
