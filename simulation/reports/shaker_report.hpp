#pragma once
// What `shaker` computes and reports (simulation/shaker/shaker.hpp): the run resolved from the
// drop test's options (body, contact, law, e, solver) and the shaker's own (model/
// shaker_parameters.hpp), its JSON, and its per-impact CSV columns.
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

/// The integrator `shaker` and `walls` run their soft contacts with unless told otherwise: their
/// wall motion is a forcing of the regularised contact only (simulation/run/soft_contact.hpp).
inline constexpr const char* shaker_default_integrator = "gbs8-regularized";

/// The shaker's own options as given (unset: the declaration's default).
struct ShakerInputs {
  std::optional<double> frequency_Hz, amplitude_m, gamma, impacts, transient, start_phase;
  std::optional<std::string> impact_model;
};

struct ShakerCommandRun {
  DropTestSetup setup;
  std::string law;
  SolverSettings solver;
  ShakerOptions options;
  Parameters inputs;  ///< describe_run() and the shaker's options
  ShakerRun run;
};

/// Resolve and validate, without running (`run` left empty).
ShakerCommandRun resolve_shaker_command(const RunOptions& options, const PaperParameters& paper,
                                        const ShakerInputs& inputs);

/// Resolve, validate and run. InvalidParameter for bad options: `amplitude` with `gamma`,
/// `height` or `impact-velocity` (the body starts at rest on the wall), a non-integer count.
ShakerCommandRun run_shaker_command(const RunOptions& options, const PaperParameters& paper, const ShakerInputs& inputs);

/// `shaker --json`: "gamma", "frequency_Hz", "amplitude_m", "impact_model", "damping",
/// "integrator_used" (soft), "period", "impacts_per_period", "e_effective", the kept impacts as
/// arrays "impact_time_s", "impact_phase", "impact_speed_mps", "rebound_speed_mps",
/// "contact_time_s", "peak_force_N", "sticking_episodes", "impacts_run", "end_reason",
/// "warnings" (strings), "inputs", "git_revision", "schema_version".
nlohmann::ordered_json to_json(const ShakerCommandRun& run);

/// The CSV columns of the kept impacts (one row each) and a row's cells.
std::vector<std::string> shaker_csv_columns();
std::vector<double> shaker_csv_row(const ShakerImpact& impact, std::size_t n);

}  // namespace hertzdash
