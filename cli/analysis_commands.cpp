// The commands that analyse a rig's impact sequence (cli/analysis_command.hpp): the frame they
// share, then each command.
//   - `hertzdash orbit RIG` (simulation/rigs/rig_orbit.hpp): --period, --section-phase, the
//     guess, --json. Exit 0 with an orbit, 3 when Newton does not converge or the rig's run gives
//     no guess (the output stands).
//   - `hertzdash continue RIG` (simulation/rigs/rig_continuation.hpp): --parameter, --from, --to,
//     the orbit's options, --max-points, --json, --csv FILE, --mkdir. Exit 0 with branches, 3
//     when no orbit is found at `from` (the output standing).
//   - `hertzdash lyapunov RIG` (simulation/rigs/rig_lyapunov.hpp): --periods, --section-phase,
//     --json. Exit 0 with a converged spectrum, 3 when the run stopped or did not converge.
//   - `hertzdash basins RIG` (simulation/rigs/rig_basins.hpp): --section-phase, the grid's ranges
//     and resolution, the cells' runs, --threads, --json, --csv FILE, --mkdir. Exit 0 with the
//     grid, 3 when no default range exists (the rig's run gives no attractor). Under `mpirun -n N`
//     the N processes share the grid's rows and process 0 writes the result.
// Bad input exits 2, the option named (cli/main.cpp).
#include "cli/analysis_command.hpp"

#include "cli/number_options.hpp"
#include "cli/process_group.hpp"
#include "cli/output_files.hpp"
#include "cli/rig_options.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/reports/orbit_report.hpp"

#include <algorithm>
#include <iostream>
#include <memory>
#include <thread>
#include <vector>

namespace hertzdash::cli {

Command add_analysis_command(CLI::App& app, std::string_view command, const std::string& description,
                             const std::string& what, AnalysisRun run) {
  CLI::App* top = app.add_subcommand(std::string(command), description);
  top->require_subcommand(1);
  auto requests = std::make_shared<std::vector<std::shared_ptr<AnalysisRequest>>>();
  const std::string group = "The " + std::string(command) + " command";
  for (const Rig& rig : rigs()) {
    if (!rig.sequence) continue;
    auto r = std::make_shared<AnalysisRequest>();
    r->rig = &rig;
    if (!rig.default_integrator.empty()) r->run.integrator = rig.default_integrator;
    r->sub = top->add_subcommand(std::string(rig.name), what + " of `hertzdash " + std::string(rig.name) + "`");
    add_rig_options(*r->sub, rig, r->run, r->inputs, true);
    for (const ParameterDecl& d : options_of_command(command)) {
      const std::string flag = "--" + std::string(d.key), key(d.key), help = help_text(d, KeySpelling::command_line);
      CLI::Option* o = nullptr;
      if (key == "json") o = r->sub->add_flag(flag, r->json, help);
      else if (key == "mkdir") o = r->sub->add_flag(flag, r->mkdir, help);
      else if (key == "csv") o = add_output_file_option(*r->sub, flag, r->csv_path, help);
      else if (d.type == ParameterType::text)
        o = r->sub->add_option_function<std::string>(flag, [r, key](const std::string& v) { r->given.texts[key] = v; }, help);
      else o = add_number_option(*r->sub, flag, [r, key](double v) { r->given.numbers[key] = v; }, help);
      if (d.range.kind == NumberRange::Kind::integer) o->type_name("INT");
      // The guess's two halves, a group --guess-position switches on (cli/help_formatter.hpp).
      o->group(key.starts_with("guess-") ? "Newton's start (--guess-position)" : group);
    }
    requests->push_back(r);
  }
  return {top, [requests, run]() {
            for (const auto& r : *requests)
              if (r->sub->parsed()) {
                prepare_output_file("--csv", r->csv_path, r->mkdir);
                return run(*r);
              }
            return 2;
          }};
}

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

Command add_basins_command(CLI::App& app) {
  return add_analysis_command(
      app, "basins", "The basins of attraction of a rig's section: which attractor each start reaches",
      "The basins of attraction", [](const AnalysisRequest& r) {
        // Under an MPI launcher the processes share the grid's rows (simulation/orbits/basins.hpp),
        // the cores of a machine shared among its processes; process 0 writes everything.
        const ProcessGroup group;
        BasinsRequest request = basins_request(r.given);
        if (group.size() > 1) {
          request.rank = group.rank(), request.ranks = group.size();
          request.gather = [&group](const std::string& mine) { return group.gather(mine); };
          if (!r.given.number("threads"))
            request.threads = std::max(1u, std::thread::hardware_concurrency() / static_cast<unsigned>(group.local_size()));
        }
        const BasinsResult result = run_basins(*r.rig, r.run, load_paper_parameters(), r.inputs, request);
        if (group.rank() > 0) return result.failure.empty() ? 0 : 3;
        if (!r.csv_path.empty()) {
          create_output_directories(r.csv_path, r.mkdir);
          basins_csv(*r.rig, result).save(r.csv_path);
        }
        if (r.json) std::cout << to_json(*r.rig, result).dump(2) << "\n";
        else std::cout << basins_text(*r.rig, result);
        if (result.failure.empty()) return 0;
        std::cerr << "hertzdash: no basins: " << result.failure << "\n";
        return 3;
      });
}

}  // namespace hertzdash::cli
