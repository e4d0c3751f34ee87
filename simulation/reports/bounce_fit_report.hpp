#pragma once
// `fit --bounce-times`'s run and report, for every front end: read a bounce recording
// (io/bounce_recording.hpp), flag its dirty data (simulation/fit/bounce_recording_check.hpp), fit
// one law or every law (and cross-validate) (simulation/fit/bounce_fit.hpp); the warnings, each
// flagged time among them, and the JSON (docs/fit.md, "Bounce recordings").
#include "hertzdash/io/bounce_recording.hpp"
#include "hertzdash/simulation/fit/bounce_fit.hpp"
#include "hertzdash/simulation/fit/bounce_recording_check.hpp"
#include "hertzdash/simulation/reports/diagnostic_messages.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <utility>
#include <vector>

namespace hertzdash {

/// A fit of a bounce recording: one law, or every law ranked.
struct BounceFitRun {
  BounceRecording recording;                                  ///< as read
  CheckedRecording checked;                                   ///< what the fit uses, and what it flagged
  BounceFitSettings settings;
  std::vector<BounceFit> fits;                                ///< one; or, comparing laws, best first
  std::vector<std::pair<std::string, std::string>> failures;  ///< comparing laws: law, why it could not be fitted
};

/// Read, check and fit the recording (`fit --bounce-times`): validating the options first
/// (InvalidParameter), then the file and whether anything in it is usable (DataError).
BounceFitRun run_bounce_fit(const std::string& recording_path, const RunOptions& base, const PaperParameters& paper,
                            const BounceFitSettings& settings, bool compare_all_laws);

/// The warnings of one fit (`law` named in the messages when comparing): synthetic_recording, the
/// note sigma_estimated, not_converged, fit_failed, not_identifiable, at_bound,
/// cross_validation_failed.
std::vector<RunDiagnostic> bounce_fit_diagnostics(const BounceFitRun& run, const BounceFit& fit);

/// What stderr shows: each flagged time (`flagged`, a warning), the check's notes
/// (`bounce_check`), every fit's warnings, the recording's once.
std::vector<RunDiagnostic> bounce_fit_diagnostics(const BounceFitRun& run);

/// One fit: "law", "parameters", "correlation", "drops" (the nuisances), "points",
/// "e_effective_range", the criteria, "cross_validation" if run, "warnings".
nlohmann::ordered_json to_json(const BounceFitRun& run, const BounceFit& fit);

/// `fit --bounce-times --json`: "recording" (path, source, synthetic, drops, impacts, used),
/// "flagged" ({drop, index, kind, reason} each), "fits", "failures", "warnings",
/// "schema_version", "git_revision".
nlohmann::ordered_json to_json(const BounceFitRun& run);

}  // namespace hertzdash
