#pragma once
// Variance-based sensitivity: first-order and total Sobol indices from the Saltelli design,
// with bootstrap confidence intervals.
//
// For y = f(X), X with d independent inputs, V = Var(y):
//   first order  S_i  = V_i / V,   V_i  = Var(E[y | X_i])        (the share of X_i alone)
//   total        ST_i = VT_i / V,  VT_i = E[Var(y | X_~i)]      (X_i with all its interactions)
// so 0 <= S_i <= ST_i, sum S_i <= 1 <= sum ST_i, and S_i = ST_i for an additive f.
//
// The design (Saltelli et al. 2010, sec. 3): two independent N x d samples A and B of the inputs
// and, for each i, A_B^(i): A with its column i taken from B. The model runs N (d + 2) times on
// the rows of
//   [ A ; B ; A_B^(1) ; ... ; A_B^(d) ]          (block k holds rows k N .. (k + 1) N - 1)
// and f lists the outputs in that order. In the unit cube, one design of 2d columns (a Sobol
// sequence: sample_design.hpp) gives A (columns 0 .. d-1) and B (columns d .. 2d-1); each
// input's quantile function maps them to its distribution (input_distribution.hpp).
//
// The estimators, with f_A = f(A), f_B = f(B), f_i = f(A_B^(i)) and means over the N rows j:
//   V_i  = mean_j (f_B,j - m) (f_i,j - f_A,j)      Saltelli et al. 2010, Table 2 (b)
//   VT_i = mean_j (f_A,j - f_i,j)^2 / 2            Jansen 1999; Saltelli et al. 2010, Table 2 (f)
//   V    = the sample variance of the 2N values [f_A, f_B]  (divided by 2N - 1), m their mean.
// Centring f_B by m leaves V_i's expectation unchanged (E[f_i - f_A] = 0: A_B^(i) and A are
// equally distributed) but removes a variance ~ m^2 Var(f_i - f_A) / N that dominates when
// the mean is large against the spread (Sobol 2001: e_effective ~ 0.83 +- 0.004 would give
// intervals wider than [-10, 10]); VT_i needs no centring. Both are consistent; their error
// falls as N^{-1/2} (Monte Carlo) and faster for a Sobol design when f is smooth. Neither is bounded to [0, 1]: an input without effect
// gets S_i scattered around 0, possibly negative; that is the estimate, not clipped.
//
// Confidence intervals: the N rows are resampled with replacement (the same rows of A, B and
// every A_B^(i) together), all indices re-estimated, `replicates` times from a fixed seed (GSL's
// MT19937), and the interval is the percentile one, the (1 - c)/2 and (1 + c)/2 quantiles of the
// replicates (Efron & Tibshirani 1993, ch. 13; Archer, Saltelli & Sobol 1997).
//
// References: A. Saltelli, P. Annoni, I. Azzini, F. Campolongo, M. Ratto, S. Tarantola,
// Variance based sensitivity analysis of model output. Design and estimator for the total
// sensitivity index, Comput. Phys. Commun. 181 (2010) 259-270. M. J. W. Jansen, Analysis of
// variance designs for model output, Comput. Phys. Commun. 117 (1999) 35-43. I. M. Sobol,
// Global sensitivity indices for nonlinear mathematical models and their Monte Carlo
// estimates, Math. Comput. Simul. 55 (2001) 271-280. G. E. B. Archer,
// A. Saltelli, I. M. Sobol, Sensitivity measures, ANOVA-like techniques and the use of
// bootstrap, J. Stat. Comput. Simul. 58 (1997) 99-120.
#include "hertzdash/simulation/uncertainty/sample_design.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace hertzdash {

/// An estimate with its bootstrap confidence interval.
struct IndexEstimate {
  double value = 0, lower = 0, upper = 0;
};

struct SobolIndices {
  std::vector<IndexEstimate> first;  ///< S_i, one per input
  std::vector<IndexEstimate> total;  ///< ST_i
  double variance = 0;               ///< V of [f(A), f(B)]
  double mean = 0;                   ///< mean of [f(A), f(B)]
};

struct SobolOptions {
  std::size_t replicates = 1000;  ///< bootstrap resamples (0: no intervals, lower = upper = value)
  double confidence = 0.95;       ///< of the percentile interval, in (0, 1)
  std::uint64_t seed = 20100101;  ///< of the resampling
};

/// The unit-cube points of the Saltelli design, N (d + 2) rows of d coordinates, row-major in
/// the block order above, from unit_sample(method, N, 2 d, seed). Throws InvalidParameter for
/// N < 2, d = 0 or a design unit_sample refuses (a Sobol design needs 2 d <= 40).
std::vector<double> saltelli_unit_points(SampleMethod method, std::size_t n, std::size_t d, std::uint64_t seed);

/// The indices from the outputs f of the design's N (d + 2) runs, in design order. Throws
/// std::invalid_argument if f.size() != N (d + 2), N < 2, d = 0, a value of f is not finite,
/// the options are out of range, or V = 0 (a constant output has no indices).
SobolIndices sobol_indices(std::span<const double> f, std::size_t n, std::size_t d, const SobolOptions& options = {});

}  // namespace hertzdash
