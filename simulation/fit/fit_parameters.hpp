#pragma once
// Internal to the trace fit (simulation/fit/trace_fit.cpp; not installed, cmake/install.cmake): the
// fitted parameters' bounds and starting values, and the transforms between a bounded parameter
// and the unbounded variable the least-squares solver moves (simulation/fit/trace_fit.hpp,
// "Uncertainty"). Parsing a --fit list (parse_fit_parameters) is public, in trace_fit.hpp.
#include "hertzdash/simulation/fit/trace_fit.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <cmath>
#include <vector>

namespace hertzdash::trace_fit_detail {

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

/// The starting value of each parameter: its value in the set-up `base` resolves to. Throws
/// InvalidParameter("fit", ...) for a parameter unset with no default, or outside its bounds.
std::vector<double> initial_values(const RunOptions& base, const PaperParameters& paper,
                                   const std::vector<FitParameter>& parameters);

}  // namespace hertzdash::trace_fit_detail
