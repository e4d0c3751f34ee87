#pragma once
// Linear Kelvin-Voigt contact: a linear spring and a linear dashpot in parallel.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/hertz.hpp"

#include <cmath>

namespace hertzdash {

/// F = k x + c xdot                                             (total contact force)
///   k = m v0^2 / X^2,  X = (5 m v0^2 / (4K))^{2/5}  [N/m]: the linear spring whose
///       undamped maximum deformation at this approach speed equals the Hertz
///       contact's (energy balance (1/2) m v0^2 = (1/2) k X^2 = (2/5) K X^{5/2}),
///       unless k is given (--linear-stiffness);
///   c = 2 zeta sqrt(k m),  zeta = ln(1/e) / sqrt(pi^2 + ln^2 e)  [N s/m]: the exact
///       linear-oscillator relation e = exp(-pi zeta / sqrt(1 - zeta^2)) (always the
///       exact form, whatever --zeta says, so that the law returns its input e).
/// With tension allowed the contact is half a period of a damped linear oscillator,
/// so e_effective = e exactly. The force jumps to c v0 at onset (discontinuous), and
/// it turns tensile (F < 0) before x returns to zero: with --no-tension contact ends
/// earlier, at F = 0, before the tensile tail can pull the rod back, so the rebound is
/// FASTER: e_effective = exp(-(zeta/s)(pi - atan2(2 zeta s, 1 - 2 zeta^2))) > e,
/// s = sqrt(1 - zeta^2) (derived in tests/test_damping_law_restitution.cpp).
class KelvinVoigt {
 public:
  static constexpr LawInfo info{
      "kelvin-voigt",
      "W. Thomson (Lord Kelvin), On the elasticity and viscosity of metals, Proc. R. Soc. Lond. 14 (1865) "
      "289-297; W. Voigt, Ueber innere Reibung fester Koerper, insbesondere der Metalle, Ann. Phys. 283 (1892) "
      "671-693. As a contact law, e.g. W. Goldsmith, Impact, Edward Arnold, London (1960).",
      "F = k x + c xdot (linear spring replaces the Hertz spring)",
      "k = m v0^2 / X^2 with X = (5 m v0^2/(4K))^{2/5} (same undamped max deformation as Hertz); "
      "c = 2 zeta sqrt(k m), zeta = ln(1/e)/sqrt(pi^2 + ln^2 e) (exact)",
      "linear contact stiffness; reproduces e exactly only with tension allowed",
      false};
  /// The law's own input: k given instead of matched to the Hertz contact.
  static constexpr ParameterDecl parameters[] = {
      {.key = "linear-stiffness",
       .unit = "N/m",
       .column_unit = "N_per_m",
       .range = NumberRange::positive(),
       .default_value = "matched",
       .default_source = "computed: k = m v0^2 / X^2, the undamped Hertz contact's maximum deformation X at v0",
       .help = "Spring constant k [N/m] of the linear contact",
       .fittable = true},
  };

  KelvinVoigt(const ImpactConditions& c, const DampingSettings& s)
      : k_(std::isnan(s.number(parameters[0])) ? linear_stiffness(c) : s.number(parameters[0])),
        zeta_(zeta_from_restitution(c.restitution, ZetaForm::exact)),
        c_(2.0 * zeta_ * std::sqrt(k_ * c.mass_kg)) {}

  double force(double x, double xdot) const noexcept { return k_ * x + c_ * xdot; }
  /// The same at u = x^{1/2}: k u^2 + c xdot [N] (RootPolynomialLaw)
  template <class T>
  auto force_of_root(const T& u, const T& xdot) const noexcept { return k_ * u * u + c_ * xdot; }

  std::vector<NamedValue> coefficients() const {
    return {{"k_N_per_m", k_}, {"zeta", zeta_}, {"c_N_s_per_m", c_}};
  }

  /// k [N/m] matched to the Hertz contact's undamped maximum deformation at v0.
  static double linear_stiffness(const ImpactConditions& c) {
    const double X = undamped_hertz_impact(c.K, c.mass_kg, c.v0_mps).max_deformation_m;
    return c.mass_kg * c.v0_mps * c.v0_mps / (X * X);
  }

 private:
  double k_;
  double zeta_;
  double c_;
};

}  // namespace hertzdash
