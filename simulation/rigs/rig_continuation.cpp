// A rig's branches of periodic orbits (simulation/rigs/rig_continuation.hpp).
#include "hertzdash/simulation/rigs/rig_continuation.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/options/command_options.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <tuple>

namespace hertzdash {

ContinuationRequest continuation_request(const RigInputs& given) {
  ContinuationRequest r;
  RigInputs orbit;
  for (const auto& [key, value] : given.numbers) {
    require_in_range(command_option("continue", key), value);
    if (key == "from") r.from = value;
    else if (key == "to") r.to = value;
    else if (key == "max-points") r.max_points = static_cast<int>(value);
    else orbit.numbers[key] = value;
  }
  const std::optional<std::string> parameter = given.text("parameter");
  if (!parameter) throw InvalidParameter("parameter", "none", "given: the rig's numeric input to continue in");
  r.parameter = *parameter;
  for (const char* key : {"from", "to"})
    if (!given.number(key)) throw InvalidParameter(key, "none", "given: the parameter's range, from ... to ...");
  if (r.from == r.to) throw InvalidParameter("to", format_value(r.to), "different from `from`");
  r.orbit = orbit_request(orbit);
  return r;
}

ContinuationResult run_continuation(const Rig& rig, const RunOptions& options, const PaperParameters& paper,
                                    const RigInputs& inputs, const ContinuationRequest& request) {
  // The parameter: one of the rig's numeric inputs, else a numeric option of its run.
  const std::string& key = request.parameter;
  const ParameterDecl* own = find_rig_input(rig, key);
  const RunOption* option = own ? nullptr : find_run_option(key);
  const ParameterDecl* decl = own ? own : option ? &option->decl : nullptr;
  if (!decl || decl->type != ParameterType::number || decl->range.kind == NumberRange::Kind::integer)
    throw InvalidParameter("parameter", key,
                           fmt::format("a numeric input of `hertzdash {}` or of its run (not a count)", rig.name));
  // The inputs that only place the rig's run's start: the map starts from its own states.
  if (key.starts_with("start-") || key == "height")
    throw InvalidParameter("parameter", key, "an input of the rig's dynamics, not of its run's start");
  auto at = [&](double value) {
    RigInputs in = inputs;
    RunOptions run = options;
    if (own) in.numbers[key] = value;
    else set_number(run, *option, value);
    return std::pair{run, in};
  };
  // Both ends checked as the rig checks its input: a value out of range is refused naming the key.
  const RigSequence end = std::apply([&](const RunOptions& r, const RigInputs& in) { return orbit_sequence(rig, r, paper, in); },
                                     at(request.to));
  RigSequence rs = std::apply([&](const RunOptions& r, const RigInputs& in) { return orbit_sequence(rig, r, paper, in); },
                              at(request.from));
  // Continued in e, an input whose default e sets (the shaker's gamma: the middle of e's period-1
  // window, and with it the amplitude) would change along the branch: refused unless given. Its
  // resolved value at either end, as the run records it, tells (the start's inputs aside). Other
  // parameters move the inputs derived from them on purpose (gamma the amplitude, frequency too).
  for (const ParameterDecl& d : rig.inputs) {
    if (key != "restitution" || d.key.starts_with("start-") || d.type != ParameterType::number) continue;
    const std::string column = input_column(d);
    auto value = [&](const Parameters& p) -> std::string {
      for (const auto& [name, text] : p)
        if (name == column) return text;
      return {};
    };
    if (value(rs.inputs) != value(end.inputs))
      throw InvalidParameter(std::string(d.key), "its default",
                             fmt::format("given when continuing in `{}`: its default changes with it ({} at `from`, {} at `to`)",
                                         key, value(rs.inputs), value(end.inputs)));
  }
  ContinuationResult out{.coordinates = section_coordinates(rs.sequence.spec), .heading = rs.heading, .inputs = std::move(rs.inputs), .parameter = key,
                         .column = own ? input_column(*own) : column_name(*option), .start = orbit_start(rs.sequence.spec, request.orbit),
                         .failure = {}, .continuation = {}};
  out.inputs.emplace_back("parameter", key);
  out.inputs.emplace_back("from", fmt::format("{}", request.from));
  out.inputs.emplace_back("to", fmt::format("{}", request.to));
  if (!out.start.failure.empty()) {
    out.failure = out.start.failure;
    return out;
  }
  out.inputs.emplace_back("period", std::to_string(out.start.period));
  out.inputs.emplace_back("section_phase", fmt::format("{}", out.start.section_phase));
  const SequenceFamily family = [&](double value) {
    const auto [run, in] = at(value);
    return rig.sequence(run, paper, in).sequence.spec;
  };
  const ContinuationOptions o{.from = request.from, .to = request.to, .period = out.start.period,
                              .section_phase = out.start.section_phase, .start = out.start.state,
                              .scale = orbit_scales(rs.sequence.spec), .max_points = request.max_points};
  try {
    out.continuation = continue_periodic_orbits(family, o);
  } catch (const std::runtime_error& e) {
    out.failure = e.what();
  }
  return out;
}

}  // namespace hertzdash
