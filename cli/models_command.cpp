// `hertzdash models`: every registered damping law with its citation, formula,
// coefficients, validity and whether its force is continuous at contact onset.
#include "cli/command.hpp"
#include "cli/setup_options.hpp"
#include "hertzdash/model/damping/registry.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>

namespace hertzdash::cli {

Command add_models_command(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  CLI::App* sub = app.add_subcommand("models", "List the damping laws (--damping NAME) with their citations");
  sub->add_flag("--json", *json, declared_option("models", "json").help);
  return {sub, [json]() {
            if (*json) {
              std::cout << registered_laws_json().dump(2) << "\n";
              return 0;
            }
            for (const LawInfo& l : registered_laws()) {
              std::cout << fmt::format("{}{}\n", l.name, l.name == default_damping_law ? " (default)" : "");
              std::cout << fmt::format("  force:        {}\n", l.formula);
              std::cout << fmt::format("  coefficients: {}\n", l.coefficients);
              std::cout << fmt::format("  validity:     {}\n", l.validity);
              std::cout << fmt::format("  onset:        force {} at contact onset\n",
                                       l.force_continuous_at_onset ? "continuous (F = 0)" : "jumps (F != 0)");
              std::cout << fmt::format("  reference:    {}\n\n", l.citation);
            }
            return 0;
          }};
}

}  // namespace hertzdash::cli
