#include "cli/setup_options.hpp"

#include "cli/number_options.hpp"

#include <iostream>
#include <type_traits>

namespace hertzdash::cli {

void add_run_options(CLI::App& app, RunOptions& options, RunOption::Group group) {
  for (const RunOption& o : run_options()) {
    if (o.group != group) continue;
    const std::string flag = "--" + o.name;
    std::visit(
        [&]<class T>(T RunOptions::*field) {
          T& value = options.*field;
          if constexpr (std::is_same_v<T, bool>) {
            app.add_flag(flag, value, o.help);
          } else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>) {
            add_number_option(app, flag, value, o.help);
          } else if constexpr (std::is_same_v<T, std::optional<std::string>>) {
            app.add_option_function<std::string>(flag, [&value](const std::string& v) { value = v; }, o.help);
          } else {
            app.add_option(flag, value, o.help)->capture_default_str();
          }
        },
        o.field);
  }
}

void add_run_options(CLI::App& app, RunOptions& options) {
  add_run_options(app, options, RunOption::Group::setup);
  add_run_options(app, options, RunOption::Group::solver);
}

void report_diagnostics(const std::vector<RunDiagnostic>& diagnostics) {
  for (const RunDiagnostic& d : diagnostics) std::cerr << "hertzdash: " << d.kind << ": " << d.message << "\n";
}

}  // namespace hertzdash::cli
