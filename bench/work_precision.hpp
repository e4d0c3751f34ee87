#pragma once
// The work-precision comparison of hertzdash's integrators against Boost.Odeint,
// GSL and naive CVODE, and the parallel-sweep throughput, run by the program
// bench/work_precision_peers: with full repeats for `make bench`, briefly for `make figures`.
#include <filesystem>
#include <vector>

namespace hertzdash::bench {

struct WorkPrecisionConfig {
  std::filesystem::path out_dir;        ///< CSV files (paper/figures)
  std::filesystem::path generated_dir;  ///< LaTeX macros and table (paper/generated)
  double budget_ms = 2.0;               ///< wall time of one timed repeat of one (solver, tolerance)
  int repeats = 5;                      ///< timed repeats; the median is reported
  bool half_decades = true;             ///< tolerances every half decade (else every decade)
  long sweep_impacts = 20000;           ///< impacts in the parallel-sweep throughput run
  /// Pages whose generated performance block (docs/performance.md, README.md) is refreshed.
  std::vector<std::filesystem::path> performance_pages;
  double figures_seconds = 0;           ///< measured wall time of `make figures` (0: not measured)
};

/// Runs everything, prints the side-by-side table and the ratios, writes
/// OUT/work_precision_peers.csv (contact phase), OUT/work_precision_peers_drop.csv
/// (full drop), GENERATED/work_precision_peers.tex (\perf... macros) and
/// GENERATED/work_precision_peers_table.tex. Returns 0.
int run_work_precision(const WorkPrecisionConfig& config);

}  // namespace hertzdash::bench
