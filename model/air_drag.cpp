#include "hertzdash/model/air_drag.hpp"

#include <cmath>
#include <numbers>

namespace hertzdash {

void validate(const AirDrag& d) {
  require_in_range(air_drag_parameters::air_density, d.air_density_kg_per_m3);
  require_in_range(air_drag_parameters::drag_coefficient, d.drag_coefficient);
}

double terminal_speed_mps(const AirDrag& d, double mass_kg, double radius_m, double gravity_mps2) {
  if (!d.active()) return std::numeric_limits<double>::infinity();
  const double area_m2 = std::numbers::pi * radius_m * radius_m;
  return std::sqrt(2.0 * mass_kg * gravity_mps2 / (d.air_density_kg_per_m3 * d.drag_coefficient * area_m2));
}

Fall fall_from_rest(double distance_m, double g, double v_t) {
  if (std::isinf(v_t)) {
    const double v = std::sqrt(2.0 * g * distance_m);
    return {v / g, v};
  }
  // v = v_t sqrt(1 - exp(-2 g D / v_t^2)), t = (v_t / g) atanh(v / v_t): -expm1 keeps the
  // small-D (or large-v_t) limit sqrt(2 g D) exact to rounding.
  const double v = v_t * std::sqrt(-std::expm1(-2.0 * g * distance_m / (v_t * v_t)));
  return {v_t / g * std::atanh(v / v_t), v};
}

Rise rise_to_apex(double speed_mps, double g, double v_t) {
  if (std::isinf(v_t)) return {speed_mps / g, speed_mps * speed_mps / (2.0 * g)};
  const double u = speed_mps / v_t;
  return {v_t / g * std::atan(u), v_t * v_t / (2.0 * g) * std::log1p(u * u)};
}

std::optional<ReturnFlight> return_flight(double v_r, double x_s, double g, double v_t) {
  if (std::isinf(v_t)) {  // the vacuum's exact forms (the bounce tests compare speeds exactly)
    const double v_squared = v_r * v_r - 2.0 * g * x_s;
    if (!(v_squared > 0)) return std::nullopt;
    const double v = std::sqrt(v_squared);
    return ReturnFlight{(v_r + v) / g, v};
  }
  const Rise rise = rise_to_apex(v_r, g, v_t);
  if (!(rise.height_m > x_s)) return std::nullopt;
  const Fall fall = fall_from_rest(rise.height_m - x_s, g, v_t);
  return ReturnFlight{rise.time_s + fall.time_s, fall.speed_mps};
}

}  // namespace hertzdash
