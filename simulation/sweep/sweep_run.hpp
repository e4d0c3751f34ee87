#pragma once
// Running a sweep's case (simulation/sweep/sweep_case.hpp) and writing what it gives: a CSV with a
// row per run, and a summary of every output (count, mean, standard deviation, quantiles).
//
// A run that fails (an invalid point, an integrator that does not finish) records its error in
// its row and the sweep carries on. The rows depend only on the case, never on how the runs were
// shared out (threads, MPI ranks): the tables below are byte-identical however they were made,
// apart from the one timing line.
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/diagnostic_codes.hpp"
#include "hertzdash/simulation/sweep/parallel_sweep.hpp"
#include "hertzdash/simulation/sweep/sweep_case.hpp"

#include <array>
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

/// The outcome of some runs of a case: outputs (NaN where a run has none or failed), errors.
struct SweepResults {
  std::size_t outputs = 0;          ///< outputs per run (the case's output columns)
  std::vector<double> values;       ///< run-major: output k of the j-th run at [j * outputs + k]
  std::vector<std::string> errors;  ///< per run: why it failed, or empty
  std::vector<DiagnosticSet> diagnostics;  ///< per run: its notes and warnings (none for a failed run)
  /// A rig's case: per run its per-impact table, row-major, one cell per column of the rig's table.
  std::vector<std::vector<double>> impacts;
};

/// Per code of diagnostic_table, the runs whose result carries it.
std::array<std::size_t, diagnostic_table.size()> diagnostic_counts(const SweepResults& results);

/// "<code> N, ..." over the codes some run carries; empty if none.
std::string diagnostic_counts_text(const SweepResults& results);

/// Run the runs `runs` of the case (indices into [0, c.size())), in the order given, over the
/// threads of `options`. Stops early if options.cancel is set (the rest stay unrun: error
/// "not run").
SweepResults run_sweep(const SweepCase& c, const std::vector<std::size_t>& runs, const PaperParameters& paper,
                       const SweepOptions& options);

/// The rows: "run", the varied options (parameter_columns), the outputs, "warnings" (the codes
/// of the run's notes and warnings, space-separated: diagnostic_names), "error"; below the column
/// names the provenance with the case file's path, SHA-256 and text, and then `timing_line` (the
/// one line that may differ between two makings of the same sweep). `results` hold all runs in
/// order.
std::string sweep_table(const SweepCase& c, const SweepResults& results, const std::string& timing_line);

/// The same table given to `write` in pieces of a few thousand rows (write_files_atomically's
/// ContentPieces): a sweep of millions of runs goes to its file without being held as text.
void write_sweep_table(const SweepCase& c, const SweepResults& results, const std::string& timing_line,
                       const std::function<void(std::string_view)>& write);

/// A rig's case (SweepCase::rig): the per-impact tables of every run, one row per kept impact:
/// "run", the varied options, "n" and the rig's table columns (a labelled column as its index),
/// below the provenance of the case.
void write_sweep_impacts(const SweepCase& c, const SweepResults& results, const std::function<void(std::string_view)>& write);

/// Per output (and per value of every text or true/false grid option, e.g. per damping law):
/// runs, failed, mean, sd, min, q05, q25, median, q75, q95, max of the runs that gave a value.
/// Quantiles interpolate linearly between order statistics (Hyndman & Fan type 7, as NumPy).
/// A comment line below the column names counts the runs per diagnostic code ("warnings, runs per
/// code (of N): under_resolved 2, ...").
std::string sweep_summary_table(const SweepCase& c, const SweepResults& results);

/// The summary as aligned text for a terminal.
std::string sweep_summary_text(const SweepCase& c, const SweepResults& results);

}  // namespace hertzdash
