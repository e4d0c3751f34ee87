#pragma once
// KuwabaraKono: the viscoelastic Hertz law, whose damping is a material constant.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/damping/reference_velocity.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <cmath>

namespace hertzdash {

/// F = K (x^{3/2} + A x^{1/2} xdot)                              [N]
/// A [s] is a material time constant of the contact (the quasi-static viscoelastic solution of
/// Kuwabara-Kono and Brilliantov et al.: A follows from the bulk and shear viscosities), fixed for
/// the pair of bodies, NOT per impact. Convention: the literature often writes the dashpot term
/// as (3/2) A' x^{1/2} xdot; here A = (3/2) A'.
///
/// The force has the paper's form (model/damping/laws/hongo_paper.hpp: K x^{1/2} (x + tau xdot))
/// with tau = A; the paper fixes tau = 2 zeta(e) / omega_n(v0) per impact, and omega_n grows as
/// v0^{1/5}, so the paper's tau falls as v0^{-1/5} and its e cannot depend on v0. Scaling x by
/// X* = (m v0^2 / K)^{2/5} and t by X*/v0 leaves one number, the damping number
///   beta = A (K/m)^{2/5} v0^{1/5},
/// so the law's restitution is a function e(beta), which rises towards 1 as v0 falls:
///   e = 1 - C1 beta + C2 beta^2 - ...,  C1 = 1.15344, C2 = 0.79826
/// (Ramirez et al. 1999; Schwager and Poeschel 2008; checked in tests/test_kuwabara_kono.cpp).
///
/// A comes from DampingSettings::viscous_time_constant_s (--viscous-time-constant); when the
/// user gives none, the simulator calibrates it so that the law's restitution at the reference
/// speed (--reference-velocity, default the first impact's approach speed) is the input e.
class KuwabaraKono {
 public:
  static constexpr LawInfo info{
      "kuwabara-kono",
      "G. Kuwabara, K. Kono, Restitution coefficient in a collision between two spheres, Jpn. J. Appl. Phys. "
      "26(8) (1987) 1230-1233; N. V. Brilliantov, F. Spahn, J.-M. Hertzsch, T. Poeschel, Model for collisions "
      "in granular gases, Phys. Rev. E 53(5) (1996) 5382-5392. Restitution series: R. Ramirez, T. Poeschel, "
      "N. V. Brilliantov, T. Schwager, Phys. Rev. E 60(4) (1999) 4465-4472; T. Schwager, T. Poeschel, Phys. "
      "Rev. E 78 (2008) 051304.",
      "F = K (x^{3/2} + A x^{1/2} xdot), A = material time constant [s] (A = (3/2) A' of the literature)",
      "A given (--viscous-time-constant), or calibrated so that e_effective = e at the reference speed "
      "(--reference-velocity, default the first impact's); e then depends on v0 through "
      "beta = A (K/m)^{2/5} v0^{1/5}",
      "quasi-static viscoelastic contact: A much shorter than the contact time, speeds far below sound",
      true};
  static constexpr bool material_time_constant = true;
  /// A is DampingSettings::viscous_time_constant_s; its size for an impact is X / v0 (MaterialTimeConstantLaw).
  static std::optional<double> material_constant(const DampingSettings& s) { return s.viscous_time_constant_s; }
  static void set_material_constant(DampingSettings& s, double A_s) { s.viscous_time_constant_s = A_s; }
  static double material_constant_scale(double X_m, double v0_mps) { return X_m / v0_mps; }
  /// The law's own inputs (fields of DampingSettings: the simulator's calibration of A reads them).
  static constexpr ParameterDecl parameters[] = {
      {.key = "viscous-time-constant",
       .unit = "s",
       .column_unit = "s",
       .range = NumberRange::non_negative(),
       .default_value = "calibrated",
       .default_source = "computed: the A whose restitution at `reference-velocity` is the input e",
       .help = "Material time constant A [s] >= 0: F = K (x^{3/2} + A x^{1/2} xdot); replaces the calibration from e",
       .fittable = true},
      reference_velocity_parameter,
  };

  KuwabaraKono(const ImpactConditions& c, const DampingSettings& s)
      : K_(c.K), A_(time_constant(s)), beta_(A_ * std::pow(c.K / c.mass_kg, 0.4) * std::pow(c.v0_mps, 0.2)) {}

  double force(double x, double xdot) const noexcept { return K_ * std::sqrt(x) * (x + A_ * xdot); }
  /// The same at u = x^{1/2}: K u (u^2 + A xdot) [N] (RootPolynomialLaw)
  template <class T>
  auto force_of_root(const T& u, const T& xdot) const noexcept { return K_ * u * (u * u + A_ * xdot); }
  /// dF/dv0 = 0: A is the material's, fixed for the set-up (beta only reports it) (SpeedDerivativeLaw)
  double force_speed_derivative(double, double) const noexcept { return 0.0; }

  std::vector<NamedValue> coefficients() const {
    return {{"viscous_time_constant_s", A_}, {"damping_number_beta", beta_}};
  }

 private:
  static double time_constant(const DampingSettings& s) {
    if (!s.viscous_time_constant_s)
      throw InvalidParameter("viscous-time-constant", "(unset)",
                             "given, or calibrated by the simulator from e at the reference speed (a kuwabara-kono "
                             "law built outside ImpactSimulator needs DampingSettings::viscous_time_constant_s)");
    require_in_range(parameters[0], *s.viscous_time_constant_s);
    return *s.viscous_time_constant_s;
  }

  double K_;     ///< Hertz stiffness [N/m^{3/2}]
  double A_;     ///< material time constant [s]
  double beta_;  ///< damping number of this impact [-]
};

}  // namespace hertzdash
