#pragma once
// HuGuo: Hunt-Crossley form with chi v0 = 3(1-e)/(2e).
#include "hertzdash/model/damping/hertz_proportional_dashpot.hpp"

namespace hertzdash {

/// F = K x^{3/2} (1 + chi xdot),  chi = 3(1-e)/(2e) / v0
/// S. Hu, X. Guo, A dissipative contact force model for impact analysis in multibody dynamics,
/// Multibody Syst. Dyn. 35(2) (2015) 131-151.
///
/// Which form: the literature quotes Hu and Guo's damping factor in two forms. This file
/// implements chi v0 = 3(1 - e)/(2e), the form the comparative reviews tabulate. The
/// original paper could not be consulted while this library was written (no network
/// access), so which of the two forms the original prints is NOT verified here; the
/// restitution map (validation/damping_laws) shows what this form returns, and checking
/// the original is an open item (docs/damping-laws.md, "Open item").
class HuGuo : public HertzProportionalDashpot<HuGuo> {
 public:
  static constexpr LawInfo info{
      "hu-guo",
      "S. Hu, X. Guo, A dissipative contact force model for impact analysis in multibody dynamics, "
      "Multibody Syst. Dyn. 35(2) (2015) 131-151.",
      "F = K x^{3/2} (1 + chi xdot)",
      "chi = 3(1-e)/(2e) / v0, v0 = approach speed; independent of K and m",
      "intended for any e in (0, 1]; not exact",
      true};

  /// chi v0 [-] as a function of the input restitution e in (0, 1].
  static double chi_v0(double e) { return 1.5 * (1.0 - e) / e; }

  using HertzProportionalDashpot::HertzProportionalDashpot;
};

}  // namespace hertzdash
