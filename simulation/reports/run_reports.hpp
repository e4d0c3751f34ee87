#pragma once
// What `simulate`, `restitution` and `bounce` compute and report, for every front end: the command
// line (cli/) prints these reports, Python (python/) returns them as dicts, so the two
// carry the same keys and the same numbers. The JSON schema is documented in
// docs/json-output.md; json_schema_version changes whenever a key is renamed or removed.
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/simulation/fit/restitution_fit.hpp"
#include "hertzdash/simulation/fit/trace_fit.hpp"
#include "hertzdash/simulation/fit/virtual_measurement.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/reports/diagnostic_messages.hpp"
#include "hertzdash/simulation/run/bounce_sequence.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

/// Version of the JSON reports below ("schema_version"); see docs/json-output.md.
inline constexpr int json_schema_version = 1;

/// One drop test as asked for.
struct SimulateRun {
  DropTestSetup setup;
  std::string law;
  SolverSettings solver;
  Parameters inputs;                ///< describe_run(): the inputs actually used
  std::string fallback_reason;      ///< why summary.integrator_used differs from the one asked for, else empty
  ImpactSummary summary;
  std::vector<TraceSample> trace;   ///< the contact phase, if asked for
};

/// Resolve, validate and run (throws InvalidParameter for bad options).
SimulateRun run_simulate(const RunOptions& options, const PaperParameters& paper, bool record_trace = false);

/// Every note and warning of a run (impact_diagnostic_list of its summary), and with
/// `trace_note` (virtual_measurement_note, or empty) an `interpolated_samples` note after them.
std::vector<RunDiagnostic> run_diagnostics(const SimulateRun& run, const std::string& trace_note = {});

/// `simulate --json`: the summary, "law_coefficients", "warnings" (run_diagnostics(run,
/// trace_note)), "inputs", "schema_version", "git_revision".
nlohmann::ordered_json to_json(const SimulateRun& run, const std::string& trace_note = {});

/// The `height_m` line of a trace's header: the drop height, or for a set-up given its impact
/// velocity the height a free fall from rest reaches that speed from, v0^2 / (2 g) (0 without gravity).
double trace_height_m(const DropTestSetup& setup);

/// The run's contact recorded as a virtual experiment (simulation/fit/virtual_measurement.hpp), with
/// its provenance: `source` says it is synthetic and what made it; `rod` is the rod asked for;
/// `height_m` the drop height that gives the run's approach speed. Needs a run with a trace.
MeasuredTrace virtual_measurement(const SimulateRun& run, const std::string& rod, const MeasurementChain& chain);

/// The note every front end shows when the run's integrator stepped more coarsely than the
/// virtual measurement samples (the samples between steps are then interpolated), else empty.
std::string virtual_measurement_note(const SimulateRun& run, const MeasurementChain& chain);

/// The header parameters of a virtual measurement file: the run's inputs, the integrator that
/// ran, and the measurement chain.
Parameters virtual_measurement_parameters(const SimulateRun& run, const MeasurementChain& chain);

/// A fit of a measured trace (simulation/fit/trace_fit.hpp): one law, or every registered law ranked.
struct FitRun {
  MeasuredTrace trace;                                        ///< as read
  TraceFitSettings settings;
  std::vector<TraceFit> fits;                                 ///< one; or, comparing laws, best first
  std::vector<std::pair<std::string, std::string>> failures;  ///< comparing laws: law, why it could not be fitted
};

/// Read the trace, fit (validating like `simulate`: InvalidParameter; a bad trace: DataError).
/// The trace's header sets the rod and height the options leave unset (trace_setup_options;
/// `given`: options a front end was given even at their default value, e.g. "rod").
FitRun run_fit(const std::string& trace_path, const RunOptions& base, const PaperParameters& paper,
               const TraceFitSettings& settings, bool compare_all_laws, const std::vector<std::string>& given = {});

/// One fit: "law", "parameters" (name, initial, estimate, standard_error, lower, upper, at_bound),
/// "correlation", "channels", the goodness of fit and the criteria, "fitted_inputs".
nlohmann::ordered_json to_json(const TraceFit& fit, const PaperParameters& paper);

/// `fit --json`: "trace" (path, source, rod, height_m, synthetic, samples), "fits" (one law, or
/// every law ranked by AIC, best first), "failures" (laws that could not be fitted), "warnings"
/// (fit_diagnostics), "schema_version", "git_revision".
nlohmann::ordered_json to_json(const FitRun& run, const PaperParameters& paper);

/// `fit --curves`: the trace, the fitted model and the residual of every channel of `fit`, one
/// row per sample time (t_s, then <channel>_measured, _model, _residual), written atomically
/// under a header naming the trace and the estimates.
void write_fit_curves(const TraceFit& fit, const MeasuredTrace& trace, const std::filesystem::path& path);

/// The warnings every front end shows for a fit: a synthetic trace (synthetic_trace), and per
/// fit one that did not converge (not_converged), failed (fit_failed: TraceFit::failure) or else
/// is not identifiable (not_identifiable), has a
/// parameter at its bound (at_bound), does not explain the trace to its noise (poor_fit), and
/// the diagnostics of the fitted model's impact (simulation/run/diagnostic_codes.hpp).
std::vector<RunDiagnostic> fit_diagnostics(const FitRun& run, const PaperParameters& paper);

/// A fit of a restitution table (simulation/fit/restitution_fit.hpp): one law, or every law ranked.
struct RestitutionFitRun {
  RestitutionTable table;                                     ///< as read
  RestitutionFitSettings settings;
  std::vector<RestitutionFit> fits;                           ///< one; or, comparing laws, best first
  std::vector<std::pair<std::string, std::string>> failures;  ///< comparing laws: law, why it could not be fitted
};

/// Read the table and fit it (`fit --restitution-table`): validating the options first
/// (InvalidParameter), then the table (DataError); with settings.cross_validate each fit is
/// cross-validated (a fold that cannot be fitted is said in its cross_validation.failure).
RestitutionFitRun run_restitution_fit(const std::string& table_path, const RunOptions& base,
                                      const PaperParameters& paper, const RestitutionFitSettings& settings,
                                      bool compare_all_laws);

/// The warnings of one fit (`law`: named in the messages when comparing): the table's
/// synthetic_table, the note sigma_estimated, not_converged, fit_failed, not_identifiable,
/// at_bound, poor_fit (reduced chi-square above 2, with e_sd).
std::vector<RunDiagnostic> restitution_fit_diagnostics(const RestitutionFitRun& run, const RestitutionFit& fit);

/// Every fit's warnings, the table's once (what stderr shows).
std::vector<RunDiagnostic> restitution_fit_diagnostics(const RestitutionFitRun& run);

/// One fit: "law", "parameters", "correlation", "points", "e_effective_range", the criteria,
/// "cross_validation" if run, "warnings".
nlohmann::ordered_json to_json(const RestitutionFitRun& run, const RestitutionFit& fit);

/// `fit --restitution-table --json`: "table" (path, source, synthetic, rows, e_sd), "fits",
/// "failures", "warnings", "schema_version", "git_revision".
nlohmann::ordered_json to_json(const RestitutionFitRun& run);

/// A law's effective restitution in the rigid-wall contact phase (no gravity), or, given a
/// target, the input e that makes it the target (simulation/run/calibrate_restitution.hpp).
struct RestitutionRun {
  std::string law;
  DropTestSetup setup;                 ///< the contact phase of the set-up asked for
  SolverSettings solver;
  IntegratorKind integrator_used = IntegratorKind::cvode;
  std::string fallback_reason;         ///< as in SimulateRun
  std::optional<double> e_target;
  double e_input = 0, e_effective = 0;
  std::optional<int> iterations;       ///< Brent iterations of a calibration
  ImpactSummary summary;               ///< the run at e_input (its diagnostics)
};

/// Resolve, validate and run; the iterated omega_n variants are rejected (they need `simulate`).
RestitutionRun run_restitution(const RunOptions& options, const PaperParameters& paper,
                               std::optional<double> e_target = std::nullopt);

/// The notes and warnings of the run at e_input.
std::vector<RunDiagnostic> run_diagnostics(const RestitutionRun& run);

/// `restitution --json`, with "warnings" (run_diagnostics).
nlohmann::ordered_json to_json(const RestitutionRun& run);

/// A drop and its bounces (simulation/run/bounce_sequence.hpp), optionally with the input e
/// calibrated so that the first interval ratio is a target.
struct BounceRun {
  DropTestSetup setup;                 ///< as asked for (restitution: the calibrated input e, if calibrated)
  std::string law;
  SolverSettings solver;
  BounceOptions options;
  Parameters inputs;
  std::string fallback_reason;         ///< as in SimulateRun
  std::optional<double> interval_target;
  std::optional<RestitutionCalibration> calibration;
  BounceSequence sequence;
};

/// Resolve, validate, calibrate (given a target) and run.
BounceRun run_bounce(const RunOptions& options, const PaperParameters& paper, const BounceOptions& bounce,
                     std::optional<double> interval_target = std::nullopt);

/// The notes and warnings of a sequence: those about how it ran (integrator_fallback,
/// stability_limit, loose_tolerance) once, those about an impact's result once per impact
/// ("impact n: ...", `impact` set). not_separated is left out: the rod coming to rest ends a
/// sequence, and end_reason says so.
std::vector<RunDiagnostic> run_diagnostics(const BounceRun& run);

/// `bounce --json`: per impact, "onset_times_s", "e_from_intervals", "e_velocity_ratio", the
/// calibration if any, "warnings" (run_diagnostics; each impact also lists its codes in its own
/// "warnings"), "inputs", "schema_version", "git_revision".
nlohmann::ordered_json to_json(const BounceRun& run);

/// `models --json`: one entry per registered law.
nlohmann::ordered_json registered_laws_json();

}  // namespace hertzdash
