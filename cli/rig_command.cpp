// `hertzdash RIG` for every registered rig (simulation/rigs/rig.hpp), generated from its schemas:
// the options of a run and the rig's own inputs (cli/rig_options.hpp), --json (the rig's JSON),
// --csv FILE (the per-impact table below its provenance), --mkdir, and the text report; bad input is refused by the rig (exit 2, the option named).
// A rig's sweeps (a bifurcation diagram over any of its inputs) are case files of `hertzdash
// sweep` with `rig = "NAME"` (simulation/sweep/sweep_case.hpp).
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/rig_options.hpp"
#include "cli/setup_options.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/reports/rig_report.hpp"

#include <iostream>
#include <memory>

namespace hertzdash::cli {

Command add_rig_command(CLI::App& app, const Rig& rig) {
  struct Request {
    RunOptions run;
    RigInputs inputs;
    std::string csv_path;
    bool json = false, mkdir = false;
  };
  auto opt = std::make_shared<Request>();
  if (!rig.default_integrator.empty()) opt->run.integrator = rig.default_integrator;
  CLI::App* sub = app.add_subcommand(std::string(rig.name), std::string(rig.summary));
  add_rig_options(*sub, rig, opt->run, opt->inputs);
  auto o = [](std::string_view key) { return declared_option("RIG", key); };
  sub->add_flag(o("json").flag, opt->json, o("json").help);
  add_output_file_option(*sub, o("csv").flag, opt->csv_path, o("csv").help);
  add_mkdir_flag(*sub, opt->mkdir);

  return {sub, [opt, &rig]() {
            prepare_output_file("--csv", opt->csv_path, opt->mkdir);
            const RigResult r = run_rig(rig, opt->run, load_paper_parameters(), opt->inputs);
            if (!opt->csv_path.empty()) {
              create_output_directories(opt->csv_path, opt->mkdir);
              rig_table_csv(rig, r).save(opt->csv_path);
            }
            for (const std::string& w : r.warnings) std::cerr << "hertzdash: warning: " << w << "\n";
            if (opt->json) std::cout << to_json(rig, r).dump(2) << "\n";
            else std::cout << rig_text(rig, r);
            if (!r.rows.empty()) return 0;
            // The run ended before any of the impacts asked for (a contact that never ends, a body
            // at rest for good): its output stands, incomplete, as a failed fit's does.
            std::cerr << "hertzdash: the run kept none of the impacts asked for: " << r.end_reason << "\n";
            return 3;
          }};
}

}  // namespace hertzdash::cli
