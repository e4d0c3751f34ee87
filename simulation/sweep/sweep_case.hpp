#pragma once
// A sweep's case file (TOML; docs/sweep.md): the runs `hertzdash sweep CASE.toml` makes.
//
//   [base]     any `simulate` option by its command-line name or Python keyword, fixed; and
//              rig = "NAME": the runs are the registered rig's (simulation/rigs/rig.hpp, e.g.
//              "shaker"), its own inputs ("gamma") set here, in [grid] and [sample] too
//   [grid]     options varied over the cartesian product of their values: a list, or a range
//              { from, to, count, spacing = "linear" | "log" }; the first key varies slowest
//   [sample]   method ("monte-carlo", "latin-hypercube", "sobol"), count, seed, and one
//              distribution per varied option: { distribution = "uniform", min, max },
//              { distribution = "normal", mean, sd [, min, max] } or
//              { distribution = "lognormal", log_mean, log_sd [, min, max] } (min/max truncate)
//   [output]   columns (quantities of simulation/sweep/sweep_outputs.hpp), file, summary
//
// With both a grid and a sample, every grid point runs the whole sample (the same draws at every
// grid point), the sample varying fastest. Run i is grid point i / count, draw i % count.
//
// Reading validates the file's structure (keys, types, ranges, decimal numbers, the outputs) and,
// with a rig, its inputs against the rig (check_rig_inputs: run 0, each grid value, each draw);
// the rest of each run's options are validated when the run is resolved, so one bad point is an
// error of that row, not of the sweep.
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/rigs/rig.hpp"
#include "hertzdash/simulation/uncertainty/input_distribution.hpp"
#include "hertzdash/simulation/uncertainty/sample_design.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace hertzdash {

/// A value a case gives an option.
using SweepValue = std::variant<double, std::string, bool>;

/// One option varied by a case: over grid values, or drawn from a distribution.
struct SweepAxis {
  const RunOption* option = nullptr;             ///< an option of a run, or
  const ParameterDecl* rig_input = nullptr;      ///< an input of the case's rig
  std::vector<SweepValue> values;                ///< grid axis
  std::optional<InputDistribution> distribution; ///< sample input
  /// Its column: the Python keyword and unit ("height_m", "gamma").
  std::string column() const;
};

struct SweepSample {
  SampleMethod method = SampleMethod::monte_carlo;
  std::size_t count = 0;
  std::uint64_t seed = 1;
  std::vector<SweepAxis> inputs;
  std::vector<double> values;  ///< the draws: count x inputs.size(), point-major (the design's quantiles)
};

/// The largest number of runs of one case (results are held in memory: ~100 bytes a run).
inline constexpr std::size_t max_sweep_runs = 10'000'000;

struct SweepCase {
  std::string source;            ///< the file's path (messages, provenance)
  std::string text;              ///< the file's content, as read
  RunOptions base;
  const Rig* rig = nullptr;      ///< [base] rig: the runs are this rig's; unset: simulate's
  RigInputs rig_base;            ///< the rig's inputs [base] sets
  std::vector<SweepAxis> grid;   ///< in the file's order: the first varies slowest
  std::optional<SweepSample> sample;
  std::vector<std::string> outputs{"e_effective", "peak_force_N", "contact_time_s"};
  std::string output_file;       ///< [output] file as written (relative to the case file's folder), or empty
  bool summary = false;          ///< [output] summary: also write the quantiles of every output

  /// The number of runs: the grid's points times the sample's count.
  std::size_t size() const;
  /// The varied options' columns (column_name: "height_m"), grid first, then the sample's.
  std::vector<std::string> parameter_columns() const;
  /// The values run `run` gives the varied options, in parameter_columns() order.
  std::vector<SweepValue> parameters(std::size_t run) const;
  /// The options of run `run`: base with the varied options set (not yet validated).
  RunOptions options(std::size_t run) const;
  /// The rig's inputs of run `run`: rig_base with the varied inputs set.
  RigInputs rig_inputs(std::size_t run) const;
};

/// Parse a case from its text; `source` names it in messages. Throws DataError for a file that
/// is not TOML ("source:line:column: ..."), InvalidParameter for a key, type or value the case
/// format does not allow (naming the key, with "(source line N)", and its valid range).
SweepCase parse_sweep_case(std::string_view text, const std::string& source);

/// Read and parse the file (DataError if it cannot be read or exceeds 1 MiB).
SweepCase read_sweep_case(const std::filesystem::path& path);

/// Where the rows go: the case's [output] file (relative to the case file's folder), else the
/// case file's path with the extension .csv.
std::filesystem::path default_sweep_output(const SweepCase& c);

}  // namespace hertzdash
