#include "hertzdash/simulation/options/run_description.hpp"

#include "hertzdash/model/damping/registry.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <string>
#include <vector>

namespace hertzdash {

Parameters describe_run(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver) {
  const std::vector<LawInfo> laws = registered_laws();
  // A description of several laws ("all registered laws") describes every law's inputs the set-up holds.
  const std::string_view reading_law =
      std::any_of(laws.begin(), laws.end(), [&](const LawInfo& info) { return info.name == law; }) ? law : "";
  const IntegratorTraits& integrator = integrator_traits(solver.integrator);
  Parameters p;
  for (const RunOption& option : run_options()) {
    if (option.name == "damping") {
      p.emplace_back("damping", std::string(law));
      continue;
    }
    // A set-up holds flight-only inputs (air drag) only where its run follows flights.
    if (!option.value_in_run ||
        !option.readers.read_by(reading_law, setup.elastic_rod.has_value(), integrator, setup.air_drag.active()))
      continue;
    if (const auto value = option.value_in_run(setup, solver)) p.emplace_back(column_name(option), *value);
  }
  if (const auto& rod = setup.elastic_rod) {
    p.emplace_back("rod_length_m", fmt::format("{}", rod->length_m));
    p.emplace_back("rod_diameter_m", fmt::format("{}", rod->diameter_m));
  }
  return p;
}

}  // namespace hertzdash
