// The tension clamp (--no-tension): the contact force never pulls, and contact ends
// where the force reaches zero.
#include "model/paper_parameters.hpp"
#include "validation/common/impact_simulator.hpp"

#include <catch2/catch.hpp>

using namespace hertzdash;

TEST_CASE("Tension clamp: force never negative, contact ends at zero force", "[clamp]") {
  // The paper's dashpot K tau sqrt(x) x' pulls during restitution where
  // x + tau x' < 0, i.e. before x returns to zero. Clamped, the rod leaves where
  // x = -tau x' > 0 and is spared the pulling phase, so it rebounds faster:
  // e_clamped > e_allowed. With tension allowed the force does go negative.
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.restitution = 0.3;  // strong damping: a long pulling phase
  SolverSettings solver;
  solver.cvode.rtol = 1e-10;
  solver.cvode.atol = 1e-15;
  ImpactSimulator sim(solver);

  std::vector<TraceSample> allowed_trace, clamped_trace;
  const ImpactSummary allowed = sim.run(s, "hongo", &allowed_trace);
  s.no_tension = true;
  const ImpactSummary clamped = sim.run(s, "hongo", &clamped_trace);
  REQUIRE(allowed.separated);
  REQUIRE(clamped.separated);

  double min_allowed = 0, min_clamped = 0;
  for (const auto& p : allowed_trace) min_allowed = std::min(min_allowed, p.force_N);
  for (const auto& p : clamped_trace) min_clamped = std::min(min_clamped, p.force_N);
  CHECK(min_allowed < -0.01 * allowed.peak_force_N);
  CHECK(min_clamped == 0.0);
  // Separation under the clamp: the unclamped force K sqrt(x)(x + tau x') crosses
  // zero with x still positive; it is located to the root finder's accuracy.
  const TraceSample& end = clamped_trace.back();
  CHECK(end.x_m > 0.01 * clamped.max_deformation_m);
  CHECK(end.force_N < 1e-6 * clamped.peak_force_N);
  CHECK(clamped.contact_time_s < allowed.contact_time_s);
  CHECK(clamped.e_effective > allowed.e_effective);
}
