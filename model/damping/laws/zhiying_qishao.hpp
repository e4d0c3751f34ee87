#pragma once
// ZhiyingQishao: Hunt-Crossley form with chi v0 = 3(1-e^2) exp(2(1-e))/4.
#include "hertzdash/model/damping/hertz_proportional_dashpot.hpp"

namespace hertzdash {

/// F = K x^{3/2} (1 + chi xdot),  chi = 3(1-e^2) exp(2(1-e))/4 / v0
/// Q. Zhiying, L. Qishao, Analysis of impact process based on restitution coefficient, J. Dyn. Control
/// 4 (2006) 294-298 (in Chinese).
class ZhiyingQishao : public HertzProportionalDashpot<ZhiyingQishao> {
 public:
  static constexpr LawInfo info{
      "zhiying-qishao",
      "Q. Zhiying, L. Qishao, Analysis of impact process based on restitution coefficient, J. Dyn. Control "
      "4 (2006) 294-298 (in Chinese).",
      "F = K x^{3/2} (1 + chi xdot)",
      "chi = 3(1-e^2) exp(2(1-e))/4 / v0, v0 = approach speed; independent of K and m",
      "intended for any e in (0, 1]; not exact (hertzdash restitution shows by how much)",
      true};

  /// chi v0 [-] as a function of the input restitution e in (0, 1].
  static double chi_v0(double e) { return 0.75 * (1.0 - e * e) * std::exp(2.0 * (1.0 - e)); }

  using HertzProportionalDashpot::HertzProportionalDashpot;
};

}  // namespace hertzdash
