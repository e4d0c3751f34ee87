#pragma once
// Identifying parameters of the drop test from a measured trace (data/measurements/README.md):
// weighted nonlinear least squares, GSL's multifit_nlinear (trust region, Levenberg-Marquardt).
//
// Model. The run options (simulation/options/run_options.hpp) with the fitted ones replaced; the drop
// starts at contact onset with the approach speed sqrt(2 g h) (or --impact-velocity), and is
// integrated by RK4 with located events at a fixed step t_H / steps_per_contact, t_H the
// undamped Hertz contact time at the initial parameters (fixed during the fit, so the model
// is a smooth function of the parameters; RK4's error is O((1/2000)^4), the linear
// interpolation between steps O((pi/2000)^2/8) = 3e-7 of the peak). The instruments read
// ImpactHistory::instruments_at(t - t0): t0, the onset time on the trace's clock, is a nuisance
// parameter fitted with the others.
//
// Residuals. r_ci = (y_c(t_i) - model_c(t_i - t0)) / sigma_c for every channel c and every
// sample with a value. sigma_c is the channel's noise estimated from the data alone,
//   sigma_c = 1.4826 median|D2 y - median D2 y| / sqrt(6),  D2 y_i = y_{i+1} - 2 y_i + y_{i-1},
// (a white noise of variance s^2 gives D2 y a variance 6 s^2; the median absolute deviation is
// robust to the few second differences the contact's curvature dominates), at least 1e-6 of the
// channel's largest magnitude (a 20-bit recorder: a noise-free virtual experiment gets finite
// weights), so the weights do not depend on the model and every law of --compare-laws is fitted
// with the same ones.
//
// Uncertainty. Parameters are fitted in unbounded variables (log(p - lower), or the logit of
// (p - lower)/(upper - lower) between two finite bounds; t0 / t_H for the onset). The
// covariance is s^2 (J^T J)^{-1} with s^2 = chi^2 / (n - p) (gsl_multifit_nlinear_covar), mapped
// to the physical parameters by the transforms' derivatives. The Jacobian is by central
// differences with step 1e-6 in the unbounded variables: on its fixed grid the model is smooth
// in the parameters, except at samples near the contact's ends, where the paper's dashpot force
// rises as sqrt(tau) and the differences err; a larger step lets more samples spoil the
// Jacobian (at step 1e-4 the exactly degenerate pair ball-E, ball-radius, which enter only
// through K, shows a condition number of 3e4, at 1e-6 about 1.5e6: its columns agree to ~1e-6).
// The condition number is that of J with columns scaled to relative changes (d r / d ln p;
// d r / d(t0 / t_H)). The fit is identifiable when that is below 1e6, no two estimates correlate
// beyond 0.999 (a degenerate pair among other parameters can hide under the condition limit, the
// Jacobian being only that accurate) and every standard error is finite: a parameter the trace
// does not see at all (a zero column of J) has an infinite one.
//
// Outside the model's domain (values the set-up rejects, or a contact over 50 times longer
// than at the start) a step is rejected. The onset starts where the trace's contact first
// departs from free fall (force or acceleration, ten noise levels) less where the model's does,
// so a trace need not start near its onset.
//
// Work. Each model run costs its RK4 steps plus one interpolation per observation; the fit's
// work, summed over its runs, is bounded by TraceFitSettings::max_work. A trace whose first
// iterations alone would exceed it (a predicted cost: (2p + 2) runs per iteration, each at the
// starting values' cost, for min_predicted_iterations) is refused before any iteration; a fit
// that reaches the bound stops there and has failed.
//
// Failure. A fit that determined nothing is `failed`, with the reason: a fitted parameter at a
// bound (the trace pushed it out of the model's range: a wrong unit, another law, the wrong
// rod), a non-finite standard error or correlation, or a stop at the iteration or work limit.
// A failed fit is never identifiable.
//
// Profile intervals (TraceFitSettings::profile_intervals, `--profile-intervals`): for each fitted
// parameter (not the onset), the values where chi^2, the other parameters and the onset re-fitted
// (a fit_trace per point, from the estimate), rises by s^2 = chi^2 / (n - p) above its minimum
// (profile_interval.hpp). Not for a failed fit.
//
// Information criteria with the noise known (sigma_c): AIC = chi^2 + 2k, BIC = chi^2 + k ln n,
// k the number of fitted parameters including t0.
#include "hertzdash/io/measured_trace.hpp"
#include "hertzdash/simulation/fit/profile_interval.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"

#include <limits>
#include <optional>
#include <string>
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

/// How to fit.
struct TraceFitSettings {
  std::vector<FitParameter> parameters = parse_fit_parameters("ball-E,restitution");
  std::vector<std::string> channels;   ///< of the trace's; empty: all the trace has
  double resample_Hz = 0;              ///< > 0: average the trace into bins of 1/resample_Hz first
  int steps_per_contact = 2000;        ///< the model's RK4 steps per undamped Hertz contact time
  int max_iterations = 200;
  /// Most work of one fit: RK4 steps plus observations interpolated, summed over model runs
  /// (a good fit of a 1 MHz trace of the paper's contact takes about 7e5; "Work" above).
  double max_work = 3e7;
  /// Each fitted parameter's profile-likelihood interval too ("Profile intervals" above).
  bool profile_intervals = false;
};

/// One fitted parameter. The onset time is the last, named "onset-time" [s].
struct FittedParameter {
  std::string name;
  double initial = 0, estimate = 0, standard_error = 0;
  double lower = 0, upper = 0;
  bool at_bound = false;  ///< at a bound (within 1e-3 of the range): the standard error does not hold
  std::optional<ProfileInterval> profile = std::nullopt;  ///< the profile-likelihood interval, where asked for (profile_interval.hpp)
};

/// One channel: its weight and how well the model explains it.
struct ChannelFit {
  std::string name;            ///< e.g. force_N
  std::size_t samples = 0;     ///< with a value
  double noise_sigma = 0;      ///< sigma_c, estimated from the data [the channel's unit]
  double residual_rms = 0;     ///< RMS of y - model [the channel's unit]
  std::vector<double> t_s, measured, model;  ///< at the samples used (for curves and figures)
};

/// The result of one fit.
struct TraceFit {
  std::string law;
  std::vector<FittedParameter> parameters;           ///< the fitted ones, then onset-time
  std::vector<std::vector<double>> correlation;      ///< of the estimates, same order
  std::vector<ChannelFit> channels;
  std::size_t samples = 0;                           ///< residuals n
  double chi_square = 0;                             ///< sum r^2
  double reduced_chi_square = 0;                     ///< chi^2 / (n - p): about 1 if the model explains the trace to its noise
  double condition_number = 0;
  bool identifiable = false;                         ///< condition number, correlations and standard errors within limits
  double aic = 0, bic = 0;
  int iterations = 0, model_runs = 0;
  std::string stop_reason;                           ///< GSL's: small step, small gradient, or why not converged
  bool converged = false;                            ///< GSL's test met (not the iteration limit, not stalled)
  bool failed = false;                               ///< the fit determined nothing ("Failure" above)
  std::string failure;                               ///< why it failed, empty if not
  double work = 0;                                   ///< RK4 steps plus observations interpolated, all runs
  double contact_time_s = 0;                         ///< of the fitted model
  ImpactSummary model_summary;                       ///< the fitted model's impact (its diagnostics)
  RunOptions fitted_options;                         ///< the run options at the estimate
  /// compare_laws only: the options given for the comparison that this law does not read (the
  /// input e for the undamped law, another law's own input), left out of its fit.
  std::vector<std::string> left_out;

  /// The fitted parameter called `name` (an option's name or "onset-time"); std::out_of_range if none.
  const FittedParameter& parameter(const std::string& name) const;
  SolverSettings model_solver;                       ///< how the model was integrated (RK4, t_H / steps_per_contact)
};

/// Largest condition number of an identifiable fit.
inline constexpr double identifiable_condition_limit = 1e6;
/// Largest correlation between two estimates of an identifiable fit.
inline constexpr double identifiable_correlation_limit = 0.999;

/// Fewest samples per contact the fit accepts (the sampling check).
inline constexpr double min_samples_per_contact = 10;
/// Most samples per contact the fit accepts: the model is integrated at t_H / 2000 and
/// interpolated linearly between its steps, so finer samples add work and no information; a
/// sampling this fine is a time column in the wrong unit, or is to be averaged (--resample).
inline constexpr double max_samples_per_contact = 1e6;
/// Iterations a fit's predicted work must allow (the work check before the first iteration).
inline constexpr double min_predicted_iterations = 5;
/// A sample whose second difference exceeds this multiple of the channel's largest magnitude
/// elsewhere is an outlier (trace_preparation.hpp): a contact sampled at ten or more samples has
/// second differences below (pi / 10)^2 = 0.1 of its peak, noise below a few of its sigma.
inline constexpr double outlier_ratio = 10;

/// Fit `settings.parameters` and the onset time to the trace, starting from the values of
/// `base` (or the paper's where `base` leaves an option unset). Validates like `simulate`
/// (InvalidParameter). The trace is resampled if asked, then checked: a channel to fit, a
/// sampling interval that resolves the model's contact at the starting values
/// (min_samples_per_contact samples; the message says the least rate), a contact the noise does
/// not hide (ten noise levels in some channel), no channel that never changes, no outlier
/// (outlier_ratio), at most max_samples_per_contact, a predicted work within
/// settings.max_work; a trace unfit for fitting throws DataError naming the file. A fit that
/// ran and determined nothing is returned with `failed` set.
TraceFit fit_trace(const MeasuredTrace& trace, const RunOptions& base, const PaperParameters& paper,
                   const TraceFitSettings& settings);

/// fit_trace for every registered law (base.damping replaced), ranked by AIC; a law that
/// cannot be fitted (its options reject the set-up, its model or the fit fails) is left out and
/// named in `failures`. A trace unfit for fitting throws DataError as fit_trace does.
struct LawComparison {
  std::vector<TraceFit> fits;                                 ///< best (lowest AIC) first
  std::vector<std::pair<std::string, std::string>> failures;  ///< law, why
};
LawComparison compare_laws(const MeasuredTrace& trace, const RunOptions& base, const PaperParameters& paper,
                           const TraceFitSettings& settings);

}  // namespace hertzdash
