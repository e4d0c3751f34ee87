#pragma once
// Identifying parameters of the drop test from a measured trace (data/measurements/README.md):
// weighted nonlinear least squares by the fit engine (fit_engine.hpp).
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
// Uncertainty. The engine's (fit_engine.hpp): the onset is a nuisance in the variable t0 / t_H,
// reported as the last parameter, `onset-time`; the covariance s^2 (J^T J)^{-1}. The Jacobian's
// central differences (step 1e-6) are accurate on the model's fixed grid, except at samples near
// the contact's ends, where the paper's dashpot force rises as sqrt(tau) and the differences err;
// a larger step lets more samples spoil the Jacobian (at step 1e-4 the exactly degenerate pair
// ball-E, ball-radius, which enter only through K, shows a condition number of 3e4, at 1e-6 about
// 1.5e6: its columns agree to ~1e-6), so the condition limit 1e6 finds it.
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
// Profile intervals (`--profile-intervals`): the engine's, for each fitted parameter but the
// onset, every other variable and the onset re-fitted from the estimate.
//
// Cross-validation (`--cross-validate`): the engine's, over trace_folds interleaved folds, sample
// i (all its channels) in fold i mod trace_folds; each left out in turn, the rest fitted, the
// left-out samples predicted with their own onset fitted. The prediction error is in the
// channels' units (with one channel, about its noise sigma for a model that explains the trace),
// the data's scatter the RMS of sigma_c over the residuals.
//
// Channels are the result's groups (FitResult::groups: name, samples, sigma_c as `unit`, the
// residual RMS), a point's x its time on the trace's clock [s].
//
// Information criteria with the noise known (sigma_c): AIC = chi^2 + 2k, BIC = chi^2 + k ln n,
// k the number of fitted parameters including t0.
#include "hertzdash/io/measured_trace.hpp"
#include "hertzdash/simulation/fit/fit_engine.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <string>
#include <vector>

namespace hertzdash {

/// How to fit a trace: the engine's settings (fitted by default: ball-E and restitution; at
/// most 3e7 of work, a good fit of a 1 MHz trace of the paper's contact taking about 7e5, "Work"
/// above) and the trace's own.
struct TraceFitSettings : FitSettings {
  std::vector<std::string> channels;   ///< of the trace's; empty: all the trace has
  double resample_Hz = 0;              ///< > 0: average the trace into bins of 1/resample_Hz first
  int steps_per_contact = 2000;        ///< the model's RK4 steps per undamped Hertz contact time
  TraceFitSettings() : FitSettings{parse_fit_parameters("ball-E,restitution"), 200, 3e7, false, false} {}
};

/// Folds of a trace's cross-validation (interleaved samples).
inline constexpr std::size_t trace_folds = 5;
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
/// ran and determined nothing is returned with `failed` set. The result has a group per channel,
/// the onset last among the parameters.
FitResult fit_trace(const MeasuredTrace& trace, const RunOptions& base, const PaperParameters& paper,
                   const TraceFitSettings& settings);

/// fit_trace for every registered law (fit_engine.hpp's compare_laws). A trace unfit for
/// fitting throws DataError as fit_trace does.
LawComparison compare_laws(const MeasuredTrace& trace, const RunOptions& base, const PaperParameters& paper,
                           const TraceFitSettings& settings);

}  // namespace hertzdash
