#pragma once
// GharibHurmuzlu: Hunt-Crossley form with chi v0 = (1/e - 1).
#include "hertzdash/model/damping/hertz_proportional_dashpot.hpp"

namespace hertzdash {

/// F = K x^{3/2} (1 + chi xdot),  chi = (1/e - 1) / v0
/// M. Gharib, Y. Hurmuzlu, A new contact force model for low coefficient of restitution impact, J.
/// Appl. Mech. 79(6) (2012) 064506.
class GharibHurmuzlu : public HertzProportionalDashpot<GharibHurmuzlu> {
 public:
  static constexpr LawInfo info{
      "gharib-hurmuzlu",
      "M. Gharib, Y. Hurmuzlu, A new contact force model for low coefficient of restitution impact, J. "
      "Appl. Mech. 79(6) (2012) 064506.",
      "F = K x^{3/2} (1 + chi xdot)",
      "chi = (1/e - 1) / v0, v0 = approach speed; independent of K and m",
      "intended for low e (the paper's title); not exact",
      true};

  /// chi v0 [-] as a function of the input restitution e in (0, 1].
  static double chi_v0(double e) { return 1.0 / e - 1.0; }

  using HertzProportionalDashpot::HertzProportionalDashpot;
};

}  // namespace hertzdash
