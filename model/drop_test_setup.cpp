#include "hertzdash/model/drop_test_setup.hpp"

#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace hertzdash {

void validate(const DropTestSetup& s) {
  require_positive("--mass", s.mass_kg, "kg");
  require_positive("--ball-radius", s.ball_radius_m, "m");
  require_positive("--ball-E", s.ball.E_Pa, "Pa");
  require_in_open("--ball-nu", s.ball.nu, -1.0, 0.5);
  require_positive_or_infinite("--ball-yield-stress", s.ball_yield_stress_Pa, "Pa");
  require_positive_or_infinite("--rod-E", s.rod.E_Pa, "Pa");
  require_in_open("--rod-nu", s.rod.nu, -1.0, 0.5);
  require_in_open_closed("--restitution", s.restitution, 0.0, 1.0);
  require_non_negative("--height", s.height_m, "m");
  require_non_negative("--gravity", s.gravity_mps2, "m/s^2");
  if (s.impact_velocity_mps) {
    require_positive("--impact-velocity", *s.impact_velocity_mps, "m/s");
  } else if (!(s.height_m > 0 && s.gravity_mps2 > 0)) {
    throw InvalidParameter("--height", format_value(s.height_m),
                           "> 0 with --gravity > 0 when no --impact-velocity is given (the rod must reach the ball)");
  }
  if (const auto& A = s.damping.viscous_time_constant_s) require_non_negative("--viscous-time-constant", *A, "s");
  require_non_negative("--reference-velocity", s.damping.reference_velocity_mps, "m/s (0: the approach speed)");
  if (s.elastic_rod) {
    if (std::isinf(s.rod.E_Pa))
      throw InvalidParameter("--rod-E", format_value(s.rod.E_Pa),
                             "a finite modulus [Pa] with --rod-model elastic (inf is the rigid rod: --rod-model rigid)");
    validate(*s.elastic_rod);
  }
  validate_hertz_scale(s);
}

void validate_hertz_scale(const DropTestSetup& s) {
  const double K = hertz_stiffness(s), v0 = approach_speed(s);
  const double X = undamped_hertz_impact(K, s.mass_kg, v0).max_deformation_m;
  // The approach speed at which X = R: R^{5/2} = 5 m v^2 / (4 K).
  const double v_max = std::sqrt(4.0 * K * std::pow(s.ball_radius_m, 2.5) / (5.0 * s.mass_kg));
  const std::string why = fmt::format(
      "(with --mass {:g} kg, --ball-radius {:g} m and K = {:.4g} N/m^1.5 from the moduli, the undamped Hertz "
      "deformation X = (5 m v0^2 / 4K)^(2/5) is {:.3g} m",
      s.mass_kg, s.ball_radius_m, K, X);
  if (!(X < s.ball_radius_m)) {
    const std::string tail = why + "; at or above the ball radius the small-deformation Hertz contact does not hold)";
    if (s.impact_velocity_mps)
      throw InvalidParameter("--impact-velocity", format_value(v0), fmt::format("below {:.4g} m/s {}", v_max, tail));
    throw InvalidParameter("--height", format_value(s.height_m),
                           fmt::format("below {:.4g} m with --gravity {:g} m/s^2 {}",
                                       v_max * v_max / (2.0 * s.gravity_mps2), s.gravity_mps2, tail));
  }
  if (!(X >= min_hertz_deformation_m)) {
    const std::string range = fmt::format(
        "large enough that X >= {:g} m {}; below that, far under atomic dimensions, no continuum contact model applies)",
        min_hertz_deformation_m, why);
    throw InvalidParameter(s.impact_velocity_mps ? "--impact-velocity" : "--height",
                           format_value(s.impact_velocity_mps ? v0 : s.height_m), range);
  }
}

const char* to_string(Accelerometer a) { return a == Accelerometer::top ? "top" : "bottom"; }

void validate(const ElasticRodSetup& s) {
  require_positive("rod length (Table 1)", s.length_m, "m");
  require_positive("rod diameter (Table 1)", s.diameter_m, "m");
  if (s.elements < 1 || s.elements > ElasticRodSetup::max_elements)
    throw InvalidParameter("--rod-elements", std::to_string(s.elements),
                           fmt::format("an integer in [1, {}]", ElasticRodSetup::max_elements));
  if (!(s.rod_damping_ratio >= 0 && s.rod_damping_ratio < 1))
    throw InvalidParameter("--rod-damping-ratio", format_value(s.rod_damping_ratio), "[0, 1)");
  require_positive("--hemisphere-mass", s.hemisphere_mass_kg, "kg");
  require_positive_or_infinite("--cell-stiffness", s.cell_stiffness_N_per_m, "N/m");
  if (!(s.cell_damping_ratio >= 0 && s.cell_damping_ratio < 1))
    throw InvalidParameter("--cell-damping-ratio", format_value(s.cell_damping_ratio), "[0, 1)");
}

double hertz_stiffness(const DropTestSetup& s) { return hertz_stiffness(s.ball_radius_m, s.ball, s.rod); }

double approach_speed(const DropTestSetup& s) {
  return s.impact_velocity_mps ? *s.impact_velocity_mps : std::sqrt(2.0 * s.gravity_mps2 * s.height_m);
}

}  // namespace hertzdash
