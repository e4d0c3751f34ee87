#include "hertzdash/simulation/shaker/next_impact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hertzdash {

NextImpact next_impact(const HarmonicWallMotion& wall, const Flight& flight, double t_from_s, double t_limit_s,
                       double time_tol) {
  // Below a few ulps of t the bisection could not shrink the bracket.
  const double time_tol_s = std::max(time_tol, 4.0 * std::numeric_limits<double>::epsilon() * std::abs(t_limit_s));
  const double M = flight.gravity_mps2 + wall.peak_acceleration_mps2();
  auto h = [&](double t) { return flight.height_m(t) - wall.position_m(t); };
  auto dh = [&](double t) { return flight.velocity_mps(t) - wall.velocity_mps(t); };
  NextImpact out;
  double a = t_from_s;
  while (out.iterations < max_next_impact_iterations) {
    ++out.iterations;
    const double H = std::max(h(a), 0.0), D = dh(a);
    if (D < 0 && D * D >= 2.0 * M * H) {
      // The bracket [a, a + d_up]: h decreasing, one root (see the header).
      double lo = a, hi = a + (-D - std::sqrt(D * D - 2.0 * M * H)) / M;
      if (hi > t_limit_s && h(t_limit_s) > 0) return out;
      double t = lo;
      while (out.iterations < max_next_impact_iterations && hi - lo > time_tol_s) {
        ++out.iterations;
        const double ht = h(t);
        if (ht == 0) {
          lo = hi = t;
          break;
        }
        (ht > 0 ? lo : hi) = t;
        const double dht = dh(t);
        const double newton = dht < 0 ? t - ht / dht : lo;
        const bool inside = newton > lo && newton < hi;
        const double next = inside ? newton : 0.5 * (lo + hi);
        if (inside && std::abs(next - t) <= 0.5 * time_tol_s) {
          lo = hi = next;
          break;
        }
        t = next;
      }
      out.found = true;
      out.time_s = 0.5 * (lo + hi);
      return out;
    }
    const double step = (D + std::sqrt(D * D + 2.0 * M * H)) / M;
    if (!(step > time_tol_s)) {
      out.found = out.grazing = true;
      out.time_s = a;
      return out;
    }
    a += step;
    if (a > t_limit_s) return out;
  }
  return out;
}

}  // namespace hertzdash
