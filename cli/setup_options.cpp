#include "cli/setup_options.hpp"

#include "cli/number_options.hpp"

#include <iostream>

namespace hertzdash::cli {

void add_run_options(CLI::App& app, RunOptions& options, RunOption::Group group) {
  for (const RunOption& o : run_options()) {
    if (o.group != group) continue;
    const std::string flag = "--" + o.name;
    switch (o.decl.type) {
      case ParameterType::flag:
        app.add_flag_callback(flag, [&options, &o] { set_flag(options, o, true); }, o.help);
        break;
      case ParameterType::text:
        app.add_option_function<std::string>(flag, [&options, &o](const std::string& v) { set_text(options, o, v); },
                                             o.help);
        break;
      case ParameterType::number:
        add_number_option(app, flag, [&options, &o](double v) { set_number(options, o, v); }, o.help);
        break;
    }
  }
}

void add_run_options(CLI::App& app, RunOptions& options) {
  add_run_options(app, options, RunOption::Group::setup);
  add_run_options(app, options, RunOption::Group::solver);
}

void report_diagnostics(const std::vector<RunDiagnostic>& diagnostics) {
  for (const RunDiagnostic& d : diagnostics)
    std::cerr << "hertzdash: " << d.kind << ": " << spell_key_references(d.message, KeySpelling::command_line) << "\n";
}

}  // namespace hertzdash::cli
