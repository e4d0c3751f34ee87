// Lyapunov exponents by the QR method (simulation/orbits/lyapunov.hpp).
#include "hertzdash/simulation/orbits/lyapunov.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hertzdash {

LyapunovSpectrum lyapunov_spectrum(const StroboscopicMap& map, const Eigen::VectorXd& start, const LyapunovOptions& o) {
  LyapunovSpectrum out;
  const auto n = start.size();
  Eigen::VectorXd z = start, sum = Eigen::VectorXd::Zero(n), half_sum = sum;
  Eigen::MatrixXd Q = Eigen::MatrixXd::Identity(n, n);
  long half_impacts = 0;
  // The sums of log R_ii over `count` periods or impacts, as averages (a count of 0 as 1).
  auto per = [](const Eigen::VectorXd& s, long count) {
    std::vector<double> v(s.data(), s.data() + s.size());
    for (double& x : v) x /= static_cast<double>(std::max(count, 1L));
    return v;
  };
  for (long k = 0; k < o.periods; ++k) {
    if (k == o.periods / 2) half_sum = sum, half_impacts = out.impacts;
    const SectionImage image = map(z);
    if (!image.failure.empty()) {
      out.failure = fmt::format("after {} periods: {}", k, image.failure);
      break;
    }
    // Q R = M Q by modified Gram-Schmidt, R's diagonal positive: each column of M Q less its
    // parts along the earlier columns, its norm R_ii.
    Q = image.monodromy * Q;
    for (Eigen::Index i = 0; i < n; ++i) {
      for (Eigen::Index j = 0; j < i; ++j) Q.col(i) -= Q.col(j).dot(Q.col(i)) * Q.col(j);
      const double r = Q.col(i).norm();
      Q.col(i) /= r;
      sum(i) += std::log(r);
    }
    z = image.state;
    out.impacts += static_cast<long>(image.impacts.size());
    out.periods = k + 1;
    if ((out.periods & (out.periods - 1)) == 0 || out.periods == o.periods) {
      out.running_periods.push_back(out.periods);
      out.running_per_impact.push_back(per(sum, out.impacts));
    }
  }
  out.per_period = per(sum, out.periods);
  out.per_impact = per(sum, out.impacts);
  out.sum_per_impact = sum.sum() / static_cast<double>(std::max(out.impacts, 1L));
  const ImpactSequenceSpec& spec = map.spec();
  // det M = e^(2k) exp(-(c/m + C/M) N T) (stroboscopic_map.hpp), C/M for a box of its own.
  const double T = 1 / spec.frequency_Hz,
               c_over_m = spec.body.damping_N_s_per_m() / spec.body.mass_kg +
                          (spec.prescribed ? 0.0 : spec.box.damping_N_s_per_m() / spec.box.mass_kg);
  out.expected_sum_per_impact =
      spec.soft ? std::numeric_limits<double>::quiet_NaN()
                : 2 * std::log(spec.restitution) -
                      c_over_m * T * static_cast<double>(out.periods) / static_cast<double>(std::max(out.impacts, 1L));
  const std::vector<double> first = per(half_sum, half_impacts), second = per(sum - half_sum, out.impacts - half_impacts);
  for (Eigen::Index i = 0; i < n; ++i)
    out.half_difference = std::max(out.half_difference, std::abs(first[static_cast<std::size_t>(i)] - second[static_cast<std::size_t>(i)]));
  double largest = 0;
  for (const double l : out.per_impact) largest = std::max(largest, std::abs(l));
  out.converged = out.failure.empty() && out.impacts > 0 && out.half_difference < o.tolerance * largest;
  return out;
}

}  // namespace hertzdash
