#pragma once
// Bifurcation diagrams of the shaker (simulation/shaker/shaker.hpp): one parameter of the wall,
// gamma = A (2 pi f)^2 / g, the amplitude A [m] or the frequency f [Hz], swept linearly over
// [from, to] in `count` values, value i = from + (to - from) i / (count - 1) (the ends exact),
// one independent `shaker` run per value (resolved as the rig `shaker` resolves that value;
// each starts where a single run with that value starts), on the threads of
// simulation/sweep/parallel_sweep.hpp, or on MPI processes (cli/shaker_sweep.cpp gathers them).
// The runs are stored by value index, so the table depends only on the inputs, never on the
// threads or processes. One CSV row per kept impact of every value: the bifurcation diagram (docs/shaker.md).
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/simulation/rigs/shaker_rig.hpp"
#include "hertzdash/simulation/sweep/parallel_sweep.hpp"

#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

/// The swept parameter and its values.
struct ShakerSweepAxis {
  std::string key;  ///< "gamma", "amplitude" or "frequency"
  double from = 0, to = 0;
  int count = 0;  ///< >= 2
  /// Value i of [0, count).
  double value(int i) const;
  /// The CSV column of the value: "gamma", "amplitude_m", "frequency_Hz".
  std::string column() const;
};

/// "KEY:FROM:TO:COUNT" (model/shaker_sweep_parameters.hpp); InvalidParameter("sweep", ...) for a
/// malformed text, InvalidParameter naming KEY for an end outside KEY's declared range.
ShakerSweepAxis parse_shaker_sweep(std::string_view text);

struct ShakerSweep {
  ShakerSweepAxis axis;
  std::vector<ShakerCommandRun> runs;  ///< one per value, in value order (`run` empty until run)
};

/// Every value's run resolved and validated (cheap: nothing is run), with the other inputs as
/// given: `inputs` must not set the swept key, nor `gamma` or `amplitude` when sweeping either
/// of them (InvalidParameter names it), and every value must be valid (InvalidParameter).
ShakerSweep resolve_shaker_sweep(const RunOptions& options, const PaperParameters& paper, const RigInputs& inputs,
                                 const ShakerSweepAxis& axis);

/// Run the values `values` (indices into sweep.runs) on the threads of `sweep_options`. The
/// first failing run's exception is rethrown once all threads have stopped.
void run_shaker_sweep(ShakerSweep& sweep, const std::vector<std::size_t>& values, const SweepOptions& sweep_options);

/// The outcome of the runs `values` as numbers and their warnings as text (to gather them from
/// MPI processes), and back into `sweep`: unpack_shaker_runs(s, v, pack_shaker_runs(t, v),
/// pack_shaker_warnings(t, v)) gives the runs of s at v what the diagram reads of t's (gamma, the
/// pattern, e_effective, the counts, the kept impacts, the warnings; not end_reason or work).
std::vector<double> pack_shaker_runs(const ShakerSweep& sweep, const std::vector<std::size_t>& values);
std::string pack_shaker_warnings(const ShakerSweep& sweep, const std::vector<std::size_t>& values);
void unpack_shaker_runs(ShakerSweep& sweep, const std::vector<std::size_t>& values, const std::vector<double>& numbers,
                        const std::string& warnings);

/// The diagram: columns "run" (value index), the axis column, "gamma" (if not the axis), "n"
/// (kept impact), "impact_phase", "impact_speed_mps", "rebound_speed_mps", "contact_time_s",
/// "period", "impacts_per_period"; one row per kept impact; the provenance holds the inputs every
/// run shares (those that vary along the sweep are in the rows) and the sweep, and a comment line
/// per run that warned.
CsvWriter shaker_sweep_csv(const ShakerSweep& sweep);

}  // namespace hertzdash
