#pragma once
// Undamped Hertz contact: the elastic force of eq. (3) alone.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/hertz.hpp"

#include <cmath>

namespace hertzdash {

/// F = K x^{3/2}. Conserves energy: e_effective = 1 whatever the input e.
class Undamped {
 public:
  static constexpr LawInfo info{
      "none",
      "H. Hertz, Ueber die Beruehrung fester elastischer Koerper, J. reine angew. Math. 92 (1882) 156-171.",
      "F = K x^{3/2}",
      "no coefficients; the input restitution is ignored",
      "elastic contact, any impact speed small against the wave speed",
      true};
  static constexpr bool conservative = true;  ///< ConservativeLaw

  Undamped(const ImpactConditions& c, const DampingSettings&) : K_(c.K) {}
  double force(double x, double /*xdot*/) const noexcept { return hertz_spring_force(K_, x); }
  /// The same at u = x^{1/2}: K u^3 [N] (RootPolynomialLaw)
  template <class T>
  auto force_of_root(const T& u, const T& /*xdot*/) const noexcept { return K_ * u * u * u; }
  /// dF/dv0 = 0: no coefficient depends on v0 (SpeedDerivativeLaw)
  double force_speed_derivative(double, double) const noexcept { return 0.0; }
  std::vector<NamedValue> coefficients() const { return {}; }

 private:
  double K_;
};

}  // namespace hertzdash
