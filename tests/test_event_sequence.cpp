// After contact onset every integrator must judge crossings by the contact's own
// event functions, not by the values they had in flight.
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <catch2/catch.hpp>

using namespace hertzdash;

TEST_CASE("Every integrator fires onset, maximum compression and separation, and no spurious peak", "[events]") {
  // Kelvin-Voigt at e = 0.1: zeta = ln(10)/sqrt(pi^2 + ln^2 10) = 0.59 > 1/2, so the force
  // F = k x + c x' starts at its maximum c v0 and falls from onset on (dF/dt = k x' + c x''
  // = (k - c^2/m) v0 < 0 at x = 0 when c^2 > k m, i.e. zeta > 1/2). The peak-force event
  // (dF/dt falling through zero) therefore never fires: a run fires exactly three events,
  // onset (a restart), maximum compression and separation (a stop). An integrator that
  // compared its first contact step with the flight values of the event functions
  // (g = 1 for the peak-force event) would fire a fourth, spurious one at onset.
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.restitution = 0.1;
  for (IntegratorKind kind : {IntegratorKind::euler, IntegratorKind::rk4, IntegratorKind::cvode, IntegratorKind::dopri5}) {
    SolverSettings solver;
    solver.integrator = kind;
    solver.dt_s = 1e-7;
    const ImpactSummary r = ImpactSimulator(solver).run(s, "kelvin-voigt");
    INFO("integrator " << to_string(kind));
    CHECK(r.separated);
    CHECK(r.work.events == 3);
  }
}
