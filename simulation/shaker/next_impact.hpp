#pragma once
// The next impact of a body in free flight above a harmonically moving wall: the first root
// after the flight's start t0 of the gap h(t) = y(t) - s(t) (model/wall_motion.hpp), found from
// the flight's parabola and the wall's sine, not by stepping an ODE through the flight.
//
// No grazing impact is missed. h is smooth with |h''| <= M = g + A w^2, so for any t >= a
//   h(a) + h'(a)(t - a) - M (t - a)^2 / 2  <=  h(t)  <=  h(a) + h'(a)(t - a) + M (t - a)^2 / 2.
// Safe step: with h(a) >= 0, the lower bound is positive on (a, a + d) for
//   d = (h'(a) + sqrt(h'(a)^2 + 2 M h(a))) / M,
// so h has no root there and the search moves to a + d. Bracket: once h'(a) < 0 and
// h'(a)^2 >= 2 M h(a), the upper bound vanishes at
//   d_up = (|h'(a)| - sqrt(h'(a)^2 - 2 M h(a))) / M  <=  |h'(a)| / M,
// so h(a + d_up) <= 0, and h' <= h'(a) + M d_up <= 0 on [a, a + d_up]: h decreases there and
// has exactly one root, the first one, refined by Newton's method safeguarded by bisection
// (every iterate kept inside the bracket) to the time tolerance. Every point the search passes
// is certified root-free by the lower bound, whatever the step. Near a transversal root the safe
// step is d = (r - a)(1 - O(r - a)), so the search reaches the bracket in a few steps; a flight
// that only grazes the wall (h touches zero with h' = 0) makes the safe steps shrink to the time
// tolerance, and the touch is reported as an impact at zero relative speed (`grazing`). The
// search itself is simulation/shaker/safe_root.hpp's, which the two-wall rig uses for each wall.
#include "hertzdash/model/wall_motion.hpp"

namespace hertzdash {

struct NextImpact {
  bool found = false;    ///< false: no impact before the limit, or the iteration cap was reached
  bool grazing = false;  ///< the flight touches the wall tangentially (h = h' = 0 to the tolerance)
  double time_s = 0;     ///< the impact time [s]
  int iterations = 0;    ///< safe steps plus Newton/bisection steps taken
};

/// The most safe steps and root-refinement steps next_impact takes (never reached by a flight
/// whose gap is not tangent to zero to roundoff; reported as not found).
inline constexpr int max_next_impact_iterations = 10000;

/// The first t > t_from_s (at most t_limit_s) with h(t) = 0 for the flight `flight`, searched from
/// t_from_s, where the body must be on or above the wall and not approaching it (h >= 0 up to
/// roundoff, h' >= 0; the caller certifies that no root lies between the flight's start and
/// t_from_s), to the time tolerance max(time_tol_s, 4 eps t_limit_s).
NextImpact next_impact(const HarmonicWallMotion& wall, const Flight& flight, double t_from_s, double t_limit_s,
                       double time_tol_s);

}  // namespace hertzdash
