#include "hertzdash/model/drop_test_setup.hpp"

#include "hertzdash/model/drop_test_parameters.hpp"

#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <string_view>
#include <tuple>

namespace hertzdash {

void validate(const DropTestSetup& s, const GivenScaleInputs& given) {
  namespace p = drop_test_parameters;
  require_in_range(p::mass, s.mass_kg);
  require_in_range(p::ball_radius, s.ball_radius_m);
  require_in_range(p::ball_E, s.ball.E_Pa);
  require_in_range(p::ball_nu, s.ball.nu);
  require_in_range(p::ball_yield_stress, s.ball_yield_stress_Pa);
  require_in_range(p::rod_E, s.rod.E_Pa);
  require_in_range(p::rod_nu, s.rod.nu);
  require_in_range(p::restitution, s.restitution);
  require_in_range(p::height, s.height_m);
  require_in_range(p::gravity, s.gravity_mps2);
  if (s.impact_velocity_mps) {
    require_in_range(p::impact_velocity, *s.impact_velocity_mps);
  } else if (!(s.gravity_mps2 > 0)) {  // named first: the height may be a default the user never typed
    throw InvalidParameter("gravity", format_value(s.gravity_mps2),
                           "> 0 with `height` > 0 when no `impact-velocity` is given (the rod must reach the ball)");
  } else if (!(s.height_m > 0)) {
    throw InvalidParameter("height", format_value(s.height_m),
                           "> 0 with `gravity` > 0 when no `impact-velocity` is given (the rod must reach the ball)");
  }
  if (const auto& A = s.damping.viscous_time_constant_s) require_non_negative("viscous-time-constant", *A, "s");
  require_non_negative("reference-velocity", s.damping.reference_velocity_mps, "m/s (0: the approach speed)");
  if (s.elastic_rod) {
    if (std::isinf(s.rod.E_Pa))
      throw InvalidParameter("rod-E", format_value(s.rod.E_Pa),
                             "a finite modulus [Pa] with `rod-model` elastic (inf is the rigid rod: `rod-model` rigid)");
    validate(*s.elastic_rod);
  }
  validate_hertz_scale(s, given);
}

void validate_hertz_scale(const DropTestSetup& s, const GivenScaleInputs& given) {
  const double K = hertz_stiffness(s), v0 = approach_speed(s), m = s.mass_kg, R = s.ball_radius_m;
  const double X = undamped_hertz_impact(K, m, v0).max_deformation_m;
  const bool too_large = !(X < R);
  if (!too_large && X >= min_hertz_deformation_m) return;
  // The deformation the bound is at, and the approach speed and mass that give it:
  // X^{5/2} = 5 m v0^2 / (4 K).
  const double X_bound = too_large ? R : min_hertz_deformation_m;
  const double v_bound = std::sqrt(4.0 * K * std::pow(X_bound, 2.5) / (5.0 * m));
  const double m_bound = 4.0 * K * std::pow(X_bound, 2.5) / (5.0 * v0 * v0);
  const char* side = too_large ? "below" : "at least";
  const bool fall = !s.impact_velocity_mps;

  auto input = [](const char* key, double value, const char* unit, bool was_given) {
    return fmt::format("{} {:g}{}{}", key_reference(key), value, unit, was_given ? "" : " (default)");
  };
  std::string inputs = fall ? input("height", s.height_m, " m", given.height) + ", " +
                                  input("gravity", s.gravity_mps2, " m/s^2", given.gravity)
                            : input("impact-velocity", v0, " m/s", true);
  inputs += ", " + input("mass", m, " kg", given.mass) + ", " + input("ball-radius", R, " m", given.ball_radius) +
            fmt::format(" and K = {:.4g} N/m^1.5 from", K);
  for (const auto& [option, value, was_given] :
       {std::tuple{"ball-E", s.ball.E_Pa, given.ball_E}, std::tuple{"rod-E", s.rod.E_Pa, given.rod_E},
        std::tuple{"ball-nu", s.ball.nu, given.ball_nu}, std::tuple{"rod-nu", s.rod.nu, given.rod_nu}})
    inputs += std::string(std::string_view(option) == "ball-E" ? " " : ", ") +
              input(option, value, std::string_view(option).ends_with("E") ? " Pa" : "", was_given);
  const std::string why =
      fmt::format("(with {}, the undamped Hertz deformation X = (5 m v0^2 / 4K)^(2/5) is {:.3g} m; {})", inputs, X,
                  too_large ? "at or above the ball radius the small-deformation Hertz contact does not hold"
                            : fmt::format("X >= {:g} m is required: below that, far under atomic dimensions, no "
                                          "continuum contact model applies",
                                          min_hertz_deformation_m));

  if (!fall) throw InvalidParameter("impact-velocity", format_value(v0), fmt::format("{} {:.4g} m/s {}", side, v_bound, why));
  if (given.height)
    throw InvalidParameter("height", format_value(s.height_m),
                           fmt::format("{} {:.4g} m {}", side, v_bound * v_bound / (2.0 * s.gravity_mps2), why));
  if (given.gravity)
    throw InvalidParameter("gravity", format_value(s.gravity_mps2),
                           fmt::format("{} {:.4g} m/s^2 {}", side, v_bound * v_bound / (2.0 * s.height_m), why));
  if (given.mass)
    throw InvalidParameter("mass", format_value(m), fmt::format("{} {:.4g} kg {}", side, m_bound, why));
  for (const auto& [option, value, was_given] :
       {std::tuple{"ball-radius", R, given.ball_radius}, std::tuple{"ball-E", s.ball.E_Pa, given.ball_E},
        std::tuple{"rod-E", s.rod.E_Pa, given.rod_E}, std::tuple{"ball-nu", s.ball.nu, given.ball_nu},
        std::tuple{"rod-nu", s.rod.nu, given.rod_nu}})
    if (was_given)
      throw InvalidParameter(option, format_value(value),
                             std::string("a value that, with the others, gives a Hertz deformation X ") +
                                 (too_large ? "below the ball radius " : "of at least 1e-12 m ") + why);
  throw InvalidParameter("height", format_value(s.height_m) + " (default)",
                         fmt::format("{} {:.4g} m {}", side, v_bound * v_bound / (2.0 * s.gravity_mps2), why));
}

const char* to_string(Accelerometer a) { return a == Accelerometer::top ? "top" : "bottom"; }

void validate(const ElasticRodSetup& s) {
  namespace p = elastic_rod_parameters;
  require_positive("rod length (Table 1)", s.length_m, "m");
  require_positive("rod diameter (Table 1)", s.diameter_m, "m");
  require_in_range(p::elements, s.elements);
  require_in_range(p::rod_damping_ratio, s.rod_damping_ratio);
  require_in_range(p::hemisphere_mass, s.hemisphere_mass_kg);
  require_in_range(p::cell_stiffness, s.cell_stiffness_N_per_m);
  require_in_range(p::cell_damping_ratio, s.cell_damping_ratio);
}

double hertz_stiffness(const DropTestSetup& s) { return hertz_stiffness(s.ball_radius_m, s.ball, s.rod); }

double approach_speed(const DropTestSetup& s) {
  return s.impact_velocity_mps ? *s.impact_velocity_mps : std::sqrt(2.0 * s.gravity_mps2 * s.height_m);
}

}  // namespace hertzdash
