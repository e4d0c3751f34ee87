#pragma once
// `hertzdash basins RIG`: the basins of attraction of a rig's stroboscopic section
// (simulation/orbits/basins.hpp, docs/orbits.md). The section phase is given, or the middle of the
// widest impact-free arc of the rig's own attractor; the grid spans the given ranges, or one state
// scale either side of that attractor's state at the section (the scales of
// simulation/rigs/rig_orbit.hpp: v_s / f for the position, v_s for the velocity).
#include "hertzdash/simulation/orbits/basins.hpp"
#include "hertzdash/simulation/rigs/rig_orbit.hpp"

#include <optional>
#include <string>

namespace hertzdash {

struct BasinsRequest {
  std::optional<double> section_phase, position_min_m, position_max_m, velocity_min_mps, velocity_max_mps;
  int resolution = 64, cell_transient = 400, cell_impacts = 32;
  unsigned threads = 0;  ///< 0: the machine's cores
  /// The processes sharing the grid's rows (BasinOptions: rank, ranks, gather; MPI in the program).
  int rank = 0, ranks = 1;
  std::function<std::vector<std::string>(const std::string&)> gather = {};
};
/// The request of the options given by key (`basins`' declarations); InvalidParameter naming a
/// key outside its range, or a range's bound without the other.
BasinsRequest basins_request(const RigInputs& given);

struct BasinsResult {
  std::string heading;  ///< the rig's
  Parameters inputs;    ///< the rig's run's, then the request's
  BasinOptions grid;    ///< as run (its ranges and section phase resolved)
  Basins basins;
  std::string failure;  ///< empty: the grid ran; else why not (a default needed, and the rig's run gives no attractor)
};

/// The basins of `rig` (see above). InvalidParameter for bad input and where `orbit` refuses.
BasinsResult run_basins(const Rig& rig, const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs,
                        const BasinsRequest& request);

}  // namespace hertzdash
