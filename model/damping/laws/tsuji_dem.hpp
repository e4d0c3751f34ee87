#pragma once
// The DEM dashpot with x^{1/4} weighting (Tsuji et al. 1992 family).
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/hertz.hpp"

#include <cmath>

namespace hertzdash {

/// F = K x^{3/2} + c x^{1/4} xdot,   c = -sqrt(5) beta sqrt(K m),
///   beta = ln e / sqrt(ln^2 e + pi^2)                              (beta <= 0)
/// This is the closed form DEM codes use (e.g. LIGGGHTS, Yade "Hertz-Mindlin"):
/// gamma_n = -2 sqrt(5/6) beta sqrt(S_n m) with the tangent stiffness
/// S_n = dF_el/dx = (3/2) K x^{1/2}; 2 sqrt(5/6 * 3/2) = sqrt(5). Tsuji, Tanaka and
/// Ishida introduced the x^{1/4} weighting and gave alpha(e) = c / sqrt(K m) as a graph.
///
/// With tension allowed the coefficient is exact: the law returns its input e.
/// Proof by a change of the independent variable of the phase-plane equation. With v = xdot as a
/// function of x,
///   m v dv/dx + c x^{1/4} v + K x^{3/2} = 0.
/// Put z = x^{5/4}, dz = (5/4) x^{1/4} dx, and divide by x^{1/4}:
///   (5m/4) v dv/dz + c v + K z = 0,
/// which is the phase-plane equation of the LINEAR oscillator (5m/4) z'' + c z' + K z = 0
/// started at z = 0 with z' = v0. The phase curve v(z), hence the rebound speed at z = 0,
/// is that oscillator's (only the time along the curve differs): e = exp(-pi zeta /
/// sqrt(1 - zeta^2)) with zeta = c / (2 sqrt(K 5m/4)) = c / sqrt(5 K m) = -beta, i.e.
/// exactly beta = ln e / sqrt(ln^2 e + pi^2). Checked in tests/test_damping_law_restitution.cpp.
/// The force is F = x^{1/4} (K z + c v): x^{1/4} times the linear oscillator's force,
/// which turns tensile late in the restitution phase. So, as for Kelvin-Voigt, the
/// tension clamp (--no-tension) ends contact earlier, where that force is zero, and
/// RAISES e_effective, to exactly Kelvin-Voigt's clamped value (same phase curve).
class TsujiDem {
 public:
  static constexpr LawInfo info{
      "tsuji-dem",
      "Y. Tsuji, T. Tanaka, T. Ishida, Lagrangian numerical simulation of plug flow of cohesionless particles in a "
      "horizontal pipe, Powder Technol. 71(3) (1992) 239-250 (x^{1/4} dashpot); the closed form of beta as "
      "used in DEM codes (LIGGGHTS, Yade).",
      "F = K x^{3/2} + c x^{1/4} xdot",
      "c = -sqrt(5) beta sqrt(K m), beta = ln e / sqrt(ln^2 e + pi^2); independent of v0",
      "DEM granular contacts; reproduces e exactly with tension allowed (phase-plane change of variable z ="
      " x^{5/4})",
      true};

  TsujiDem(const ImpactConditions& c, const DampingSettings&)
      : K_(c.K),
        beta_(beta_from_restitution(c.restitution)),
        c_(-std::sqrt(5.0) * beta_ * std::sqrt(c.K * c.mass_kg)) {}

  double force(double x, double xdot) const noexcept {
    const double x_quarter = std::sqrt(std::sqrt(x));
    return hertz_spring_force(K_, x) + c_ * x_quarter * xdot;
  }

  std::vector<NamedValue> coefficients() const { return {{"beta", beta_}, {"c_N_s_per_m_1_25", c_}}; }

  /// beta = ln e / sqrt(ln^2 e + pi^2) in (-1, 0]: minus the exact linear-oscillator zeta.
  static double beta_from_restitution(double e) { return -zeta_from_restitution(e, ZetaForm::exact); }

 private:
  double K_;
  double beta_;
  double c_;  ///< [N s / m^{5/4}]
};

}  // namespace hertzdash
