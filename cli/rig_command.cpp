// `hertzdash RIG` for every registered rig (simulation/rigs/rig.hpp), generated from its schemas:
// the options of a run and the rig's own inputs (--KEY, help, valid values and default from the
// declarations), --json (the rig's JSON), --csv FILE (the per-impact table below its provenance),
// --mkdir, and the text report; bad input is refused by the rig (exit 2, the option named).
// A rig's sweeps (a bifurcation diagram over any of its inputs) are case files of `hertzdash
// sweep` with `rig = "NAME"` (simulation/sweep/sweep_case.hpp).
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/setup_options.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/reports/rig_report.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"

#include <algorithm>
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
  add_run_options(*sub, opt->run);
  for (const RigOptionNote& n : rig.run_option_notes) sub->get_option("--" + std::string(n.key))->description(std::string(n.help));
  // The help lists what a run of the rig reads (issue 46): the options it never reads stay
  // options, refused with their reason when given, but out of the help: those the rig declares
  // unread, those of a trace, of the bounce sequence's flights, of the elastic rod and the tension
  // clamp (a rig's soft contacts are the rigid rod's, in regularising variables), and those no
  // integrator in regularising variables reads.
  for (const RunOption& option : run_options()) {
    const OptionReaders& r = option.readers;
    bool regularized_reads = !r.integrators;
    for (const IntegratorTraits& t : all_integrator_traits)
      regularized_reads = regularized_reads || (t.variables == Variables::regularized && r.integrators(t));
    const bool unread = std::ranges::find(rig.run_options_not_read, option.name) != rig.run_options_not_read.end();
    if (unread || r.trace_only || r.flights_only || r.elastic_rod || option.name == "rod-model" || option.name == "no-tension" ||
        !regularized_reads)
      sub->get_option("--" + option.name)->group("");
  }
  const std::string group = "The " + std::string(rig.name) + " rig";
  for (const ParameterDecl& d : rig.inputs) {
    const std::string flag = "--" + std::string(d.key), key(d.key), help = help_text(d, KeySpelling::command_line);
    CLI::Option* o =
        d.type == ParameterType::text
            ? sub->add_option_function<std::string>(flag, [opt, key](const std::string& v) { opt->inputs.texts[key] = v; }, help)
            : add_number_option(*sub, flag, [opt, key](double v) { opt->inputs.numbers[key] = v; }, help);
    if (d.type == ParameterType::number && d.range.kind == NumberRange::Kind::integer) o->type_name("INT");
    o->group(group);
  }
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
