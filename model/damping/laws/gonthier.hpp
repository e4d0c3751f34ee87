#pragma once
// Gonthier: Hunt-Crossley form with chi v0 = (1-e^2)/e.
#include "hertzdash/model/damping/hertz_proportional_dashpot.hpp"

namespace hertzdash {

/// F = K x^{3/2} (1 + chi xdot),  chi = (1-e^2)/e / v0
/// Y. Gonthier, J. McPhee, C. Lange, J.-C. Piedboeuf, A regularized contact model with asymmetric
/// damping and dwell-time dependent friction, Multibody Syst. Dyn. 11(3) (2004) 209-233.
class Gonthier : public HertzProportionalDashpot<Gonthier> {
 public:
  static constexpr LawInfo info{
      "gonthier",
      "Y. Gonthier, J. McPhee, C. Lange, J.-C. Piedboeuf, A regularized contact model with asymmetric "
      "damping and dwell-time dependent friction, Multibody Syst. Dyn. 11(3) (2004) 209-233.",
      "F = K x^{3/2} (1 + chi xdot)",
      "chi = (1-e^2)/e / v0, v0 = approach speed; independent of K and m",
      "intended for any e in (0, 1]; not exact (hertzdash restitution shows by how much)",
      true};

  /// chi v0 [-] as a function of the input restitution e in (0, 1].
  static double chi_v0(double e) { return (1.0 - e * e) / e; }

  using HertzProportionalDashpot::HertzProportionalDashpot;
};

}  // namespace hertzdash
