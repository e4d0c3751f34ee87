#pragma once
// Fitting a damping law's own parameters to a bounce recording (io/bounce_recording.hpp;
// data/measurements/README.md, "Bounce recordings"), after its dirty data have been flagged and
// left out (bounce_recording_check.hpp): least squares of the impact times by the fit engine
// (fit_engine.hpp), as the restitution-table fit (restitution_fit.hpp).
//
// Model. Drop d's impact numbered k is at
//   t_{d,k} = t0_d + onset_k(v0_d),
// onset_k the onset time of impact k in the bounce sequence `hertzdash bounce --impact-velocity
// v0_d` runs (run_bounce_sequence, bounce_sequence.hpp: impacts by the integrators, flights as
// that function takes them, onset_0 = 0), with the run options and the fitted parameters
// replaced. Each drop has two nuisance parameters of its own: its first recorded impact's
// approach speed v0_d (> 0, fitted as ln v0) and its clock offset t0_d (any clock origin). The
// impacts run by gbs8 in the regularising variables at rtol = atol = 1e-12, as the table fit's
// (restitution_fit_model.hpp), so an onset time is accurate to far below any timing jitter and
// smooth in the parameters at the scale of the Jacobian's central differences (step 1e-6 in
// the unbounded variables); the model keeps its runs, so a drop's t0 costs no run and its speed
// two, and the Jacobian costs 2 (p_law + 1) sequences per drop.
//
// Parameters. The law's own, as for a table (law_fit_parameters; any fittable
// option by FitSettings::parameters, `--fit`). Starting values: the option given, else the
// input e at the median of the drops' interval ratios (bounce_recording_check.hpp), the time
// constant of a material-time-constant law calibrated to that e at the median first impact
// speed, else the set-up's value; v0_d = sqrt(2 g h) where the drop gives drop_height_m, else
// g dt_0 / (2 r S_g(r)) from its first interval (a rigid flight of 2 v / g, r the drop's ratio,
// S_g its span); t0_d the drop's first time.
//
// Residuals and uncertainty. r = t - t_model, one common, unknown timing sigma estimated as
// s^2 = RSS / (n - p), p = p_law + 2 D; covariance s^2 (J^T J)^-1 (restitution_fit.hpp);
// AIC = n ln(RSS / n) + 2 (p + 1), BIC = n ln(RSS / n) + (p + 1) ln n, RSS / n at least
// (1e-10 s)^2 (the model's accuracy; a noise-free synthetic recording otherwise gives ln 0).
// The nuisances count in p: every law has the same 2 D of them, so they shift every law's
// criteria alike and leave the ranking as it is.
//
// Cross-validation and profile intervals are the engine's (fit_engine.hpp). The folds are the
// drops: each in turn is left out, the rest fitted (from the full fit's estimate), then the
// left-out drop predicted with the law's parameters fixed and only its own v0 and t0 fitted; the
// prediction error's RMS is sqrt(sum RSS_d / sum (n_d - 2)), against the full fit's timing
// sigma. A drop is a group of the result (FitResult::groups: its label, times, and its v0
// `first_impact_speed_mps` and t0 `clock_offset_s`); a point's x is the model's approach speed.
#include "hertzdash/simulation/fit/bounce_recording_check.hpp"
#include "hertzdash/simulation/fit/fit_engine.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <string>
#include <vector>

namespace hertzdash {

/// Refuses (InvalidParameter) the options a bounce-recording fit cannot use: `impact-velocity`
/// or `height` (each drop's first impact speed is fitted), `gravity` 0, an elastic rod (flights
/// integrated: too slow to fit), an iterated omega_n, an option read only into a trace; then the
/// set-up's own refusals (resolve_setup) but for the Hertz scale of the speed, which each drop's
/// first impact speed sets (named after the drop, or after the option the user gave that sets
/// the bound, when the recording is fitted).
void check_bounce_fit_setup(const RunOptions& o, const PaperParameters& paper);

/// Fit the checked recording (`path`: for messages). Validates the options
/// (check_bounce_fit_setup); throws DataError for fewer times than parameters.
/// The result has a group per drop.
FitResult fit_bounce_recording(const CheckedRecording& data, const std::string& path, const RunOptions& base,
                               const PaperParameters& paper, const FitSettings& settings);

/// Every registered law fitted (fit_engine.hpp's compare_laws).
LawComparison compare_laws_on_bounces(const CheckedRecording& data, const std::string& path,
                                            const RunOptions& base, const PaperParameters& paper,
                                            const FitSettings& settings);

}  // namespace hertzdash
