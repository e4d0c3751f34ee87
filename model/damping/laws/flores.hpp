#pragma once
// Flores: Hunt-Crossley form with chi v0 = 8(1-e)/(5e).
#include "hertzdash/model/damping/hertz_proportional_dashpot.hpp"

namespace hertzdash {

/// F = K x^{3/2} (1 + chi xdot),  chi = 8(1-e)/(5e) / v0
/// P. Flores, M. Machado, M. T. Silva, J. M. Martins, On the continuous contact force models for soft
/// materials in multibody dynamics, Multibody Syst. Dyn. 25(3) (2011) 357-375.
class Flores : public HertzProportionalDashpot<Flores> {
 public:
  static constexpr LawInfo info{
      "flores",
      "P. Flores, M. Machado, M. T. Silva, J. M. Martins, On the continuous contact force models for soft "
      "materials in multibody dynamics, Multibody Syst. Dyn. 25(3) (2011) 357-375.",
      "F = K x^{3/2} (1 + chi xdot)",
      "chi = 8(1-e)/(5e) / v0, v0 = approach speed; independent of K and m",
      "intended for soft materials and any e in (0, 1], low e included; not exact",
      true};

  /// chi v0 [-] as a function of the input restitution e in (0, 1].
  static double chi_v0(double e) { return 1.6 * (1.0 - e) / e; }

  using HertzProportionalDashpot::HertzProportionalDashpot;
};

}  // namespace hertzdash
