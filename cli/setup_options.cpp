#include "cli/setup_options.hpp"

#include "cli/number_options.hpp"
#include "hertzdash/simulation/run_reports.hpp"

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

void report_fallback(IntegratorKind asked, IntegratorKind used, const std::string& why) {
  if (const std::string note = fallback_note(asked, used, why); !note.empty())
    std::cerr << "hertzdash: note: " << note << "\n";
}

}  // namespace hertzdash::cli
