// `hertzdash continue RIG`: the branches of a rig's periodic orbits in one of its numeric inputs,
// with their folds, period doublings, Neimark-Sacker points and grazings
// (simulation/rigs/rig_continuation.hpp, docs/orbits.md), on cli/analysis_command.hpp:
// --parameter, --from, --to, the orbit's --period, --section-phase and guess, --max-points,
// --json, --csv FILE, --mkdir. Exit 0 with branches, 3 when no orbit is found at `from` (the
// output standing), 2 for bad input.
#include "cli/analysis_command.hpp"
#include "cli/output_files.hpp"
#include "hertzdash/simulation/reports/orbit_report.hpp"

#include <iostream>

namespace hertzdash::cli {

Command add_continue_command(CLI::App& app) {
  return add_analysis_command(
      app, "continue", "Branches of a rig's periodic orbits in a parameter: folds, period doublings, grazings",
      "The branches of the periodic orbits", [](const AnalysisRequest& r) {
        const ContinuationResult result =
            run_continuation(*r.rig, r.run, load_paper_parameters(), r.inputs, continuation_request(r.given));
        if (!r.csv_path.empty()) {
          create_output_directories(r.csv_path, r.mkdir);
          continuation_csv(*r.rig, result).save(r.csv_path);
        }
        if (r.json) std::cout << to_json(*r.rig, result).dump(2) << "\n";
        else std::cout << continuation_text(*r.rig, result);
        if (result.failure.empty()) return 0;
        std::cerr << "hertzdash: no branch followed: " << result.failure << "\n";
        return 3;
      });
}

}  // namespace hertzdash::cli
