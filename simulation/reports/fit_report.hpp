#pragma once
// `hertzdash fit`'s run and report, for every front end and every kind of data (a measured trace,
// a restitution table, a bounce recording; simulation/fit/fit_engine.hpp): read the data, fit one
// law or every law (docs/fit.md), the warnings, the JSON (docs/json-output.md) and the curves.
#include "hertzdash/io/bounce_recording.hpp"
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/io/measured_trace.hpp"
#include "hertzdash/io/restitution_table.hpp"
#include "hertzdash/simulation/fit/bounce_fit.hpp"
#include "hertzdash/simulation/fit/bounce_recording_check.hpp"
#include "hertzdash/simulation/fit/restitution_fit.hpp"
#include "hertzdash/simulation/fit/trace_fit.hpp"
#include "hertzdash/simulation/reports/diagnostic_messages.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace hertzdash {

/// The kinds of data `hertzdash fit` reads: --trace, --restitution-table, --bounce-times.
enum class FitDataKind { trace, restitution_table, bounce_times };

/// What a fit is asked: the data's kind and file, the options, the settings.
struct FitRequest {
  FitDataKind kind = FitDataKind::trace;
  std::string path;
  RunOptions options;
  /// The fitted parameters (--fit); empty: the kind's default (a trace's ball-E and restitution,
  /// else the law's own).
  std::string fit;
  TraceFitSettings settings;  ///< the parameters replaced by `fit`'s; a trace's own settings apply to traces only
  bool compare_laws = false;
  std::vector<std::string> given;  ///< options given even at their default value (a trace's rod may not contradict them)
  double timing_sd_s = 0;          ///< a recording's timing precision [s] (CheckedRecording::timing_sd_s); 0: unknown
};

/// A fit: the data as read, one law or every law ranked.
struct FitRun {
  FitDataKind kind = FitDataKind::trace;
  MeasuredTrace trace;        ///< kind trace
  RestitutionTable table;     ///< kind restitution_table
  BounceRecording recording;  ///< kind bounce_times, as read
  CheckedRecording checked;   ///< kind bounce_times: what the fit uses, and what it flagged
  TraceFitSettings settings;
  std::vector<FitResult> fits;                                ///< one; or, comparing laws, best first
  std::vector<std::pair<std::string, std::string>> failures;  ///< comparing laws: law, why it could not be fitted
};

/// Validate the options (InvalidParameter), read the data (DataError), fit. A trace's header
/// sets the rod and height the options leave unset (trace_setup_options).
FitRun run_fit(const FitRequest& request, const PaperParameters& paper);

/// run_fit of a trace.
FitRun run_fit(const std::string& trace_path, const RunOptions& base, const PaperParameters& paper,
               const TraceFitSettings& settings, bool compare_all_laws, const std::vector<std::string>& given = {});

/// The warnings of one fit (the law named when comparing): not_converged, fit_failed or else
/// not_identifiable, at_bound, poor_fit (reduced chi-square above 2, sd known), the note
/// sigma_estimated, cross_validation_failed; a trace's fitted impact's diagnostics.
std::vector<RunDiagnostic> fit_diagnostics(const FitRun& run, const FitResult& fit, const PaperParameters& paper);

/// What stderr shows: the data's (synthetic_trace, _table, _recording; a trace's model_columns;
/// a recording's flagged times and its check's notes), then every fit's, a note once.
std::vector<RunDiagnostic> fit_diagnostics(const FitRun& run, const PaperParameters& paper);

/// `fit --json`: the data ("trace", "table" or "recording"; a recording's "flagged"), "fits",
/// "failures", "warnings", "schema_version", "git_revision" (docs/json-output.md).
nlohmann::ordered_json to_json(const FitRun& run, const PaperParameters& paper);

/// `fit --curves`: the trace, the fitted model and the residual of every channel of `fit`, one
/// row per sample time (t_s, then <channel>_measured, _model, _residual), written atomically
/// under a header naming the trace and the estimates.
void write_fit_curves(const FitResult& fit, const MeasuredTrace& trace, const std::filesystem::path& path);
/// The same table, not yet written.
CsvWriter fit_curves_csv(const FitResult& fit, const MeasuredTrace& trace);

}  // namespace hertzdash
