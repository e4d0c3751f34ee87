#include "hertzdash/model/drop_test_setup.hpp"

#include "hertzdash/model/drop_test_parameters.hpp"

#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

namespace hertzdash {

void validate(const DropTestSetup& s) {
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
  validate(s.air_drag);
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
  validate_hertz_scale(s);
}

HertzScale hertz_scale(const DropTestSetup& s) {
  HertzScale h{};
  h.stiffness_N_per_m1_5 = hertz_stiffness(s);
  h.approach_speed_mps = approach_speed(s);
  const double K = h.stiffness_N_per_m1_5, v0 = h.approach_speed_mps, m = s.mass_kg;
  h.deformation_m = undamped_hertz_impact(K, m, v0).max_deformation_m;
  h.too_large = !(h.deformation_m < s.ball_radius_m);
  h.too_small = !h.too_large && h.deformation_m < min_hertz_deformation_m;
  h.bound_m = h.too_small ? min_hertz_deformation_m : s.ball_radius_m;
  // X^{5/2} = 5 m v0^2 / (4 K) at X = bound_m, solved for v0 and for m.
  h.speed_at_bound_mps = std::sqrt(4.0 * K * std::pow(h.bound_m, 2.5) / (5.0 * m));
  h.mass_at_bound_kg = 4.0 * K * std::pow(h.bound_m, 2.5) / (5.0 * v0 * v0);
  return h;
}

std::string HertzScale::reason() const {
  return too_large ? "at or above the ball radius the small-deformation Hertz contact does not hold"
                   : fmt::format("X >= {:g} m is required: below that, far under atomic dimensions, no continuum "
                                 "contact model applies",
                                 min_hertz_deformation_m);
}

void validate_hertz_scale(const DropTestSetup& s) {
  const HertzScale h = hertz_scale(s);
  if (h.within()) return;
  const char* side = h.too_large ? "below" : "at least";
  const std::string why = fmt::format(
      "(with m = {:g} kg, R = {:g} m and K = {:.4g} N/m^1.5, the undamped Hertz deformation X = (5 m v0^2 / 4K)^(2/5) "
      "is {:.3g} m at v0 = {:g} m/s; {})",
      s.mass_kg, s.ball_radius_m, h.stiffness_N_per_m1_5, h.deformation_m, h.approach_speed_mps, h.reason());
  if (s.impact_velocity_mps)
    throw HertzScaleRefused("impact-velocity", format_value(*s.impact_velocity_mps),
                            fmt::format("{} {:.4g} m/s {}", side, h.speed_at_bound_mps, why), h);
  throw HertzScaleRefused("height", format_value(s.height_m),
                          fmt::format("{} {:.4g} m {}", side,
                                      h.speed_at_bound_mps * h.speed_at_bound_mps / (2.0 * s.gravity_mps2), why),
                          h);
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
  if (s.impact_velocity_mps) return *s.impact_velocity_mps;
  const double v_t = terminal_speed_mps(s.air_drag, s.mass_kg, s.ball_radius_m, s.gravity_mps2);
  return fall_from_rest(s.height_m, s.gravity_mps2, v_t).speed_mps;  // sqrt(2 g h) without air
}

}  // namespace hertzdash
