#include "hertzdash/simulation/shaker/next_impact.hpp"

#include "hertzdash/simulation/shaker/safe_root.hpp"

namespace hertzdash {

NextImpact next_impact(const HarmonicWallMotion& wall, const Flight& flight, double t_from_s, double t_limit_s,
                       double time_tol) {
  // The gap and its rate; |h''| <= g + A w^2 (see the header and safe_root.hpp).
  auto h = [&](double t) { return flight.height_m(t) - wall.position_m(t); };
  auto dh = [&](double t) { return flight.velocity_mps(t) - wall.velocity_mps(t); };
  const SafeRoot r = first_safe_root(h, dh, flight.gravity_mps2 + wall.peak_acceleration_mps2(), t_from_s, t_limit_s,
                                     time_tol, max_next_impact_iterations);
  return {.found = r.found, .grazing = r.grazing, .time_s = r.time_s, .iterations = r.iterations};
}

}  // namespace hertzdash
