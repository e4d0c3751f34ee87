#include "hertzdash/simulation/shaker/impact_pattern.hpp"

#include <algorithm>
#include <cmath>

namespace hertzdash {

ImpactPattern detect_impact_pattern(std::span<const double> t_s, std::span<const double> v_mps, double frequency_Hz,
                                    const PatternTolerance& tol) {
  const std::size_t n = std::min(t_s.size(), v_mps.size());
  for (std::size_t k = 1; 2 * k <= n; ++k) {
    long cycles = -1;
    bool fits = true;
    for (std::size_t i = 0; fits && i + k < n; ++i) {
      const double elapsed = (t_s[i + k] - t_s[i]) * frequency_Hz;
      const double p = std::round(elapsed);
      const double speed_scale = std::max(std::abs(v_mps[i]), tol.speed_scale_mps);
      fits = p >= 1 && std::abs(elapsed - p) <= tol.phase && (cycles < 0 || static_cast<long>(p) == cycles) &&
             std::abs(v_mps[i + k] - v_mps[i]) <= tol.speed * speed_scale;
      cycles = static_cast<long>(p);
    }
    if (fits) return {static_cast<int>(cycles), static_cast<int>(k)};
  }
  return {};
}

}  // namespace hertzdash
