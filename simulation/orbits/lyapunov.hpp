#pragma once
// The Lyapunov exponents of a rig's stroboscopic map over one drive period
// (simulation/orbits/stroboscopic_map.hpp), along the trajectory from a start: the QR method
// (Benettin, Galgani, Giorgilli and Strelcyn, Meccanica 15 (1980) 9; Eckmann and Ruelle, Rev.
// Mod. Phys. 57 (1985) 617): with the map's monodromy M_n (saltation matrices, no differences),
//   Q_{n+1} R_{n+1} = M_n Q_n,   Q_0 = I,   lambda_i = (1/n) sum_n log (R_n)_ii,
// (modified Gram-Schmidt, R's diagonal positive),
// per drive period, and per impact over the impacts the trajectory made. Their sum is
// (1/n) log |det(M_n ... M_1)|: for instantaneous impacts each impact gives log e^2 and each
// period of flight -c T/m (Liouville), so the sum per impact is 2 ln e - (c/m) T periods/impacts
// (`expected_sum_per_impact`), whatever the trajectory: a check of the accumulation to round-off.
// A box of its own (the damper's primary, mass M, dashpot C) adds -C T/M per period.
// Soft impacts have no such closed form (a contact's determinant depends on its speed and phase):
// there it is NaN.
// Convergence: the exponents per impact of the first and of the second half of the run, whose
// largest difference (`half_difference`) is below `tolerance` times the largest exponent's
// magnitude. A chaotic trajectory's averages converge like 1/sqrt(impacts) (a stretch of O(1)
// per impact: 2 % after ~5000 impacts); a periodic one's like 1/impacts. The run stops, with a failure, on
// a sticking episode (the map is not smooth there) or an image the driver cannot give.
#include "hertzdash/simulation/orbits/stroboscopic_map.hpp"

#include <string>
#include <vector>

namespace hertzdash {

struct LyapunovOptions {
  long periods = 10000;     ///< drive periods of the run
  double tolerance = 0.02;  ///< on the halves' exponents per impact, relative to the largest magnitude
};

struct LyapunovSpectrum {
  std::string failure;              ///< empty: the run went through
  long periods = 0, impacts = 0;    ///< done
  std::vector<double> per_period;   ///< largest first [1/period]
  std::vector<double> per_impact;   ///< the same over the impacts [1/impact]
  double sum_per_impact = 0;
  double expected_sum_per_impact = 0;  ///< 2 ln e - (c/m [+ C/M]) T periods/impacts; NaN for soft impacts
  double half_difference = 0;          ///< max_i |lambda_i(first half) - lambda_i(second half)| per impact
  bool converged = false;              ///< half_difference < tolerance max_i |lambda_i|
  /// The running estimate per impact at periods 1, 2, 4, ..., and at the end.
  std::vector<long> running_periods;
  std::vector<std::vector<double>> running_per_impact;
};

/// The spectrum along the trajectory of `map` (over one period) from `start`.
LyapunovSpectrum lyapunov_spectrum(const StroboscopicMap& map, const Eigen::VectorXd& start, const LyapunovOptions& options);

}  // namespace hertzdash
