// The tension clamp (--no-tension): the contact force never pulls, and contact ends
// where the force reaches zero.
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace hertzdash;

TEST_CASE("Tension clamp: force never negative, contact ends at zero force", "[clamp]") {
  // The paper's dashpot K tau sqrt(x) x' pulls during restitution where
  // x + tau x' < 0, i.e. before x returns to zero. Clamped, the rod leaves where
  // x = -tau x' > 0 and is spared the pulling phase, so it rebounds faster:
  // e_clamped > e_allowed. With tension allowed the force does go negative.
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.restitution = 0.3;  // strong damping: a long pulling phase
  SolverSettings solver;
  solver.rtol = 1e-10;
  solver.atol = 1e-15;
  ImpactSimulator sim(solver);

  std::vector<TraceSample> allowed_trace, clamped_trace;
  const ImpactSummary allowed = sim.run(s, "hongo", &allowed_trace);
  s.no_tension = true;
  const ImpactSummary clamped = sim.run(s, "hongo", &clamped_trace);
  REQUIRE(allowed.separated);
  REQUIRE(clamped.separated);

  double min_allowed = 0;
  for (const auto& p : allowed_trace) min_allowed = std::min(min_allowed, p.force_N);
  CHECK(min_allowed < -0.01 * allowed.peak_force_N);

  // Under the clamp the law's own (unclamped) force K sqrt(x) (x + tau x') must stay
  // positive until separation and be zero there, located to the root finder's accuracy
  // (1e-6 of the peak bounds it at rtol 1e-10); x is then still positive.
  double c_e = 0;  // K tau [N s / m^{3/2}]
  for (const NamedValue& c : clamped.law_coefficients)
    if (std::string(c.name) == "c_e_coefficient_N_s_per_m_1_5") c_e = c.value;
  REQUIRE(c_e > 0);
  auto unclamped = [&](const TraceSample& p) { return std::sqrt(p.x_m) * (clamped.K * p.x_m + c_e * p.xdot_mps); };
  for (std::size_t i = 1; i + 1 < clamped_trace.size(); ++i) {
    INFO("sample " << i << " of " << clamped_trace.size());
    CHECK(unclamped(clamped_trace[i]) > 0);
  }
  const TraceSample& end = clamped_trace.back();
  CHECK(end.x_m > 0.01 * clamped.max_deformation_m);
  CHECK(std::abs(unclamped(end)) < 1e-6 * clamped.peak_force_N);
  CHECK(clamped.contact_time_s < allowed.contact_time_s);
  CHECK(clamped.e_effective > allowed.e_effective);
}
