#pragma once
// One fit engine for every kind of data (a measured trace, a restitution table, a bounce
// recording): weighted nonlinear least squares by GSL's multifit_nlinear (trust region,
// Levenberg-Marquardt), its covariance, identifiability, Wald and profile-likelihood intervals,
// cross-validation and law comparison by AIC and BIC, and one result (FitResult: a common core
// and a per-point table). A kind of data is a FitData: its prepared data, its nuisance
// parameters, its residuals from a run of the model, and its folds (docs/fit.md).
//
// Variables. z = (the law's fitted parameters, each in an unbounded variable: log(p - lower), or
// the logit of (p - lower) / (upper - lower) between two finite bounds (Transform); then the
// kind's nuisances, each in its own variable (linear with a scale, or log)). The Jacobian is by
// central differences, step 1e-6 in every z; a model that keeps its last runs (every kind's
// does) makes a nuisance's column cheap.
//
// Residuals r_i = (y_i - model_i) / sd_i, sd_i the row's `unit` (the data's scatter where the
// kind knows it: a trace's channel noise, a table's e_sd; else 1 with one common sigma
// estimated). Outside the model's domain every residual is `outside_residual`: the trust region
// rejects the step and shrinks.
//
// Covariance s^2 (J^T J)^-1 with s^2 = chi^2 / (n - p) (gsl_multifit_nlinear_covar), with sd
// known at least 1 (the stated scatter is inflated where the model does not explain the data to
// it, never deflated: the Particle Data Group's scale factor), with sigma estimated at least the
// kind's least_variance; mapped to
// the parameters by the transforms' derivatives; a column of J no larger than the central
// difference's rounding noise (about 1e3 eps (|y / sd| + |r|) / h: the data do not see that
// variable), or a variance GSL's pivoting sets to zero, is an infinite standard error. Condition number: of J with the law's
// columns scaled to relative changes (d r / d ln p) and the nuisances' to their variables.
// Identifiable: not failed, condition number below identifiable_condition_limit, no
// correlation beyond identifiable_correlation_limit, every standard error finite, every law
// parameter's below identifiable_relative_error_limit times its estimate.
//
// Criteria, k = p (every variable, nuisances included: each law of a comparison has the same
// ones). sd known: chi^2 = sum r^2, AIC = chi^2 + 2k, BIC = chi^2 + k ln n, reduced chi-square
// chi^2 / (n - p). sd unknown (one common sigma, fitted too): AIC = n ln(RSS / n) + 2 (k + 1),
// BIC = n ln(RSS / n) + (k + 1) ln n, RSS / n at least the kind's least_variance (the model's
// accuracy: a noise-free synthetic data set otherwise gives ln 0); sigma = s, the reduced
// chi-square NaN (1 by construction).
//
// Nested fits: with two or more law parameters and a fit in doubt (not converged, or its condition
// number at or above identifiable_condition_limit), each law parameter is held at its start in
// turn and the rest fitted; a lower chi-square there means the full fit stopped short, and it is
// restarted from that point (a fit with more parameters is never worse than one with fewer;
// `stop_reason` says so).
//
// Failure: a fit that determined nothing is `failed`, with the reason: a law parameter at a bound
// (within 1e-3 of the range in its variable), no law parameter with a finite standard error, the
// iteration or work limit, a model that cannot be evaluated at the estimate.
//
// Profile intervals (FitSettings::profile_intervals): for each law parameter, the values where
// chi^2, every other variable re-fitted from the estimate, rises by s^2 above its minimum
// (profile_interval.hpp: Bates and Watts 1988, Venzon and Moolgavkar 1988).
//
// Cross-validation (FitSettings::cross_validate): each of the kind's folds in turn is left out;
// the rest is fitted (from the estimate), then the left-out part predicted with the law's
// parameters fixed there and only its own nuisances fitted. The prediction error's RMS is
// sqrt(sum e^2 / sum (n_k - q_k)), n_k the left-out rows and q_k their nuisances, e_i = r_i sd_i
// in the data's unit where the rows share one (a table's e, a recording's times), else
// (FitData::mixed_units: a trace's channels in N, m/s^2, m) the standardized r_i, dimensionless;
// the data's own scatter is then 1, else the RMS of sd_i where known, else the fit's sigma; a
// ratio about 1 for a law that predicts new data as well as the data allow.
//
// Work (issue 45). A kind predicts the work of one fit from its size (FitData::predicted_work,
// in units of about 1 us on one core of the development machine); a request (a fit, its
// cross-validation's folds, its profiles; every law of a comparison) predicted above
// max_predicted_fit_work (about a minute) is refused before it starts (DataError), one above
// progress_fit_work reports its progress (FitSettings::progress: each iteration, fold and law),
// and a front end stops a fit by setting FitSettings::cancel (FitCancelled at the next model
// evaluation: Python's Ctrl-C).
#include "hertzdash/simulation/fit/profile_interval.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"

#include <atomic>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <exception>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hertzdash {

/// A parameter to fit: a numeric set-up option by name (--fit NAME[:LOWER:UPPER]) and its bounds [SI].
struct FitParameter {
  std::string option;  ///< the option's name, e.g. "ball-E"
  double lower = 0, upper = std::numeric_limits<double>::infinity();
};

/// The parameters of a --fit list, "ball-E,restitution" or "ball-E:1e9:3e9,restitution"; each
/// without bounds gets the bounds of the option's declared range (docs/parameters.md). Throws
/// InvalidParameter("fit", ...).
std::vector<FitParameter> parse_fit_parameters(const std::string& list);

/// The options that may be fitted, comma-separated (for help and messages).
std::string fittable_option_names();

/// The law's own parameters, fitted by default to a table or a recording: `restitution`, or
/// `viscous-time-constant` for a law with a material time constant; empty for a law that reads neither.
std::vector<FitParameter> law_fit_parameters(const RunOptions& base);

/// A parameter in [lo, hi] as an unbounded variable z: the logit of (p - lo) / (hi - lo) between
/// two finite bounds, log(p - lo) with hi infinite.
struct Transform {
  double lo, hi;
  bool two_sided() const { return std::isfinite(hi); }
  double p(double z) const { return two_sided() ? lo + (hi - lo) / (1.0 + std::exp(-z)) : lo + std::exp(z); }
  double z(double p) const { return two_sided() ? std::log((p - lo) / (hi - p)) : std::log(p - lo); }
  double dp_dz(double z) const {
    if (!two_sided()) return std::exp(z);
    const double s = 1.0 / (1.0 + std::exp(-z));
    return (hi - lo) * s * (1.0 - s);
  }
};

/// One fitted parameter (a law's, or a nuisance).
struct FittedParameter {
  std::string name;
  double initial = 0, estimate = 0, standard_error = 0;
  double lower = 0, upper = 0;
  bool at_bound = false;  ///< at a bound (within 1e-3 of the range): the standard error does not hold
  std::optional<ProfileInterval> profile = std::nullopt;  ///< the profile-likelihood interval, where asked for
};

/// A nuisance parameter of a kind: its name, starting value and variable (z = value / scale, or
/// ln value), and the group of rows it belongs to (none: every row's, reported among the
/// fit's parameters, e.g. a trace's onset time).
struct Nuisance {
  std::string name;
  double start = 0;  ///< reported as the initial value
  bool log = false;
  double scale = 1;
  std::optional<std::size_t> group = std::nullopt;
  std::optional<double> z_start = std::nullopt;  ///< the variable to start from, if not variable(start) (a trace's scanned onset)
  double value(double z) const { return log ? std::exp(z) : scale * z; }
  double variable(double v) const { return log ? std::log(v) : v / scale; }
  double dvalue_dz(double z) const { return log ? std::exp(z) : scale; }
};

/// One row of the data and the fitted model there.
struct FitPoint {
  std::optional<std::size_t> group;  ///< the row's group (a trace's channel, a recording's drop)
  std::size_t index = 0;             ///< in its group, in file order
  int number = 0;                    ///< a recording's impact number from the drop's first
  double x = 0;                      ///< the abscissa: time [s] (trace), impact speed [m/s] (table; recording: the model's), incident angle [deg] (rebound angles)
  double measured = 0, model = 0, residual = 0;  ///< residual = measured - model, in the data's unit
  double unit = 1;                   ///< sd_i of the residual r_i = residual / unit
};

/// A group of rows: a trace's channel, a recording's drop.
struct FitGroup {
  std::string label;
  std::size_t rows = 0;
  double unit = 1;                         ///< the rows' sd (a channel's noise sigma)
  double residual_rms = 0;                 ///< of measured - model
  std::vector<FittedParameter> nuisances;  ///< its own (a drop's first impact speed and clock offset)
};

/// The cross-validation of a fit (the header's "Cross-validation").
struct CrossValidation {
  std::size_t folds = 0;
  double rms_prediction_error = 0;  ///< in the data's unit; of the standardized r_i with mixed units
  double scatter = 0;               ///< RMS of sd_i, or the fit's sigma; 1 with mixed units
  double ratio = 0;                 ///< rms_prediction_error / scatter
  std::string failure;              ///< why a fold could not be fitted (the values above then unset), else empty
};

/// The fitted model's e at one impact of the data.
struct ImpactRestitution {
  std::size_t row = 0;          ///< the data's row of the impact (a table's, a recording's; a trace's one: 0)
  double speed_mps = 0;         ///< the impact's approach speed (the model's)
  double e = 0;                 ///< its effective restitution, rebound / approach speed
  double standard_error = NAN;  ///< its 1-sigma error, as the mean's below (set by the engine)
};

/// The physical e a fit reports first (issue 46): the fitted model's effective restitution over
/// the data's impacts (a table's rows, a recording's impacts, a trace's one), not the law's input
/// e. `value` is their mean; `standard_error` its 1-sigma error, sqrt(g^T C g) with g the gradient of the
/// mean over the law's variables (central differences, step effective_restitution_step) and C
/// their block of the fit's covariance (the impacts' speeds held at the estimate's); the range and
/// the speeds at its ends show a dependence on speed; each impact's e with its error draws the
/// fitted law and its band (a fit's figure). NaN where the kind has no impact or the model none
/// that separates.
struct EffectiveRestitution {
  double value = NAN, standard_error = NAN;
  double min = NAN, max = NAN;                      ///< over the impacts
  double speed_at_min_mps = NAN, speed_at_max_mps = NAN;
  std::vector<ImpactRestitution> impacts;           ///< those that separate, in the data's order
};

/// The step in the law's variables of effective restitution's gradient: the models' e are
/// accurate to about 1e-9, so the difference's rounding error is about 1e-5 relative, its
/// truncation error h^2 = 1e-8.
inline constexpr double effective_restitution_step = 1e-4;

/// The one result of every fit.
struct FitResult {
  std::string law;
  std::vector<FittedParameter> parameters;       ///< the law's, then the nuisances of every row (a trace's onset)
  std::vector<std::vector<double>> correlation;  ///< of `parameters`
  std::vector<FitGroup> groups;                  ///< with their own nuisances
  std::vector<FitPoint> points;                  ///< every row
  std::size_t n = 0, p = 0;                      ///< residuals; fitted variables
  bool sigma_estimated = false;                  ///< sd unknown: one common sigma fitted
  double sigma = 0;                              ///< that sigma s = sqrt(RSS / (n - p)); 0 with sd known
  double chi_square = 0;                         ///< sum r^2 (RSS with sd unknown)
  double reduced_chi_square = 0;                 ///< chi^2 / (n - p); NaN with sigma estimated
  double condition_number = 0;
  bool identifiable = false;
  double aic = 0, bic = 0;
  EffectiveRestitution e_effective;             ///< the fitted model's e over the data's impacts
  int iterations = 0, model_runs = 0;
  double work = 0;                               ///< the kind's work measure, all runs (a trace's RK4 steps and interpolations)
  std::string stop_reason;                       ///< GSL's: small step, small gradient, or why not converged
  bool converged = false, failed = false;
  std::string failure;                           ///< why it failed, empty if not
  std::string integrator_used;                   ///< the integrator of the model's runs
  SolverSettings model_solver;                   ///< how the model was integrated
  std::optional<ImpactSummary> model_impact;     ///< a trace's fitted impact (its diagnostics)
  RunOptions fitted_options;                     ///< the run options at the estimate
  std::vector<std::string> left_out;             ///< compare: options given or fitted that this law does not read
  std::optional<CrossValidation> cross_validation;

  /// The fitted parameter called `name`; std::out_of_range if none.
  const FittedParameter& parameter(const std::string& name) const;
};

/// Largest condition number of an identifiable fit.
inline constexpr double identifiable_condition_limit = 1e6;
/// Largest correlation between two estimates of an identifiable fit.
inline constexpr double identifiable_correlation_limit = 0.999;
/// Largest standard error of an identifiable fit's law parameter, relative to its estimate: an
/// estimate within one standard error of 0 is not determined.
inline constexpr double identifiable_relative_error_limit = 1.0;
/// A residual where the model cannot be evaluated.
inline constexpr double outside_residual = 1e30;

/// How to fit.
struct FitSettings {
  std::vector<FitParameter> parameters;  ///< empty: the law's own (law_fit_parameters)
  int max_iterations = 200;
  double max_work = std::numeric_limits<double>::infinity();  ///< the kind's work() bound
  bool profile_intervals = false;
  bool cross_validate = false;
  /// Set by a front end: once true, the fit stops at its next model evaluation (FitCancelled).
  const std::atomic<bool>* cancel = nullptr;
  /// Given a line of progress (an iteration, a fold, a law) on a request predicted above
  /// progress_fit_work; a front end shows it.
  std::function<void(const std::string&)> progress{};
};

/// The most predicted work of one request (a fit with its folds and profiles, or every law of a
/// comparison), in FitData::predicted_work's units: about a minute.
inline constexpr double max_predicted_fit_work = 6e7;
/// A request predicted above this (about 10 s) reports its progress.
inline constexpr double progress_fit_work = 1e7;

/// Thrown when FitSettings::cancel is set; no std::runtime_error, which the engine and the kinds
/// take for a model outside its domain.
struct FitCancelled : std::exception {
  const char* what() const noexcept override { return "the fit was cancelled"; }
};

/// One fit's predicted work and what it comes from.
struct FitWork {
  double units = 0;   ///< about 1 us each on one core of the development machine (0: not predicted)
  std::string size;   ///< "rec.csv: 2000 drops, 16000 times, 4001 parameters"
};

/// A kind of data, prepared for one law (its options and fitted parameters).
class FitData {
 public:
  virtual ~FitData() = default;
  /// Residual rows n.
  virtual std::size_t rows() const = 0;
  /// The row's description (group, index, number, x, measured, unit); model and residual unset.
  virtual FitPoint row(std::size_t i) const = 0;
  /// The labels of the groups rows belong to (none: no groups).
  virtual std::vector<std::string> groups() const { return {}; }
  virtual std::vector<Nuisance> nuisances() const { return {}; }
  /// The law's starting values for `parameters` (called only where no start is given).
  virtual std::vector<double> start(const std::vector<FitParameter>& parameters) = 0;
  /// r_i = (y_i - model_i) / sd_i at the law's values and the nuisances' values; false outside the model's domain.
  virtual bool residuals(const std::vector<double>& law, const std::vector<double>& nuisances, double* r) = 0;
  /// sd_i known (chi^2 criteria) or one common sigma estimated.
  virtual bool sd_known() const = 0;
  /// Rows in different units (a trace's channels): cross-validation scores the standardized r_i.
  virtual bool mixed_units() const { return false; }
  /// Least RSS / n with sigma estimated (the model's accuracy) [the data's unit squared].
  virtual double least_variance() const { return 0; }
  /// The work so far, bounded by FitSettings::max_work (a trace's RK4 steps and interpolations).
  virtual double work() const { return 0; }
  /// The predicted work of one fit of `law_parameters` of the law's parameters (see above).
  virtual FitWork predicted_work(std::size_t law_parameters) const { (void)law_parameters; return {}; }
  /// Why the model could not be evaluated the last time residuals() returned false (empty: no
  /// reason kept): the refusal of the starting values quotes it.
  virtual std::string outside_domain() const { return {}; }
  /// Why n values cannot determine p variables (a DataError's message).
  virtual std::string too_few(std::size_t n, std::size_t p) const = 0;
  /// The number of folds; throws DataError below two.
  virtual std::size_t folds() const = 0;
  /// Fold k as the messages name it ("speed 0.5 m/s", "drop 'a'").
  virtual std::string fold_name(std::size_t k) const = 0;
  /// The data without fold k (held false) or fold k alone (held true), its nuisances starting
  /// from `nuisances`, this data's nuisance values.
  virtual std::unique_ptr<FitData> part(std::size_t k, bool held, const std::vector<double>& nuisances) const = 0;
  /// The kind's outputs at the estimate: model runs, integrator, points' x where the model gives it, ...
  virtual void finish(FitResult& fit, const std::vector<double>& law, const std::vector<double>& nuisances) = 0;
  /// The model's e at each impact of the data (row, speed, e) at the law's values `law`, the
  /// nuisances at the values finish() was given (an impact that does not separate left out);
  /// empty outside the model's domain or for a kind without impacts. Called after finish().
  virtual std::vector<ImpactRestitution> restitution_at(const std::vector<double>& law) { (void)law; return {}; }
};

/// Fit `data` (the law's parameters settings.parameters, `start` their starting values or
/// data.start's); profile intervals and cross-validation as settings ask. Throws DataError for
/// n <= p, InvalidParameter("fit", ...) for starting values outside the model's domain.
FitResult fit(FitData& data, const std::string& law, const FitSettings& settings,
              const std::optional<std::vector<double>>& start = std::nullopt);

/// One law of a law comparison: the options with `damping` set to it and every given option it
/// does not read cleared, the fit's parameters it reads (empty: the law's own), both kinds named
/// in `left_out`; `refusal` says why it cannot be fitted (empty if it can).
struct LawTrial {
  RunOptions options;
  std::vector<FitParameter> parameters;
  std::vector<std::string> left_out;
  std::string refusal;
};
LawTrial law_trial(const RunOptions& base, std::string_view law, const std::vector<FitParameter>& parameters);

/// Every registered law fitted (base.damping replaced), failed fits last, then by AIC; a law
/// that cannot be fitted (nothing to fit, its options refuse the set-up, its fit throws) is
/// named in `failures`; a DataError (the data's fault, the same for every law) is rethrown.
struct LawComparison {
  std::vector<FitResult> fits;
  std::vector<std::pair<std::string, std::string>> failures;  ///< law, why
};
using FitDataMaker = std::function<std::unique_ptr<FitData>(const RunOptions&, const std::vector<FitParameter>&)>;
LawComparison compare_laws(const FitDataMaker& make, const RunOptions& base, const FitSettings& settings);

}  // namespace hertzdash
