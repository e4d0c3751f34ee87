#pragma once
// LankaraniNikravesh: Hunt-Crossley form with chi v0 = 3(1-e^2)/4.
#include "hertzdash/model/damping/hertz_proportional_dashpot.hpp"

namespace hertzdash {

/// F = K x^{3/2} (1 + chi xdot),  chi = 3(1-e^2)/4 / v0
/// H. M. Lankarani, P. E. Nikravesh, A contact force model with hysteresis damping for impact analysis
/// of multibody systems, J. Mech. Des. 112(3) (1990) 369-376.
class LankaraniNikravesh : public HertzProportionalDashpot<LankaraniNikravesh> {
 public:
  static constexpr LawInfo info{
      "lankarani-nikravesh",
      "H. M. Lankarani, P. E. Nikravesh, A contact force model with hysteresis damping for impact analysis "
      "of multibody systems, J. Mech. Des. 112(3) (1990) 369-376.",
      "F = K x^{3/2} (1 + chi xdot)",
      "chi = 3(1-e^2)/4 / v0, v0 = approach speed; independent of K and m",
      "e close to 1 (energy balance with compression-phase velocity taken for both phases)",
      true};

  /// chi v0 [-] as a function of the input restitution e in (0, 1].
  static double chi_v0(double e) { return 0.75 * (1.0 - e * e); }

  using HertzProportionalDashpot::HertzProportionalDashpot;
};

}  // namespace hertzdash
