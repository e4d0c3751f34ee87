#pragma once
// LeeHerrmann: the Hertz spring with a linear dashpot proportional to the mass, whose damping rate
// is a constant of the pair of bodies.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/damping/reference_velocity.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <optional>

namespace hertzdash {

/// F = K x^{3/2} + m gamma xdot                                  [N]
/// gamma [1/s] is a damping rate of the pair of bodies, fixed for them, not per impact: Lee and
/// Herrmann's Hertz contact with the dashpot gamma_n m_eff xdot. LAMMPS's pair_style granular with
/// damping mass_velocity (eta_n = eta_n0 m*) is this law with gamma = eta_n0; its damping velocity
/// (eta_n = eta_n0) is this law contact by contact, with gamma = eta_n0 / m*. The dashpot does not
/// vanish at onset: F(0, v0) = m gamma v0.
///
/// Scaling x by X* = (m v0^2 / K)^{2/5} and t by X*/v0 leaves one number, gamma X*/v0 =
/// gamma (m/K)^{2/5} v0^{-1/5}: e FALLS as v0 falls (slower impacts last longer and lose more; e -> 0
/// as v0 -> 0, where kuwabara-kono's e -> 1). To first order in gamma the dashpot takes
/// m gamma int xdot^2 dt of the undamped impact, int_0^{t_c} xdot^2 dt = 2 v0 X int_0^1 (1 - s^{5/2})^{1/2} ds
/// = (4/5) B(2/5, 3/2) v0 X with X = (5 m v0^2 / (4K))^{2/5}, so 1 - e = (4/5) B(2/5, 3/2) gamma X / v0
/// + O(gamma^2) (tests/test_lee_herrmann.cpp checks it, and the order of the remainder).
///
/// gamma comes from --damping-rate; when the user gives none, the simulator calibrates it so that
/// the law's restitution at the reference speed (--reference-velocity, default the first
/// impact's approach speed) is the input e.
class LeeHerrmann {
 public:
  static constexpr LawInfo info{
      "lee-herrmann",
      "J. Lee, H. J. Herrmann, Angle of repose and angle of marginal stability: molecular dynamics of granular "
      "particles, J. Phys. A 26(2) (1993) 373-383 (a Hertz contact with the dashpot gamma_n m_eff xdot); LAMMPS's "
      "pair_style granular with damping mass_velocity.",
      "F = K x^{3/2} + m gamma xdot, gamma = a damping rate of the pair [1/s]",
      "gamma given (--damping-rate), or calibrated so that e_effective = e at the reference speed "
      "(--reference-velocity, default the first impact's); e then falls with v0 through gamma (m/K)^{2/5} v0^{-1/5}",
      "a DEM contact, not a material law: its e tends to 0 at small speeds",
      false};
  static constexpr bool material_time_constant = true;
  /// The law's own inputs: its damping rate first (MaterialTimeConstantLaw), then the reference speed.
  static constexpr ParameterDecl parameters[] = {
      {.key = "damping-rate",
       .unit = "1/s",
       .column_unit = "per_s",
       .range = NumberRange::non_negative(),
       .default_value = "calibrated",
       .default_source = "computed: the gamma whose restitution at `reference-velocity` is the input e",
       .help = "Damping rate gamma [1/s] >= 0 of lee-herrmann's dashpot m gamma xdot; replaces the calibration from e",
       .fittable = true},
      reference_velocity_parameter,
  };
  /// gamma is the law value `damping-rate`; its size for an impact is v0 / X (MaterialTimeConstantLaw).
  static std::optional<double> material_constant(const DampingSettings& s) { return s.given(parameters[0]); }
  static void set_material_constant(DampingSettings& s, double gamma_per_s) { s.set(parameters[0], gamma_per_s); }
  static double material_constant_scale(double X_m, double v0_mps) { return v0_mps / X_m; }

  LeeHerrmann(const ImpactConditions& c, const DampingSettings& s)
      : K_(c.K), gamma_(rate(s)), c_(c.mass_kg * gamma_) {}

  double force(double x, double xdot) const noexcept { return hertz_spring_force(K_, x) + c_ * xdot; }
  /// The same at u = x^{1/2}: K u^3 + c xdot [N] (RootPolynomialLaw)
  template <class T>
  auto force_of_root(const T& u, const T& xdot) const noexcept { return K_ * u * u * u + c_ * xdot; }
  /// dF/dv0 = 0: gamma is the pair's, fixed for the set-up (SpeedDerivativeLaw)
  double force_speed_derivative(double, double) const noexcept { return 0.0; }

  std::vector<NamedValue> coefficients() const { return {{"damping_rate_per_s", gamma_}, {"c_N_s_per_m", c_}}; }

 private:
  static double rate(const DampingSettings& s) {
    const std::optional<double> gamma = material_constant(s);
    if (!gamma)
      throw InvalidParameter("damping-rate", "(unset)",
                             "given, or calibrated by the simulator from e at the reference speed (a lee-herrmann "
                             "law built outside ImpactSimulator needs the law value `damping-rate`)");
    require_in_range(parameters[0], *gamma);
    return *gamma;
  }

  double K_;      ///< Hertz stiffness [N/m^{3/2}]
  double gamma_;  ///< damping rate [1/s]
  double c_;      ///< m gamma [N s/m]
};

}  // namespace hertzdash
