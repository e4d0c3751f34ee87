#pragma once
// Fitting a damping law's own parameters to a bounce recording (io/bounce_recording.hpp;
// data/measurements/README.md, "Bounce recordings"), after its dirty data have been flagged and
// left out (bounce_recording_check.hpp): weighted nonlinear least squares of the impact times,
// GSL's multifit_nlinear (trust region, Levenberg-Marquardt), as the restitution-table fit
// (restitution_fit.hpp).
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
// the unbounded variables); d r / d t0_d = -1 exactly, and a drop's speed moves its own times
// only, so the Jacobian costs 2 (p_law + 1) sequences per drop.
//
// Parameters. The law's own, as for a table (default_restitution_fit_parameters; any fittable
// option by BounceFitSettings::parameters, `--fit`). Starting values: the option given, else the
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
// Cross-validation. Each drop in turn is left out, the rest fitted (from the full fit's
// estimate), then the left-out drop predicted with the law's parameters fixed and only its own
// v0 and t0 fitted; the prediction error's RMS is sqrt(sum RSS_d / sum (n_d - 2)) (each drop's
// residuals after its two nuisances, per degree of freedom left), against the full fit's timing
// sigma: a ratio about 1 for a law that predicts a new drop as well as the data allow.
#include "hertzdash/simulation/fit/bounce_recording_check.hpp"
#include "hertzdash/simulation/fit/restitution_fit.hpp"
#include "hertzdash/simulation/fit/trace_fit.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace hertzdash {

/// How to fit a bounce recording.
struct BounceFitSettings {
  /// Empty: the law's own (default_restitution_fit_parameters).
  std::vector<FitParameter> parameters;
  int max_iterations = 200;
  bool cross_validate = false;
};

/// Refuses (InvalidParameter) the options a bounce-recording fit cannot use: `impact-velocity`
/// or `height` (each drop's first impact speed is fitted), an elastic rod (flights integrated:
/// too slow to fit), an iterated omega_n, an option read only into a trace.
void check_bounce_fit_options(const RunOptions& o);

/// One usable impact time and the fitted model there.
struct BouncePoint {
  std::string drop;
  std::size_t index = 0;     ///< the time's index in its drop (file order)
  int impact_number = 0;     ///< from the drop's first (a missed impact makes a gap)
  double measured = 0, model = 0, residual = 0;  ///< [s]; residual = measured - model
  double impact_speed_mps = 0;  ///< the model's approach speed of this impact
};

/// A drop's nuisance parameters at the estimate.
struct BounceDropFit {
  std::string label;
  std::size_t impacts = 0;             ///< times used
  double drop_height_m = 0;            ///< as recorded (0: not given)
  FittedParameter first_impact_speed;  ///< v0 [m/s]
  FittedParameter clock_offset;        ///< t0 [s]: the drop's first impact on its own clock
};

/// Leave-one-drop-out cross-validation of a fit.
struct BounceCrossValidation {
  std::size_t folds = 0;            ///< drops
  double rms_prediction_error = 0;  ///< [s]: sqrt(sum RSS_d / sum (n_d - 2)), each drop predicted without it
  double scatter = 0;               ///< the full fit's timing sigma [s]
  double ratio = 0;                 ///< rms_prediction_error / scatter
  std::string failure;              ///< why a fold could not be fitted (the values above then unset), else empty
};

/// The result of one fit.
struct BounceFit {
  std::string law;
  std::vector<FittedParameter> parameters;          ///< the law's
  std::vector<std::vector<double>> correlation;     ///< of the law's parameters
  std::vector<BounceDropFit> drops;                 ///< the nuisances, per drop
  std::vector<BouncePoint> points;                  ///< every usable time, drop by drop
  std::size_t times = 0;                            ///< n
  std::size_t fitted = 0;                           ///< p: the law's parameters and two per drop
  double sigma = 0;                                 ///< timing sigma [s], s = sqrt(RSS / (n - p))
  double chi_square = 0;                            ///< RSS [s^2]
  double reduced_chi_square = 0;                    ///< NaN: sigma is estimated (1 by construction)
  double aic = 0, bic = 0;
  double e_min = 0, e_max = 0;   ///< the fitted model's e (rebound over approach) over the data's impacts
  bool identifiable = false;     ///< not failed, every standard error finite, no law correlation beyond 0.999
  int iterations = 0, model_runs = 0;
  std::string stop_reason;
  bool converged = false, failed = false;
  std::string failure;
  std::string integrator_used;
  std::vector<std::string> left_out;  ///< compare: options given or fitted that this law does not read
  std::optional<BounceCrossValidation> cross_validation;
  RunOptions fitted_options;          ///< the run options at the estimate (without a drop's speed)
  const FittedParameter& parameter(const std::string& name) const;
};

/// Fit the checked recording (`path`: for messages). Validates the options
/// (check_bounce_fit_options, resolve_setup); throws DataError for fewer times than parameters.
/// `start`, if given, replaces the starting values: the law's parameters, then v0 and t0 of each
/// drop (the cross-validation's folds).
BounceFit fit_bounce_recording(const CheckedRecording& data, const std::string& path, const RunOptions& base,
                               const PaperParameters& paper, const BounceFitSettings& settings,
                               const std::optional<std::vector<double>>& start = std::nullopt);

/// Leave-one-drop-out cross-validation of `fit` (fit_bounce_recording's result for the same data,
/// options and settings). Throws DataError for fewer than two drops.
BounceCrossValidation cross_validate_bounces(const CheckedRecording& data, const std::string& path,
                                             const RunOptions& base, const PaperParameters& paper,
                                             const BounceFitSettings& settings, const BounceFit& fit);

/// Every registered law fitted, as compare_laws_on_restitution: failed fits last, then by AIC.
struct BounceLawComparison {
  std::vector<BounceFit> fits;
  std::vector<std::pair<std::string, std::string>> failures;  ///< law, why
};
BounceLawComparison compare_laws_on_bounces(const CheckedRecording& data, const std::string& path,
                                            const RunOptions& base, const PaperParameters& paper,
                                            const BounceFitSettings& settings);

}  // namespace hertzdash
