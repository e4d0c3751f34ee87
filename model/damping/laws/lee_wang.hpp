#pragma once
// LeeWang: Hunt-Crossley form with chi v0 = 3(1-e)/4.
#include "hertzdash/model/damping/hertz_proportional_dashpot.hpp"

namespace hertzdash {

/// F = K x^{3/2} (1 + chi xdot),  chi = 3(1-e)/4 / v0
/// T. W. Lee, A. C. Wang, On the dynamics of intermittent-motion mechanisms, Part 1: dynamic model and
/// response, J. Mech. Trans. Autom. Des. 105(3) (1983) 534-540.
class LeeWang : public HertzProportionalDashpot<LeeWang> {
 public:
  static constexpr LawInfo info{
      "lee-wang",
      "T. W. Lee, A. C. Wang, On the dynamics of intermittent-motion mechanisms, Part 1: dynamic model and "
      "response, J. Mech. Trans. Autom. Des. 105(3) (1983) 534-540.",
      "F = K x^{3/2} (1 + chi xdot)",
      "chi = 3(1-e)/4 / v0, v0 = approach speed; independent of K and m",
      "e close to 1",
      true};

  /// chi v0 [-] as a function of the input restitution e in (0, 1].
  static double chi_v0(double e) { return 0.75 * (1.0 - e); }

  using HertzProportionalDashpot::HertzProportionalDashpot;
};

}  // namespace hertzdash
