// The discrete-element engines' commands (simulation/reports/export_report.hpp, docs/engines.md):
//   - `hertzdash export --engine lammps|liggghts|yade`: a contact's input decks, two spheres head-on and
//     a sphere on a wall, each runnable as written, and the lines to paste into an input of one's
//     own, for the engine model that equals the law --damping names, with hertzdash's prediction
//     of each impact beside them; the three files written together, atomically, into --out;
//   - `hertzdash conformance --engine ...`: the installed engine run on every model it has at three
//     speeds, e asked against e the engine gives, beside the law's prediction.
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/setup_options.hpp"
#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/reports/export_report.hpp"

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

namespace hertzdash::cli {

namespace {

struct ExportOptions {
  RunOptions run;
  std::string engine, model, out;
  std::optional<double> steps_per_contact;
  bool json = false, mkdir = false;
};

}  // namespace

Command add_export_command(CLI::App& app) {
  auto opt = std::make_shared<ExportOptions>();
  CLI::App* sub = app.add_subcommand(
      "export", "Input decks of a contact for LAMMPS, LIGGGHTS or YADE: the engine model equal to --damping, runnable as written");
  add_run_options(*sub, opt->run);
  auto o = [](std::string_view key) { return declared_option("export", key); };
  sub->add_option(o("engine").flag, opt->engine, o("engine").help);
  sub->add_option(o("engine-model").flag, opt->model, o("engine-model").help);
  add_output_file_option(*sub, o("out").flag, opt->out, o("out").help);
  add_number_option(*sub, o("steps-per-contact").flag, opt->steps_per_contact, o("steps-per-contact").help);
  sub->add_flag(o("json").flag, opt->json, o("json").help);
  add_mkdir_flag(*sub, opt->mkdir);

  return {sub, [opt]() {
            const Engine engine = parse_engine(opt->engine);
            if (opt->out.empty()) throw InvalidParameter("out", "none", "given: the directory of the decks");
            const int steps = steps_per_contact_option("export", opt->steps_per_contact);
            const std::filesystem::path dir(opt->out);
            std::vector<std::pair<std::filesystem::path, std::string>> files;
            // Checked before any work, written after all of it.
            const auto names = engine_deck_files(engine);
            for (const std::string& name : names) prepare_output_file("out", (dir / name).string(), opt->mkdir);
            const EngineExport e = export_engine_decks(opt->run, load_paper_parameters(), engine, opt->model, steps);
            for (const auto& [name, text] : e.files()) files.emplace_back(dir / name, text);
            create_output_directories((dir / names[0]).string(), opt->mkdir);
            write_files_atomically(files);
            if (opt->json) std::cout << to_json(e).dump(2) << "\n";
            else {
              std::cout << export_text(e) << "  decks        ";
              for (const auto& [name, text] : files) std::cout << name.string() << (name == files.back().first ? "\n" : ", ");
            }
            return 0;
          }};
}

Command add_conformance_command(CLI::App& app) {
  struct ConformanceOptions {
    RunOptions run;
    std::string engine;
    std::optional<double> steps_per_contact;
    bool json = false;
  };
  auto opt = std::make_shared<ConformanceOptions>();
  CLI::App* sub = app.add_subcommand(
      "conformance", "Run an installed engine on every contact model it has: e asked against e the engine gives, "
                     "beside the law each model equals");
  add_run_options(*sub, opt->run);
  auto o = [](std::string_view key) { return declared_option("conformance", key); };
  sub->add_option(o("engine").flag, opt->engine, o("engine").help);
  add_number_option(*sub, o("steps-per-contact").flag, opt->steps_per_contact, o("steps-per-contact").help);
  sub->add_flag(o("json").flag, opt->json, o("json").help);
  return {sub, [opt]() {
            const Engine engine = parse_engine(opt->engine);
            const int steps = steps_per_contact_option("conformance", opt->steps_per_contact);
            const EngineConformance c = run_engine_conformance(opt->run, load_paper_parameters(), engine, steps);
            std::cout << (opt->json ? to_json(c).dump(2) + "\n" : conformance_text(c));
            return 0;
          }};
}

}  // namespace hertzdash::cli
