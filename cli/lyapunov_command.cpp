// `hertzdash lyapunov RIG`: the Lyapunov exponents of a rig's attractor
// (simulation/rigs/rig_lyapunov.hpp, docs/orbits.md), on cli/analysis_command.hpp: --periods,
// --section-phase, --json. Exit 0 with a converged spectrum, 3 when the run stopped or did not
// converge (the output standing), 2 for bad input.
#include "cli/analysis_command.hpp"
#include "hertzdash/simulation/reports/orbit_report.hpp"

#include <iostream>

namespace hertzdash::cli {

Command add_lyapunov_command(CLI::App& app) {
  return add_analysis_command(
      app, "lyapunov", "The Lyapunov exponents of a rig's attractor, from its stroboscopic map", "The Lyapunov exponents",
      [](const AnalysisRequest& r) {
        const LyapunovResult result =
            run_lyapunov(*r.rig, r.run, load_paper_parameters(), r.inputs, lyapunov_request(r.given));
        if (r.json) std::cout << to_json(*r.rig, result).dump(2) << "\n";
        else std::cout << lyapunov_text(*r.rig, result);
        if (result.spectrum.converged) return 0;
        std::cerr << "hertzdash: the exponents did not converge: "
                  << (result.spectrum.failure.empty() ? "the run's halves disagree (more --periods)" : result.spectrum.failure)
                  << "\n";
        return 3;
      });
}

}  // namespace hertzdash::cli
