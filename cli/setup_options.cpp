#include "cli/setup_options.hpp"

#include "cli/number_options.hpp"
#include "hertzdash/simulation/options/command_options.hpp"

#include <iostream>

namespace hertzdash::cli {

namespace {

/// The heading an option is listed under in --help, from what reads it: the laws' inputs (those
/// of one law apart, a group --help folds into one line when it runs long), the elastic rod's,
/// the solver's, and the drop test's.
const char* help_group(const RunOption& o) {
  if (o.group == RunOption::Group::solver) return "Solver";
  if (o.readers.laws.size() == 1) return "Inputs of one law (--damping LAW)";
  if (!o.readers.laws.empty() || o.name == "damping") return "Damping law";
  if (o.readers.elastic_rod || o.name == "rod-model") return "Elastic rod and load cell (--rod-model elastic)";
  return "Drop test";
}

}  // namespace

void add_run_options(CLI::App& app, RunOptions& options, RunOption::Group group) {
  for (const RunOption& o : run_options()) {
    if (o.group != group) continue;
    const std::string flag = "--" + o.name;
    CLI::Option* added = nullptr;
    switch (o.decl.type) {
      case ParameterType::flag:
        added = app.add_flag_callback(flag, [&options, &o] { set_flag(options, o, true); }, o.help);
        break;
      case ParameterType::text:
        added = app.add_option_function<std::string>(
            flag, [&options, &o](const std::string& v) { set_text(options, o, v); }, o.help);
        break;
      case ParameterType::number:
        added = add_number_option(app, flag, [&options, &o](double v) { set_number(options, o, v); }, o.help);
        if (o.decl.range.kind == NumberRange::Kind::integer) added->type_name("INT");
        break;
    }
    added->group(help_group(o));
  }
}

void add_run_options(CLI::App& app, RunOptions& options) {
  add_run_options(app, options, RunOption::Group::setup);
  add_run_options(app, options, RunOption::Group::solver);
}

DeclaredOption declared_option(std::string_view command, std::string_view key) {
  const ParameterDecl& d = command_option(command, key);
  return {"--" + std::string(d.key), help_text(d, KeySpelling::command_line)};
}

void report_diagnostics(const std::vector<RunDiagnostic>& diagnostics) {
  for (const RunDiagnostic& d : diagnostics)
    std::cerr << "hertzdash: " << d.kind << ": " << spell_key_references(d.message, KeySpelling::command_line) << "\n";
}

}  // namespace hertzdash::cli
