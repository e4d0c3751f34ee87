// The registered rigs (simulation/rigs/rig.hpp), one line each, and what every rig shares: its
// inputs' lookup and checks.
#include "hertzdash/simulation/rigs/oblique_rig.hpp"
#include "hertzdash/simulation/rigs/oscillator_rig.hpp"
#include "hertzdash/simulation/rigs/rig.hpp"
#include "hertzdash/simulation/rigs/shaker_rig.hpp"
#include "hertzdash/simulation/rigs/spheres_rig.hpp"
#include "hertzdash/simulation/rigs/walls_rig.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

namespace hertzdash {

std::span<const Rig> rigs() {
  static const std::array table{
      shaker_rig(),
      walls_rig(),
      oscillator_rig(),
      spheres_rig(),
      oblique_rig(),
  };
  return table;
}

const Rig* find_rig(std::string_view name) {
  for (const Rig& r : rigs())
    if (r.name == name) return &r;
  return nullptr;
}

const ParameterDecl* find_rig_input(const Rig& rig, std::string_view key) {
  for (const ParameterDecl& d : rig.inputs)
    if (d.key == key) return &d;
  return nullptr;
}

void require_free_sphere(const RunOptions& o, std::string_view speed_is, std::string_view whose_mass) {
  check_given_options(o);  // what is given first: a malformed number before a missing one
  if (!o.impact_velocity_mps) throw InvalidParameter("impact-velocity", "none", fmt::format("given: {}", speed_is));
  if (!o.mass_kg && !o.density_kg_per_m3)
    throw InvalidParameter("mass", "none", fmt::format("given, or `density`: {} (no preset body is a sphere)", whose_mass));
}

std::string input_column(const ParameterDecl& d) {
  const std::string keyword = python_keyword(d.key);
  return d.column_unit.empty() ? keyword : keyword + "_" + std::string(d.column_unit);
}

Parameters describe_rig_run(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                            std::span<const std::string_view> not_read) {
  Parameters p = describe_run(setup, law, solver);
  std::erase_if(p, [&](const auto& entry) {
    return std::any_of(not_read.begin(), not_read.end(), [&](std::string_view key) {
      const RunOption* o = find_run_option(key);
      return o && column_name(*o) == entry.first;
    });
  });
  return p;
}

std::string flat_name(std::string_view name) {
  std::string s(name);
  std::replace(s.begin(), s.end(), '.', '_');
  return s;
}

std::optional<double> RigInputs::number(std::string_view key) const {
  const auto it = numbers.find(key);
  return it == numbers.end() ? std::nullopt : std::optional(it->second);
}

std::optional<std::string> RigInputs::text(std::string_view key) const {
  const auto it = texts.find(key);
  return it == texts.end() ? std::nullopt : std::optional(it->second);
}

double RigInputs::number_or_default(const ParameterDecl& d) const { return number(d.key).value_or(d.default_number); }

void check_rig_inputs(const Rig& rig, const RunOptions& options, const RigInputs& inputs) {
  auto declared = [&](const std::string& key, ParameterType type) -> const ParameterDecl& {
    const ParameterDecl* d = find_rig_input(rig, key);
    if (!d || d->type != type) throw std::invalid_argument(fmt::format("`{}` is no input of the rig {}", key, rig.name));
    return *d;
  };
  for (const auto& [key, value] : inputs.numbers) require_in_range(declared(key, ParameterType::number), value);
  for (const auto& [key, text] : inputs.texts) {
    const std::string& value = text;  // a lambda may not capture a structured binding in clang 14
    const ParameterDecl& d = declared(key, ParameterType::text);
    const std::vector<std::string> choices = split_option_list(std::string(d.choices));
    if (std::none_of(choices.begin(), choices.end(), [&](const std::string& c) { return c == value || " " + value == c; }))
      throw InvalidParameter(key, value, "one of: " + std::string(d.choices));
  }
  for (const std::string_view key : rig.run_options_not_read) {
    const RunOption* o = find_run_option(key);
    if (o && is_given(options, *o))
      throw InvalidParameter(std::string(key), given_text(options, *o),
                             fmt::format("not given for `hertzdash {}` ({})", rig.name, rig.not_read_because));
  }
  if (rig.refuse) rig.refuse(options, inputs);
}

RigResult run_rig(const Rig& rig, const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs) {
  check_rig_inputs(rig, options, inputs);
  return rig.run(options, paper, inputs);
}

}  // namespace hertzdash
