#pragma once
// The p-quantile of a sample: Hyndman & Fan (1996) definition 7, the default of R and NumPy.
// With the n values sorted, x_(1) <= ... <= x_(n), and h = (n - 1) p:
//   Q(p) = x_(floor h + 1) + (h - floor h) (x_(floor h + 2) - x_(floor h + 1)),
// so Q(0) is the least value, Q(1) the largest, Q(1/2) the median.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <vector>

namespace hertzdash {

/// Q(p) of `values` (taken by value: sorted in place). Throws std::invalid_argument for an
/// empty sample or p outside [0, 1].
inline double sample_quantile(std::vector<double> values, double p) {
  if (values.empty()) throw std::invalid_argument("sample_quantile: empty sample");
  if (!(p >= 0 && p <= 1)) throw std::invalid_argument("sample_quantile: p must be in [0, 1]");
  std::sort(values.begin(), values.end());
  const double h = static_cast<double>(values.size() - 1) * p;
  const auto k = static_cast<std::size_t>(std::floor(h));
  if (k + 1 >= values.size()) return values.back();
  return values[k] + (h - static_cast<double>(k)) * (values[k + 1] - values[k]);
}

}  // namespace hertzdash
