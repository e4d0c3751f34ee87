#pragma once
// Fitting a damping law's own parameters to a restitution table (io/restitution_table.hpp;
// data/measurements/README.md, "Restitution tables"): weighted nonlinear least squares of e
// against the impact speed, GSL's multifit_nlinear (trust region, Levenberg-Marquardt), as the
// trace fit (trace_fit.hpp) but with one model value per row.
//
// Model. At each distinct speed v of the table, the law's effective restitution of one impact
// at approach speed v in the contact in which `hertzdash restitution` defines it
// (calibrate_restitution.hpp: the set-up's bodies against a rigid flat, or against `rod-E` if
// given, gravity off): the run options with --impact-velocity v and the fitted parameters
// replaced, through resolve_setup and ImpactSimulator. The impacts run by gbs8 in the
// regularising variables at rtol = atol = 1e-12 (the integrator table's fall-back where a law
// cannot), so a model value is accurate to about 1e-10 and a smooth function of the parameters
// at the scale of the Jacobian's differences (central, step 1e-6 in the unbounded variables:
// an error of ~1e-10 / 1e-6 = 1e-4 of a derivative of order 1 at worst).
//
// Parameters. By default the law's own: the input e (`restitution`) for the laws that read it,
// the material time constant (`viscous-time-constant`) for a law that has one (kuwabara-kono:
// with A fixed its e falls with the speed; calibrated from e at each run's own speed it would
// not); a law with neither (the undamped `none`) has nothing to fit. Any fittable option by
// RestitutionFitSettings::parameters instead (`--fit`). Starting values: the option given, else
// for `restitution` the table's mean e, for `viscous-time-constant` the A whose e at the table's
// median speed is the table's mean e (the law's calibration), else the set-up's value
// (fit_parameters.hpp). Bounded parameters are fitted in unbounded variables (Transform).
//
// Residuals and uncertainty. r_i = (e_i - e_model(v_i)) / sd_i with sd_i the row's e_sd; a table
// without e_sd has one common, unknown sigma: sd_i = 1, and sigma^2 is estimated by
// s^2 = RSS / (n - p). The covariance is s^2 (J^T J)^-1 in both cases, s^2 = chi^2 / (n - p)
// (as the trace fit's), mapped to the parameters by the transforms' derivatives.
//
// Criteria. With e_sd: chi^2 = sum r_i^2, reduced chi-square chi^2 / (n - p) (about 1 if the law
// explains the table to its scatter), AIC = chi^2 + 2k, BIC = chi^2 + k ln n (k the fitted
// parameters). Without: the Gaussian likelihood with sigma fitted too, AIC = n ln(RSS / n) +
// 2 (k + 1), BIC = n ln(RSS / n) + (k + 1) ln n, RSS / n at least (1e-9)^2 (the model's accuracy:
// a noise-free synthetic table otherwise gives ln 0); the reduced chi-square is 1 by
// construction and not reported.
//
// Profile intervals (RestitutionFitSettings::profile_intervals, `--profile-intervals`): for each
// fitted parameter, the values where the profile of chi^2 (the other parameters re-fitted, from
// the estimate) rises by s^2 = chi^2 / (n - p) above its minimum (profile_interval.hpp: the rule,
// Bates and Watts 1988, Venzon and Moolgavkar 1988). With one parameter the profile is chi^2
// itself, one model evaluation per point; with more, a re-fit per point. Not for a failed fit.
//
// Cross-validation. Each distinct speed in turn is left out, the rest fitted (from the full fit's
// estimate) and the left-out rows predicted; the RMS of the prediction errors over all rows,
// and its ratio to the data's own scatter: the RMS of e_sd, or the fit's sigma s without it.
#include "hertzdash/io/restitution_table.hpp"
#include "hertzdash/simulation/fit/trace_fit.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hertzdash {

/// How to fit a restitution table.
struct RestitutionFitSettings {
  /// Empty: the law's own (default_restitution_fit_parameters).
  std::vector<FitParameter> parameters;
  int max_iterations = 200;
  bool cross_validate = false;
  bool profile_intervals = false;  ///< each parameter's profile-likelihood interval too ("Profile intervals")
};

/// The parameters fitted by default for the run's law: `restitution`, or `viscous-time-constant`
/// for a law with a material time constant; empty for a law that reads neither.
std::vector<FitParameter> default_restitution_fit_parameters(const RunOptions& base);

/// One law of a law comparison (`--compare-laws` of a table or a recording): the options with
/// `damping` set to it and every given option it does not read cleared, the fit's parameters it
/// reads, both kinds named in `left_out`; `refusal` says why it cannot be fitted (empty if it can).
struct LawTrial {
  RunOptions options;
  std::vector<FitParameter> parameters;  ///< empty: the law's own
  std::vector<std::string> left_out;
  std::string refusal;
};
LawTrial law_trial(const RunOptions& base, std::string_view law, const std::vector<FitParameter>& parameters);

/// Refuses (InvalidParameter) the options a restitution-table fit cannot use: an elastic rod,
/// `impact-velocity` or `height` (the table gives the speeds), `gravity`, `rod-nu` without
/// `rod-E`, an iterated omega_n.
void check_restitution_fit_options(const RunOptions& o);

/// One row of the table and the fitted model there.
struct RestitutionPoint {
  double impact_speed_mps = 0, measured = 0, model = 0, residual = 0;  ///< residual = measured - model
};

/// Leave-one-speed-out cross-validation of a fit.
struct RestitutionCrossValidation {
  std::size_t folds = 0;              ///< distinct speeds
  double rms_prediction_error = 0;    ///< RMS of e - predicted e over every row, each predicted without its speed
  double scatter = 0;                 ///< the data's own: RMS of e_sd, or the fit's sigma
  double ratio = 0;                   ///< rms_prediction_error / scatter
  std::string failure;                ///< why a fold could not be fitted (the values above then unset), else empty
};

/// The result of one fit.
struct RestitutionFit {
  std::string law;
  std::vector<FittedParameter> parameters;
  std::vector<std::vector<double>> correlation;
  std::vector<RestitutionPoint> points;  ///< the table's rows, in its order
  std::size_t rows = 0;
  bool sigma_estimated = false;          ///< the table has no e_sd: one common sigma, fitted
  double sigma = 0;                      ///< that sigma, s = sqrt(RSS / (n - p)); with e_sd, 0
  double chi_square = 0;                 ///< sum of squared weighted residuals (RSS without e_sd)
  double reduced_chi_square = 0;         ///< chi^2 / (n - p) with e_sd; NaN without
  double aic = 0, bic = 0;
  double e_min = 0, e_max = 0;           ///< the fitted model's e over the table's speeds
  bool identifiable = false;             ///< not failed, every standard error finite, no correlation beyond 0.999
  int iterations = 0, model_runs = 0;
  std::string stop_reason;
  bool converged = false, failed = false;
  std::string failure;
  std::string integrator_used;           ///< the integrator the model's impacts ran with
  std::vector<std::string> left_out;     ///< compare: options given or fitted that this law does not read
  std::optional<RestitutionCrossValidation> cross_validation;
  RunOptions fitted_options;             ///< the run options at the estimate
  const FittedParameter& parameter(const std::string& name) const;
};

/// Fit the table. Validates the options like `restitution` (InvalidParameter: the rod model
/// rigid, no `impact-velocity` or `height` (the table gives the speeds), no `gravity`, a
/// closed-form omega_n variant); throws DataError for a table with no more rows than parameters.
/// `start`, if given, replaces the starting values (the cross-validation's folds).
RestitutionFit fit_restitution_table(const RestitutionTable& table, const RunOptions& base, const PaperParameters& paper,
                                     const RestitutionFitSettings& settings,
                                     const std::optional<std::vector<double>>& start = std::nullopt);

/// Leave-one-speed-out cross-validation of `fit` (fit_restitution_table's result for the same
/// table, options and settings). Throws DataError for a table of fewer than two distinct speeds.
RestitutionCrossValidation cross_validate_restitution(const RestitutionTable& table, const RunOptions& base,
                                                      const PaperParameters& paper,
                                                      const RestitutionFitSettings& settings, const RestitutionFit& fit);

/// Every registered law fitted (base.damping replaced; each with its own default parameters, or
/// settings.parameters less those it does not read), failed fits last, then by AIC; a law that
/// cannot be fitted (nothing to fit, its options refuse the set-up) is named in `failures`.
struct RestitutionLawComparison {
  std::vector<RestitutionFit> fits;
  std::vector<std::pair<std::string, std::string>> failures;  ///< law, why
};
RestitutionLawComparison compare_laws_on_restitution(const RestitutionTable& table, const RunOptions& base,
                                                     const PaperParameters& paper,
                                                     const RestitutionFitSettings& settings);

}  // namespace hertzdash
