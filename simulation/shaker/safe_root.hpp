#pragma once
// The first root after a of a smooth function h with |h''| <= M on [a, limit], h(a) >= 0, found
// by safe steps that can miss no root, grazing ones included: the next impact on each wall, the
// instant a carried body leaves a wall and the end of the window where it cannot come back
// (simulation/shaker/impact_sequence.hpp). For t >= a
//   h(a) + h'(a)(t - a) - M (t - a)^2 / 2  <=  h(t)  <=  h(a) + h'(a)(t - a) + M (t - a)^2 / 2,
// so the lower bound is positive on (a, a + d), d = (h' + sqrt(h'^2 + 2 M h)) / M, and the search
// moves there; once h' < 0 and h'^2 >= 2 M h, h(a + d_up) <= 0 for
// d_up = (|h'| - sqrt(h'^2 - 2 M h)) / M and h decreases on [a, a + d_up]: one root, refined by
// Newton's method safeguarded by bisection. Both steps are computed in the forms without
// cancellation, d = 2 h / (sqrt(h'^2 + 2 M h) - h') for h' <= 0 and
// d_up = 2 h / (|h'| + sqrt(h'^2 - 2 M h)), so that M -> 0 (a flight at constant speed in a
// box at rest, no gravity) gives the straight line's root. A touch (h = h' = 0 to the
// tolerance) is reported as `grazing`.
#include <algorithm>
#include <cmath>
#include <limits>

namespace hertzdash {

struct SafeRoot {
  bool found = false;    ///< false: none before the limit, or the iteration cap was reached
  bool grazing = false;  ///< h touches zero tangentially
  double time_s = 0;     ///< the root [s]
  int iterations = 0;    ///< safe steps plus Newton/bisection steps
  double root_free_to_s = 0;  ///< not found: h has no root before this time [s] (the limit, or where the cap stopped it)
};

/// The first root of h (derivative dh, |h''| <= M) in (t_from_s, t_limit_s], searched from
/// t_from_s where h >= 0 up to roundoff, to the time tolerance max(time_tol_s, 4 eps t_limit_s).
template <class H, class DH>
SafeRoot first_safe_root(const H& h, const DH& dh, double M, double t_from_s, double t_limit_s, double time_tol_s,
                         int max_iterations = 10000) {
  const double tol = std::max(time_tol_s, 4.0 * std::numeric_limits<double>::epsilon() * std::abs(t_limit_s));
  M = std::max(M, std::numeric_limits<double>::min());
  SafeRoot out;
  double a = t_from_s;
  out.root_free_to_s = a;
  while (out.iterations < max_iterations) {
    ++out.iterations;
    const double Ha = std::max(h(a), 0.0), D = dh(a);
    if (D < 0 && D * D >= 2.0 * M * Ha) {
      double lo = a, hi = a + 2.0 * Ha / (-D + std::sqrt(D * D - 2.0 * M * Ha));
      if (hi > t_limit_s && h(t_limit_s) > 0) {
        out.root_free_to_s = t_limit_s;
        return out;
      }
      double t = lo;
      while (out.iterations < max_iterations && hi - lo > tol) {
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
        if (inside && std::abs(next - t) <= 0.5 * tol) {
          lo = hi = next;
          break;
        }
        t = next;
      }
      out.found = true;
      out.time_s = 0.5 * (lo + hi);
      return out;
    }
    const double root = std::sqrt(D * D + 2.0 * M * Ha);
    const double step = D > 0 ? (D + root) / M : 2.0 * Ha / (root - D);
    if (!(step > tol)) {
      out.found = out.grazing = true;
      out.time_s = a;
      return out;
    }
    a += step;
    out.root_free_to_s = std::min(a, t_limit_s);
    if (a > t_limit_s) return out;
  }
  return out;
}

}  // namespace hertzdash
