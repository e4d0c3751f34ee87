#pragma once
// The physics extension point: a damping law (the numerical one, an integrator, is a
// row of simulation/run/integrator_table.hpp).
//
// A law is a small class in its own header under model/damping/laws/, listed
// once in model/damping/registered_laws.cmake. It carries
//   - `static constexpr LawInfo info`: name (CLI spelling), citation, formula,
//     how its coefficients follow from (e, v0, K, m), validity range;
//   - a constructor from the impact's ImpactConditions and the DampingSettings,
//     which fixes its coefficients for that impact (called at contact onset);
//   - `double force(double x, double xdot) const noexcept`: the total contact
//     force [N], compressive positive, for deformation x >= 0 [m] and
//     deformation rate xdot [m/s] (positive while approaching);
//   - `std::vector<NamedValue> coefficients() const`: its fixed coefficients,
//     with units in the names, for reports (never on the hot path).
// The drop test, the CLI, the restitution maps and the standard tests all take
// every registered law from the registry; see model/README.md.
#include "hertzdash/model/omega_n_variant.hpp"
#include "hertzdash/model/parameter.hpp"
#include "hertzdash/model/restitution.hpp"

#include <concepts>
#include <optional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

namespace hertzdash {

/// What a law's coefficients may depend on, fixed at contact onset.
struct ImpactConditions {
  double K;              ///< Hertz stiffness [N/m^{3/2}], eq. (3)
  double mass_kg;        ///< impacting mass [kg]
  double v0_mps;         ///< approach speed at contact onset [m/s], > 0
  double restitution;    ///< input coefficient of restitution e in (0, 1]
};

/// Modelling choices shared by laws that need them.
struct DampingSettings {
  ZetaForm zeta_form = ZetaForm::paper;  ///< eq. (6) or the exact linear-oscillator relation
  OmegaNVariant omega_n = OmegaNVariant::paper;  ///< the paper's law only: how omega_n is chosen (eqs. 7-11)
  double omega_n_rad_per_s = 0;  ///< omega_n [rad/s] used by the iterated variants (> 0 then), else ignored
  /// Laws with a material time constant (MaterialTimeConstantLaw): A [s] >= 0. Unset, the
  /// simulator calibrates it so that the law's restitution at reference_velocity_mps is the
  /// input e (simulation/run/viscous_time_constant.hpp); other laws ignore it.
  std::optional<double> viscous_time_constant_s;
  /// Approach speed [m/s] at which that calibration holds, > 0; 0 means the set-up's own
  /// approach speed (of its first impact).
  double reference_velocity_mps = 0;
  /// The numbers a user gave for the inputs a law declares in its own `parameters` list and
  /// reads through number() (a law's own inputs need no field here): {key, value}, set by
  /// simulation/options/run_options.cpp, validated there against the declaration's range.
  std::vector<std::pair<std::string_view, double>> law_values;

  /// The value given for the law's input `p`, else its declared default.
  double number(const ParameterDecl& p) const { return given(p).value_or(p.default_number); }
  /// The value given for the law's input `p`, if one was.
  std::optional<double> given(const ParameterDecl& p) const {
    for (const auto& [key, value] : law_values)
      if (key == p.key) return value;
    return std::nullopt;
  }
  /// Gives the law's input `p` the value `value` (replacing one given before).
  void set(const ParameterDecl& p, double value) {
    for (auto& [key, v] : law_values)
      if (key == p.key) {
        v = value;
        return;
      }
    law_values.emplace_back(p.key, value);
  }
};

/// Descriptive data of a law, shown by `hertzdash models`.
struct LawInfo {
  std::string_view name;          ///< CLI spelling, e.g. "hunt-crossley"
  std::string_view citation;      ///< full reference
  std::string_view formula;       ///< the force law, plain text
  std::string_view coefficients;  ///< how the coefficients follow from e, v0, K, m
  std::string_view validity;      ///< stated validity range
  bool force_continuous_at_onset; ///< F(0, v0) = 0 ?
};

struct NamedValue {
  const char* name;
  double value;
};

/// Optional for a law: the inputs it reads besides (e, v0, K, m), declared once in its header as
///   static constexpr ParameterDecl parameters[] = {{.key = "...", ...}};
/// Each becomes an option of every front end (--key, a Python keyword, a case key, a `fit`
/// parameter when fittable), refused with every other law. A number the law reads through
/// DampingSettings::number(decl); the paper's law's zeta and omega-n and kuwabara-kono's time
/// constant are declared here too but, being read outside the law as well, keep fields above.
template <class L>
concept LawWithParameters = requires { std::span<const ParameterDecl>(L::parameters); };

/// The inputs law L declares (none for most laws).
template <class L> ParameterDecls law_parameters() {
  if constexpr (LawWithParameters<L>) return ParameterDecls(L::parameters);
  else return {};
}

template <class L>
concept DampingLaw = requires(const L& law, const ImpactConditions& c, const DampingSettings& s, double x) {
  { L::info } -> std::convertible_to<LawInfo>;
  L(c, s);
  { law.force(x, x) } -> std::same_as<double>;
  { law.coefficients() } -> std::same_as<std::vector<NamedValue>>;
};

namespace detail {
/// A stand-in for the scalar types force_of_root is evaluated over: a ring over the
/// reals (+, - and * among its values and with doubles, / by a double), nothing more --
/// double, and the truncated power series of the Taylor integrator
/// (integrators/power_series.hpp). Declared only, for the concept below.
struct RingScalar {};
RingScalar operator+(RingScalar, RingScalar);
RingScalar operator-(RingScalar, RingScalar);
RingScalar operator*(RingScalar, RingScalar);
RingScalar operator-(RingScalar);
RingScalar operator*(double, RingScalar);
RingScalar operator*(RingScalar, double);
RingScalar operator/(RingScalar, double);
RingScalar operator+(double, RingScalar);
RingScalar operator+(RingScalar, double);
RingScalar operator-(double, RingScalar);
RingScalar operator-(RingScalar, double);
}  // namespace detail

/// Optional for a law: a force that is a polynomial in (x^{1/2}, xdot) -- Hertz, the
/// paper's law, the Hunt-Crossley family, Kelvin-Voigt -- declares it by offering
/// `force_of_root(u, xdot)` = force(u^2, xdot) for u = x^{1/2} >= 0, written as that
/// polynomial in u (no square root), once, as a template over the scalar type:
///   template <class T> auto force_of_root(const T& u, const T& xdot) const { return K_ * u * (u * u + c_ * xdot); }
/// using only +, - and * (and doubles), so that it also evaluates on power series (the
/// Taylor integrator generates the Taylor coefficients of the contact from it). Its
/// smooth continuation to u < 0 is what makes the contact in regularising variables
/// (model/contact_system.hpp) smooth through onset and separation.
template <class L>
concept RootPolynomialLaw = DampingLaw<L> && requires(const L& law, double u, detail::RingScalar r) {
  { law.force_of_root(u, u) } -> std::same_as<double>;
  { law.force_of_root(r, r) } -> std::same_as<detail::RingScalar>;
};

/// Optional for a RootPolynomialLaw: how its force at fixed (x, xdot) moves with the approach
/// speed v0 through the coefficients fixed at onset, declared by offering
///   double force_speed_derivative(double u, double xdot) const;   // dF/dv0 [N s/m] at u = x^{1/2}
/// (0 for a law whose coefficients do not depend on v0). The soft contact's variational equations
/// (model/contact_tangent_system.hpp) need it: a change of the impact speed changes the law too.
template <class L>
concept SpeedDerivativeLaw = RootPolynomialLaw<L> && requires(const L& law, double u) {
  { law.force_speed_derivative(u, u) } -> std::same_as<double>;
};

/// Optional for a law: damping set by a material constant of the pair (the viscoelastic Hertz
/// law's time constant A [s], DampingSettings::viscous_time_constant_s; a damping rate gamma [1/s],
/// a law number) instead of by the input e, so that its restitution depends on the impact speed.
/// Such a law declares `static constexpr bool material_time_constant = true`, its constant first
/// in its `parameters`, and
///   static std::optional<double> material_constant(const DampingSettings&);  // the value given
///   static void set_material_constant(DampingSettings&, double);
///   static double material_constant_scale(double X_m, double v0_mps);  // its size for an impact of
///                                                                       // undamped deformation X at v0
/// and requires the constant in its constructor; when the user gives none, the simulator supplies
/// it by calibrating the law's restitution to the input e at the reference speed
/// (simulation/run/viscous_time_constant.hpp), its damping growing with the constant from none at 0.
/// Optional for a law: `static constexpr bool conservative = true` declares that the contact
/// returns all the energy it stores, e_effective = 1 (the undamped Hertz law). Every other law
/// dissipates, e_effective < 1. Either way no law creates energy: an e_effective above 1 beyond
/// the run's accuracy is an under-resolved run (simulation/run/result_checks.hpp), and the message
/// says which of the two the law is.
template <class L>
concept ConservativeLaw = DampingLaw<L> && requires { requires L::conservative; };

template <class L>
concept MaterialTimeConstantLaw = DampingLaw<L> && requires(DampingSettings& s, double x) {
  requires L::material_time_constant;
  { L::material_constant(s) } -> std::same_as<std::optional<double>>;
  L::set_material_constant(s, x);
  { L::material_constant_scale(x, x) } -> std::same_as<double>;
};

/// A list of laws as types (the registered ones: RegisteredLaws, model/damping/registered_law_types.hpp).
template <DampingLaw... L> struct LawList {};

}  // namespace hertzdash
