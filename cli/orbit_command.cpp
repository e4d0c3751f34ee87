// `hertzdash orbit RIG`: a periodic orbit of a rig, its Floquet multipliers and its stability
// (simulation/rigs/rig_orbit.hpp, docs/orbits.md), on cli/analysis_command.hpp: --period,
// --section-phase, --guess-position, --guess-velocity, --json. Exit 0 with an orbit, 3 when
// Newton does not converge or the rig's run gives no guess (the output stands), 2 for bad input.
#include "cli/analysis_command.hpp"
#include "hertzdash/simulation/reports/orbit_report.hpp"

#include <iostream>

namespace hertzdash::cli {

Command add_orbit_command(CLI::App& app) {
  return add_analysis_command(
      app, "orbit", "A rig's periodic orbit by shooting: its Floquet multipliers and stability", "The periodic orbit",
      [](const AnalysisRequest& r) {
        const OrbitResult result = run_orbit(*r.rig, r.run, load_paper_parameters(), r.inputs, orbit_request(r.given));
        if (r.json) std::cout << to_json(*r.rig, result).dump(2) << "\n";
        else std::cout << orbit_text(*r.rig, result);
        if (result.orbit.converged) return 0;
        std::cerr << "hertzdash: no periodic orbit found: " << result.orbit.failure << "\n";
        return 3;
      });
}

}  // namespace hertzdash::cli
