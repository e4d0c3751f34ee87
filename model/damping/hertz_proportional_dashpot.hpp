#pragma once
// The Hunt-Crossley family: a Hertz spring whose dashpot is proportional to the
// elastic force,
//   F = K x^{3/2} (1 + chi xdot),   chi = chi_v0(e) / v0   [s/m],
// fixed per impact from the input restitution e and the approach speed v0.
// The laws of this family differ only in the dimensionless product chi v0 = f(e)
// that each author derives (an energy balance of the hysteresis loop under some
// approximation of the velocity during compression and restitution).
//
// Two properties every member shares (used by the tests and the README):
//  - the force is continuous at onset (F(0, v0) = 0) and, with tension allowed,
//    never negative: during restitution 1 + chi xdot stays above zero (the
//    rebound speed vr satisfies chi vr < 1, see tests/test_damping_law_restitution.cpp),
//    so the tension clamp (--no-tension) changes nothing;
//  - the effective restitution depends on chi v0 alone (a Lambert-W closed form),
//    hence on e alone, not on m, K or v0.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/hertz.hpp"

#include <cmath>

namespace hertzdash {

/// CRTP base: Derived supplies `static double chi_v0(double e)` (dimensionless chi v0)
/// and `static constexpr LawInfo info`; the base fixes chi and computes the force.
template <class Derived>
class HertzProportionalDashpot {
 public:
  HertzProportionalDashpot(const ImpactConditions& c, const DampingSettings&)
      : K_(c.K), chi_(Derived::chi_v0(c.restitution) / c.v0_mps), v0_mps_(c.v0_mps) {}

  /// F = K x^{3/2} (1 + chi xdot) [N]
  double force(double x, double xdot) const noexcept { return hertz_spring_force(K_, x) * (1.0 + chi_ * xdot); }
  /// The same at u = x^{1/2}: K u^3 (1 + chi xdot) [N] (RootPolynomialLaw)
  template <class T>
  auto force_of_root(const T& u, const T& xdot) const noexcept { return K_ * u * u * u * (1.0 + chi_ * xdot); }

  /// dF/dv0 = -K u^3 chi xdot / v0 [N s/m]: chi = f(e)/v0 (SpeedDerivativeLaw)
  double force_speed_derivative(double u, double xdot) const noexcept { return -K_ * u * u * u * chi_ * xdot / v0_mps_; }

  std::vector<NamedValue> coefficients() const {
    return {{"chi_s_per_m", chi_}, {"damping_coefficient_N_s_per_m_2_5", K_ * chi_}};
  }

 private:
  double K_;    ///< Hertz stiffness [N/m^{3/2}]
  double chi_;  ///< hysteresis damping factor [s/m]
  double v0_mps_;  ///< the approach speed chi was fixed at [m/s]
};

}  // namespace hertzdash
