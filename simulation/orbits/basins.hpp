#pragma once
// Basins of attraction of a rig's stroboscopic section (docs/orbits.md): a grid of starts z = (y
// [m], u [m/s]) of the body at the drive phase phi_s (a box of its own, the damper's primary,
// started at the same (X, V) from every cell: a slice of its four-dimensional section), each run by the impact-sequence driver
// (simulation/shaker/impact_sequence.hpp) for `transient` impacts and then `kept` more, and
// classified by the attractor it settles on:
//   - a periodic attractor: its period N (drive cycles, impact_pattern.hpp), its impacts per
//     period and their drive phases (sorted);
//   - the body at rest on the wall (a run that ends carried for good);
//   - no period within the kept impacts (chaotic, or slower to settle).
// Two starts reach the same attractor when these agree, the phases to `phase_tolerance` of a
// cycle (circularly). The attractors are numbered in the order of their first cell (row-major,
// velocity slowest): whatever the threads, the same grid gives the same numbers.
// Threads: each runs whole rows on a spec of its own (`make_spec`, called once per thread before
// they start), so a soft contact, which a spec's copies share, is never run by two threads at once.
// Processes (MPI ranks, the caller's `gather`): process r of R runs the rows r, r + R, ..., each on
// its threads, and sends their outcomes as text (every number in its shortest exact decimal) to
// process 0, which numbers the attractors over the whole grid: the same numbers as one process.
#include "hertzdash/simulation/shaker/impact_sequence.hpp"

#include <functional>
#include <string>
#include <vector>

namespace hertzdash {

struct BasinOptions {
  double section_phase = 0;  ///< phi_s in [0, 1)
  double position_min_m = 0, position_max_m = 0, velocity_min_mps = 0, velocity_max_mps = 0;
  double box_position_m = 0, box_velocity_mps = 0;  ///< a box of its own: its state at every start
  int resolution = 64;       ///< cells per axis (cell centres)
  int transient = 400, kept = 32;
  double phase_tolerance = 1e-4;  ///< cycles
  unsigned threads = 1;
  int rank = 0, ranks = 1;   ///< this process among the processes that share the grid's rows
  /// With ranks > 1: sends this process's text to process 0 and returns every process's, in rank
  /// order, there (empty on the others). Set by the caller (cli/process_group.hpp: MPI).
  std::function<std::vector<std::string>(const std::string&)> gather = {};
};

/// One attractor the grid reached.
struct BasinAttractor {
  enum class Kind { periodic, rest, no_period } kind = Kind::periodic;
  int period = 0, impacts_per_period = 0;
  std::vector<double> phases;   ///< periodic: the impacts' drive phases over one period, sorted
  long cells = 0;
  std::string describe() const;  ///< "period 1, 1 impact", "at rest on the wall", ...
};

struct Basins {
  std::vector<int> cell;  ///< per cell (row-major, velocity slowest): its attractor's index, or -1 for a start inside a wall
  std::vector<BasinAttractor> attractors;
  long inside_wall = 0;   ///< cells whose start lies inside a wall
  bool elsewhere = false; ///< a process other than 0 of several: the grid was numbered on process 0
};

/// The basins on the grid of `o` of the sequence `make_spec()` (the start's position, velocity and
/// time set per cell, a box of its own's state from `o`). std::invalid_argument for a grid of fewer than 2
/// cells per axis or an empty range.
Basins compute_basins(const std::function<ImpactSequenceSpec()>& make_spec, const BasinOptions& o);

/// The centre of cell i of n over [lo, hi].
inline double cell_centre(double lo, double hi, int i, int n) { return lo + (hi - lo) * (i + 0.5) / n; }

}  // namespace hertzdash
