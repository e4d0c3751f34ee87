#pragma once
// Distributions of uncertain inputs, each given by its quantile function (inverse CDF), so
// that one unit-cube design (Monte Carlo, Latin hypercube, Sobol; simulation/uncertainty/sample_design.hpp)
// maps onto any of them: x = quantile(u), u in (0, 1).
//
//   uniform(min, max)              F^-1(u) = min + u (max - min)
//   normal(mean, sd)               F^-1(u) = mean + sd Phi^-1(u)
//   lognormal(log_mean, log_sd)    F^-1(u) = exp(log_mean + log_sd Phi^-1(u))  (of ln X; median exp(log_mean))
//
// A normal or lognormal may be truncated to [lower, upper]: u is mapped into
// [F(lower), F(upper)] first, F^-1(F(lower) + u (F(upper) - F(lower))), which is the exact
// truncated distribution (no rejection, so a design keeps its structure).
#include <limits>
#include <string>
#include <string_view>

namespace hertzdash {

enum class DistributionKind { uniform, normal, lognormal };

/// One input's distribution. Constant parameters; quantile() is the only operation.
struct InputDistribution {
  DistributionKind kind = DistributionKind::uniform;
  double p1 = 0;  ///< uniform: min; normal: mean; lognormal: mean of ln X
  double p2 = 1;  ///< uniform: max; normal: standard deviation; lognormal: standard deviation of ln X
  double lower = -std::numeric_limits<double>::infinity();  ///< truncation (normal, lognormal)
  double upper = std::numeric_limits<double>::infinity();

  /// The value at probability u in (0, 1); truncated distributions stay within [lower, upper].
  /// u = 0 or 1 gives the support's end (infinite for an untruncated normal).
  double quantile(double u) const;
};

InputDistribution uniform_distribution(double min, double max);
InputDistribution normal_distribution(double mean, double sd, double lower = -std::numeric_limits<double>::infinity(),
                                      double upper = std::numeric_limits<double>::infinity());
InputDistribution lognormal_distribution(double log_mean, double log_sd, double lower = 0,
                                         double upper = std::numeric_limits<double>::infinity());

/// "uniform", "normal", "lognormal" -> the kind; anything else InvalidParameter(`name`, ...).
DistributionKind parse_distribution_kind(std::string_view kind, const std::string& name);
std::string to_string(DistributionKind kind);

/// Throws InvalidParameter naming `name` (e.g. "ball-E") unless the parameters are finite and
/// ordered: min < max, sd > 0, log_sd > 0, lower < upper with positive probability between them
/// (a lognormal's lower >= 0).
void validate(const InputDistribution& d, const std::string& name);

/// "normal(mean = 0.83, sd = 0.003) truncated to [0.8, 0.86]": for headers and tables.
std::string describe(const InputDistribution& d);

}  // namespace hertzdash
