// The commands that analyse a rig's impact sequence (cli/analysis_command.hpp).
#include "cli/analysis_command.hpp"

#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/rig_options.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/options/run_options.hpp"

#include <memory>
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

}  // namespace hertzdash::cli
