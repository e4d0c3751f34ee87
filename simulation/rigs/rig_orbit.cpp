// A rig's periodic orbit (simulation/rigs/rig_orbit.hpp).
#include "hertzdash/simulation/rigs/rig_orbit.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/orbits/section_guess.hpp"

#include <fmt/format.h>

namespace hertzdash {

OrbitRequest orbit_request(const RigInputs& given) {
  for (const auto& [key, value] : given.numbers) require_in_range(command_option("orbit", key), value);
  OrbitRequest r;
  if (auto p = given.number("period")) r.period = static_cast<int>(*p);
  r.section_phase = given.number("section-phase");
  r.guess_position_m = given.number("guess-position");
  r.guess_velocity_mps = given.number("guess-velocity");
  if (r.guess_position_m.has_value() != r.guess_velocity_mps.has_value()) {
    const char* missing = r.guess_position_m ? "guess-velocity" : "guess-position";
    throw InvalidParameter(missing, "none", "given with the other half of the guess (position and velocity)");
  }
  if (r.guess_position_m && !r.section_phase)
    throw InvalidParameter("section-phase", "none", "given with a guess: the phase at which the guess holds");
  return r;
}

OrbitResult run_orbit(const Rig& rig, const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs,
                      const OrbitRequest& request) {
  if (!rig.sequence)
    throw InvalidParameter("rig", std::string(rig.name), "a rig on the impact-sequence driver with a prescribed box");
  check_rig_inputs(rig, options, inputs);
  RigSequence rs = rig.sequence(options, paper, inputs);
  const ImpactSequenceSpec& spec = rs.sequence.spec;
  if (spec.soft)
    throw InvalidParameter("impact-model", "soft",
                           "instantaneous for the orbit command: a soft contact's multipliers need its variational equations "
                           "(not yet built; docs/orbits.md)");
  if (!spec.prescribed)
    throw InvalidParameter("rig", std::string(rig.name), "a rig whose box moves as prescribed (the damper's does not)");
  const double v = spec.speed_scale_mps;
  OrbitResult out{.heading = rs.heading, .inputs = std::move(rs.inputs), .guess = {}, .period = 0, .section_phase = 0,
                  .scale = Eigen::Vector2d(v / spec.frequency_Hz, v), .orbit = {}};
  Eigen::VectorXd guess;
  if (request.guess_position_m) {
    out.period = request.period.value_or(1);
    out.section_phase = *request.section_phase;
    guess = Eigen::Vector2d(*request.guess_position_m, *request.guess_velocity_mps);
    out.guess = "the given guess";
  } else {
    const SectionGuess g = section_guess(spec, request.section_phase, request.period);
    out.period = g.period;
    out.section_phase = g.section_phase;
    if (!g.failure.empty()) {
      out.orbit.failure = g.failure;
      out.guess = "none";
      return out;
    }
    guess = g.state;
    out.guess = fmt::format("the rig's own run after {} transient impacts (period {}, {} impact{} per period)",
                            spec.transient, g.period, g.impacts_per_period, g.impacts_per_period == 1 ? "" : "s");
  }
  out.inputs.emplace_back("period", std::to_string(out.period));
  out.inputs.emplace_back("section_phase", fmt::format("{}", out.section_phase));
  out.inputs.emplace_back("newton_tolerance", fmt::format("{}", request.shooting.tolerance));
  const StroboscopicMap map(spec, out.section_phase, out.period);
  out.orbit = find_periodic_orbit(map, guess, out.scale, request.shooting);
  return out;
}

}  // namespace hertzdash
