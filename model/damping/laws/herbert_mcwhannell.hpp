#pragma once
// HerbertMcWhannell: Hunt-Crossley form with chi v0 = 6(1-e)/((2e-1)^2+3).
#include "hertzdash/model/damping/hertz_proportional_dashpot.hpp"

namespace hertzdash {

/// F = K x^{3/2} (1 + chi xdot),  chi = 6(1-e)/((2e-1)^2+3) / v0
/// R. G. Herbert, D. C. McWhannell, Shape and frequency composition of pulses from an impact pair, J.
/// Eng. Ind. 99(3) (1977) 513-518.
class HerbertMcWhannell : public HertzProportionalDashpot<HerbertMcWhannell> {
 public:
  static constexpr LawInfo info{
      "herbert-mcwhannell",
      "R. G. Herbert, D. C. McWhannell, Shape and frequency composition of pulses from an impact pair, J. "
      "Eng. Ind. 99(3) (1977) 513-518.",
      "F = K x^{3/2} (1 + chi xdot)",
      "chi = 6(1-e)/((2e-1)^2+3) / v0, v0 = approach speed; independent of K and m",
      "fitted to numerical solutions of the Hunt-Crossley form; not exact",
      true};

  /// chi v0 [-] as a function of the input restitution e in (0, 1].
  static double chi_v0(double e) { return 6.0 * (1.0 - e) / ((2.0 * e - 1.0) * (2.0 * e - 1.0) + 3.0); }

  using HertzProportionalDashpot::HertzProportionalDashpot;
};

}  // namespace hertzdash
