#pragma once
// HuntCrossley: Hunt-Crossley form with chi v0 = 3(1-e)/2.
#include "hertzdash/model/damping/hertz_proportional_dashpot.hpp"

namespace hertzdash {

/// F = K x^{3/2} (1 + chi xdot),  chi = 3(1-e)/2 / v0
/// K. H. Hunt, F. R. E. Crossley, Coefficient of restitution interpreted as damping in vibroimpact, J.
/// Appl. Mech. 42(2) (1975) 440-445.
class HuntCrossley : public HertzProportionalDashpot<HuntCrossley> {
 public:
  static constexpr LawInfo info{
      "hunt-crossley",
      "K. H. Hunt, F. R. E. Crossley, Coefficient of restitution interpreted as damping in vibroimpact, J. "
      "Appl. Mech. 42(2) (1975) 440-445.",
      "F = K x^{3/2} (1 + chi xdot)",
      "chi = 3(1-e)/2 / v0, v0 = approach speed; independent of K and m",
      "derived for e close to 1 (linearised e = 1 - (2/3) chi v0)",
      true};

  /// chi v0 [-] as a function of the input restitution e in (0, 1].
  static double chi_v0(double e) { return 1.5 * (1.0 - e); }

  using HertzProportionalDashpot::HertzProportionalDashpot;
};

}  // namespace hertzdash
