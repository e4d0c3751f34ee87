// `hertzdash continue RIG`: the branches of a rig's periodic orbits in one of its numeric inputs,
// with their folds, period doublings, Neimark-Sacker points and grazings
// (simulation/rigs/rig_continuation.hpp, docs/orbits.md). One subcommand per rig `orbit` takes,
// with the rig's options (cli/rig_options.hpp) and the continuation's own, declared in
// simulation/options/command_options.cpp: --parameter, --from, --to, the orbit's --period,
// --section-phase and guess, --max-points, --json, --csv FILE, --mkdir. Exit 0 with branches, 3
// when no orbit is found at `from` (the output standing), 2 for bad input.
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/rig_options.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/reports/continuation_report.hpp"

#include <iostream>
#include <memory>
#include <vector>

namespace hertzdash::cli {

Command add_continue_command(CLI::App& app) {
  struct Request {
    const Rig* rig = nullptr;
    CLI::App* sub = nullptr;
    RunOptions run;
    RigInputs inputs, given;
    std::string csv_path;
    bool json = false, mkdir = false;
  };
  CLI::App* command = app.add_subcommand(
      "continue", "Branches of a rig's periodic orbits in a parameter: folds, period doublings, grazings");
  command->require_subcommand(1);
  auto requests = std::make_shared<std::vector<std::shared_ptr<Request>>>();
  for (const Rig& rig : rigs()) {
    if (!rig.sequence) continue;
    auto r = std::make_shared<Request>();
    r->rig = &rig;
    if (!rig.default_integrator.empty()) r->run.integrator = rig.default_integrator;
    r->sub = command->add_subcommand(std::string(rig.name),
                                     "The branches of `hertzdash orbit " + std::string(rig.name) + "` in a parameter");
    add_rig_options(*r->sub, rig, r->run, r->inputs, true);
    for (const ParameterDecl& d : options_of_command("continue")) {
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
      o->group(key.starts_with("guess-") ? "Newton's start (--guess-position)" : "The continuation");
    }
    requests->push_back(r);
  }
  return {command, [requests]() {
            for (const auto& r : *requests) {
              if (!r->sub->parsed()) continue;
              prepare_output_file("--csv", r->csv_path, r->mkdir);
              const ContinuationRequest request = continuation_request(r->given);
              const ContinuationResult result = run_continuation(*r->rig, r->run, load_paper_parameters(), r->inputs, request);
              if (!r->csv_path.empty()) {
                create_output_directories(r->csv_path, r->mkdir);
                continuation_csv(*r->rig, result).save(r->csv_path);
              }
              if (r->json) std::cout << to_json(*r->rig, result).dump(2) << "\n";
              else std::cout << continuation_text(*r->rig, result);
              if (result.failure.empty()) return 0;
              std::cerr << "hertzdash: no branch followed: " << result.failure << "\n";
              return 3;
            }
            return 2;
          }};
}

}  // namespace hertzdash::cli
