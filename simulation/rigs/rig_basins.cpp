// A rig's basins of attraction (simulation/rigs/rig_basins.hpp).
#include "hertzdash/simulation/rigs/rig_basins.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/parameter.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/orbits/section_guess.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <thread>

namespace hertzdash {

BasinsRequest basins_request(const RigInputs& given) {
  for (const auto& [key, value] : given.numbers) require_in_range(command_option("basins", key), value);
  BasinsRequest r;
  r.section_phase = given.number("section-phase");
  r.position_min_m = given.number("position-min"), r.position_max_m = given.number("position-max");
  r.velocity_min_mps = given.number("velocity-min"), r.velocity_max_mps = given.number("velocity-max");
  for (const auto& [low, high, lo, hi] : {std::tuple{"position-min", "position-max", r.position_min_m, r.position_max_m},
                                          std::tuple{"velocity-min", "velocity-max", r.velocity_min_mps, r.velocity_max_mps}}) {
    if (lo.has_value() != hi.has_value())
      throw InvalidParameter(lo ? high : low, "none", fmt::format("given with `{}`", lo ? low : high));
    if (lo && !(*hi > *lo)) throw InvalidParameter(high, format_value(*hi), fmt::format("above `{}` = {}", low, format_value(*lo)));
  }
  r.resolution = static_cast<int>(given.number_or_default(command_option("basins", "resolution")));
  r.cell_transient = static_cast<int>(given.number_or_default(command_option("basins", "cell-transient")));
  r.cell_impacts = static_cast<int>(given.number_or_default(command_option("basins", "cell-impacts")));
  r.threads = static_cast<unsigned>(given.number_or_default(command_option("basins", "threads")));
  return r;
}

BasinsResult run_basins(const Rig& rig, const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs,
                        const BasinsRequest& request) {
  RigSequence rs = orbit_sequence(rig, options, paper, inputs);
  const ImpactSequenceSpec& spec = rs.sequence.spec;
  BasinsResult out{.heading = rs.heading, .inputs = std::move(rs.inputs), .grid = {}, .basins = {}, .failure = {}};
  BasinOptions& g = out.grid;
  g.resolution = request.resolution, g.transient = request.cell_transient, g.kept = request.cell_impacts;
  g.threads = request.threads > 0 ? request.threads : std::max(1u, std::thread::hardware_concurrency());
  g.rank = request.rank, g.ranks = request.ranks, g.gather = request.gather;
  // A box of its own starts every cell where the rig's own attractor has it at the section.
  if (!request.position_min_m || !request.velocity_min_mps || !request.section_phase || !spec.prescribed) {
    // The rig's own attractor gives what is not given.
    const SectionGuess guess = section_guess(spec, request.section_phase, 1);
    if (!guess.failure.empty()) {
      out.failure = spec.prescribed ? "the rig's own run gives no attractor to place the grid at (give --section-phase "
                                      "and the four bounds): " + guess.failure
                                    : "the rig's own run gives no attractor to start the primary from (a box of its "
                                      "own starts every cell where the run's attractor has it): " + guess.failure;
      return out;
    }
    g.section_phase = guess.section_phase;
    if (!spec.prescribed) g.box_position_m = guess.state(2), g.box_velocity_mps = guess.state(3);
    // The window: the rig's scales around the attractor's state, at most the walls' span across
    // (two walls: the clearance), and for a box of its own (whose speed scale is the primary's
    // acceleration's) the body's own speed at the section.
    const Eigen::VectorXd s = orbit_scales(spec);
    double dy = s(0), du = s(1);
    if (spec.walls.size() == 2) dy = std::min(dy, 0.5 * std::abs(spec.walls[1].offset_m - spec.walls[0].offset_m));
    if (!spec.prescribed && std::abs(guess.state(1)) > 0) du = std::abs(guess.state(1));
    g.position_min_m = guess.state(0) - dy, g.position_max_m = guess.state(0) + dy;
    g.velocity_min_mps = guess.state(1) - du, g.velocity_max_mps = guess.state(1) + du;
  }
  if (request.section_phase) g.section_phase = *request.section_phase;
  if (request.position_min_m) g.position_min_m = *request.position_min_m, g.position_max_m = *request.position_max_m;
  if (request.velocity_min_mps) g.velocity_min_mps = *request.velocity_min_mps, g.velocity_max_mps = *request.velocity_max_mps;
  for (const auto& [key, value] : {std::pair{"section_phase", g.section_phase}, {"position_min_m", g.position_min_m},
                                   {"position_max_m", g.position_max_m}, {"velocity_min_mps", g.velocity_min_mps},
                                   {"velocity_max_mps", g.velocity_max_mps}})
    out.inputs.emplace_back(key, fmt::format("{}", value));
  if (!spec.prescribed) {
    out.inputs.emplace_back("box_position_m", fmt::format("{}", g.box_position_m));
    out.inputs.emplace_back("box_velocity_mps", fmt::format("{}", g.box_velocity_mps));
  }
  out.inputs.emplace_back("resolution", std::to_string(g.resolution));
  out.inputs.emplace_back("cell_transient", std::to_string(g.transient));
  out.inputs.emplace_back("cell_impacts", std::to_string(g.kept));
  out.inputs.emplace_back("processes", std::to_string(g.ranks));  // how it ran: the result does not depend on it
  // Each thread its own copy of the rig's sequence (its own soft contact).
  out.basins = compute_basins([&] { return rig.sequence(options, paper, inputs).sequence.spec; }, g);
  return out;
}

}  // namespace hertzdash
