#pragma once
// What a fit means, in one line and first (issue 46): the default body a fit ran against, a
// ranking whose ties share a rank, and the verdict: whether the data show e depending on speed
// (by AIC and cross-validation between the laws whose e is constant over the data's speeds and
// those whose e varies), whether air drag matters against e's error (recordings), whether the
// fit is poor against the data's stated precision. docs/fit.md ("What a fit says first").
#include "hertzdash/simulation/reports/fit_report.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace hertzdash {

/// Fits whose AIC differ by less than this share a rank: a likelihood ratio of exp(0.005), no
/// difference at all (laws that make the same e differ by the model's accuracy).
inline constexpr double aic_rank_tie = 0.01;
/// AIC differences below 2 do not prefer one model over another (Burnham and Anderson 2002).
inline constexpr double aic_preference = 2.0;
/// A law's e is constant over the data's speeds when its range there is below this: about what a
/// drop test resolves at best, while the laws of constant e vary by 1e-5 to 1e-4 with the
/// gravity in the contact and the body's speed.
inline constexpr double constant_e_span = 1e-3;
bool constant_e(const EffectiveRestitution& e);
/// A poor fit (sd known): its reduced chi-square above 2 and the probability of a chi-square as
/// large from the stated scatter alone below 1e-3.
inline constexpr double poor_fit_reduced_chi_square = 2.0;
inline constexpr double poor_fit_probability = 1e-3;

/// The rank of each fit of a comparison (best first, as run_fit orders them): 1, 1, 3 where the
/// first two's AIC differ by less than aic_rank_tie; failed fits after every other.
std::vector<std::size_t> aic_ranks(const std::vector<FitResult>& fits);

/// Cross-validated prediction errors within this relative difference of the first of a group
/// share its cv_rank: laws that make the same e predict to within about 1e-4 of each other, and a
/// prediction error is itself uncertain by far more.
inline constexpr double cv_rank_tie = 1e-3;

/// The rank of each fit by its cross-validated prediction error, ties as above (1, 1, 3); 0 for
/// a fit not cross-validated, or whose cross-validation failed.
std::vector<std::size_t> cv_ranks(const std::vector<FitResult>& fits);

/// Whether the user gave fit `f` a body of their own: a mass, modulus, Poisson ratio or radius
/// set in its options that it did not estimate.
bool own_body(const FitResult& f);

/// Whether fit `f` is poor against the data's stated precision (see above).
bool poor_fit(const FitResult& f);

/// "the paper's steel rod (0.778 kg) on its nylon hemisphere: no --mass, --ball-* or --rod-E
/// given (docs/balls.md)" for a table or recording fitted without a body of the user's own;
/// empty otherwise (a trace names its rod).
std::string default_body_notice(const FitRun& run, const PaperParameters& paper);

/// The verdict, one line: its clauses joined by "; " (speed dependence, drag, fit quality).
std::string fit_verdict(const FitRun& run, const PaperParameters& paper);

/// Warnings of likely unit mistakes (drop_height_units): a drop whose fitted first impact speed
/// falls from a height (with the run's drag) more than twice or less than half its
/// drop_height_m; the hint names the column and the factor (a height in cm or mm written as m),
/// or impact_time_ms where the fall is far too long (times in ms: a million times the height).
std::vector<RunDiagnostic> unit_diagnostics(const FitRun& run, const PaperParameters& paper);

}  // namespace hertzdash
