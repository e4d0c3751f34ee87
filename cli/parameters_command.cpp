// `hertzdash parameters`: every option of a run from its one declaration (key, unit, valid
// values, default and its source, what reads it, fittable, meaning), as the Markdown of
// docs/parameters.md.
#include "cli/command.hpp"
#include "hertzdash/simulation/reports/parameter_reference.hpp"

#include <iostream>

namespace hertzdash::cli {

Command add_parameters_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "parameters", "List every option with its unit, valid values, default and what reads it (docs/parameters.md)");
  return {sub, []() {
            std::cout << parameter_reference_markdown();
            return 0;
          }};
}

}  // namespace hertzdash::cli
