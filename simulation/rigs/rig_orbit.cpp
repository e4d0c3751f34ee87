// A rig's periodic orbit (simulation/rigs/rig_orbit.hpp).
#include "hertzdash/simulation/rigs/rig_orbit.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/parameter.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/orbits/section_guess.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace hertzdash {

OrbitRequest orbit_request(const RigInputs& given) {
  for (const auto& [key, value] : given.numbers) require_in_range(command_option("orbit", key), value);
  OrbitRequest r;
  if (auto p = given.number("period")) r.period = static_cast<int>(*p);
  r.section_phase = given.number("section-phase");
  r.guess_position_m = given.number("guess-position");
  r.guess_velocity_mps = given.number("guess-velocity");
  r.guess_box_position_m = given.number("guess-box-position");
  r.guess_box_velocity_mps = given.number("guess-box-velocity");
  for (const auto& [given_key, other] : {std::pair{"guess-box-position", "guess-position"}, {"guess-box-velocity", "guess-position"}})
    if (given.number(given_key) && !r.guess_position_m)
      throw InvalidParameter(other, "none", fmt::format("given with `{}` (the body's half of the guess)", given_key));
  if (r.guess_position_m.has_value() != r.guess_velocity_mps.has_value()) {
    const char* missing = r.guess_position_m ? "guess-velocity" : "guess-position";
    throw InvalidParameter(missing, "none", "given with the other half of the guess (position and velocity)");
  }
  if (r.guess_position_m && !r.section_phase)
    throw InvalidParameter("section-phase", "none", "given with a guess: the phase at which the guess holds");
  return r;
}

RigSequence orbit_sequence(const Rig& rig, const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs) {
  if (!rig.sequence)
    throw InvalidParameter("rig", std::string(rig.name), "a rig on the impact-sequence driver with a prescribed box");
  check_rig_inputs(rig, options, inputs);
  RigSequence rs = rig.sequence(options, paper, inputs);
  if (rs.sequence.spec.soft && !rs.sequence.spec.soft_tangent)
    throw InvalidParameter("damping", options.damping,
                           fmt::format("a law whose force declares its dependence on the impact speed, for a soft "
                                       "orbit's variational equations ({}), or `impact-model` instantaneous",
                                       contact_tangent_laws()));
  return rs;
}

Eigen::VectorXd orbit_scales(const ImpactSequenceSpec& spec) {
  const double v = spec.speed_scale_mps, x = v / spec.frequency_Hz;
  if (spec.prescribed) return Eigen::Vector2d(x, v);
  return Eigen::Vector4d(x, v, x, v);
}

OrbitStart orbit_start(const ImpactSequenceSpec& spec, const OrbitRequest& request) {
  OrbitStart start;
  if (request.guess_position_m) {
    const bool own_box = !spec.prescribed;
    for (const auto& [key, value] : {std::pair{"guess-box-position", request.guess_box_position_m},
                                     {"guess-box-velocity", request.guess_box_velocity_mps}}) {
      if (own_box && !value) throw InvalidParameter(key, "none", "given with a guess on a box of its own (walls --rig damper)");
      if (!own_box && value) throw InvalidParameter(key, format_value(*value), "given only with a box of its own (walls --rig damper)");
    }
    start.period = request.period.value_or(1);
    start.section_phase = *request.section_phase;
    start.state = own_box ? Eigen::VectorXd(Eigen::Vector4d(*request.guess_position_m, *request.guess_velocity_mps,
                                                            *request.guess_box_position_m, *request.guess_box_velocity_mps))
                          : Eigen::VectorXd(Eigen::Vector2d(*request.guess_position_m, *request.guess_velocity_mps));
    start.guess = "the given guess";
    return start;
  }
  SectionGuess g = section_guess(spec, request.section_phase, request.period);
  start.period = g.period;
  start.section_phase = g.section_phase;
  start.state = std::move(g.state);
  start.failure = std::move(g.failure);
  start.guess = start.failure.empty()
                    ? fmt::format("the rig's own run after {} transient impacts (period {}, {} impact{} per period)",
                                  spec.transient, g.period, g.impacts_per_period, g.impacts_per_period == 1 ? "" : "s")
                    : "none";
  return start;
}

OrbitResult run_orbit(const Rig& rig, const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs,
                      const OrbitRequest& request) {
  RigSequence rs = orbit_sequence(rig, options, paper, inputs);
  const ImpactSequenceSpec& spec = rs.sequence.spec;
  const OrbitStart start = orbit_start(spec, request);
  OrbitResult out{.coordinates = section_coordinates(spec), .heading = rs.heading, .inputs = std::move(rs.inputs), .method = monodromy_method(spec), .guess = start.guess, .period = start.period,
                  .section_phase = start.section_phase, .scale = orbit_scales(spec), .orbit = {}};
  if (!start.failure.empty()) {
    out.orbit.failure = start.failure;
    return out;
  }
  out.inputs.emplace_back("period", std::to_string(out.period));
  out.inputs.emplace_back("section_phase", fmt::format("{}", out.section_phase));
  out.inputs.emplace_back("newton_tolerance", fmt::format("{}", request.shooting.tolerance));
  out.orbit = find_periodic_orbit(StroboscopicMap(spec, out.section_phase, out.period), start.state, out.scale,
                                  request.shooting);
  return out;
}

}  // namespace hertzdash
