#pragma once
// What `simulate`, `restitution` and `bounce` compute and report, for every front end: the command
// line (cli/) prints these reports, Python (python/) returns them as dicts, so the two
// carry the same keys and the same numbers. The JSON schema is documented in
// docs/json-output.md; json_schema_version changes whenever a key is renamed or removed.
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/simulation/fit/virtual_measurement.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/reports/diagnostic_messages.hpp"
#include "hertzdash/simulation/reports/fit_report.hpp"
#include "hertzdash/simulation/run/bounce_sequence.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

/// Version of the JSON reports below ("schema_version"); see docs/json-output.md.
inline constexpr int json_schema_version = 2;

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
