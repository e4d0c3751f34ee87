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
  // v = v_t sqrt(1 - exp(-2a)), a = g D / v_t^2, and t = (v_t / g) acosh(exp(a))
  // = (v_t / g)(a + ln(1 + sqrt(1 - exp(-2a)))): -expm1 and log1p keep the small-a (large-v_t)
  // limit sqrt(2 D / g) to rounding, and the sum stays finite where v rounds to v_t (a > 19),
  // which atanh(v / v_t) would not.
  const double a = g * distance_m / (v_t * v_t), root = std::sqrt(-std::expm1(-2.0 * a));
  return {v_t / g * (a + std::log1p(root)), v_t * root};
}

Rise rise_to_apex(double speed_mps, double g, double v_t) {
  if (std::isinf(v_t)) return {speed_mps / g, speed_mps * speed_mps / (2.0 * g)};
  const double u = speed_mps / v_t;
  return {v_t / g * std::atan(u), v_t * v_t / (2.0 * g) * std::log1p(u * u)};
}

FlightPoint flight_point(double v_r, double tau, double g, double v_t) {
  if (std::isinf(v_t)) return {v_r * tau - 0.5 * g * tau * tau, v_r - g * tau};
  const Rise rise = rise_to_apex(v_r, g, v_t);
  const double scale = v_t * v_t / g;
  if (tau <= rise.time_s) {
    const double phi0 = std::atan(v_r / v_t), phi = phi0 - g * tau / v_t;
    return {scale * std::log(std::cos(phi) / std::cos(phi0)), v_t * std::tan(phi)};
  }
  const double w = g * (tau - rise.time_s) / v_t;  // ln cosh w = w + log1p(exp(-2w)) - ln 2: no overflow
  return {rise.height_m - scale * (w + std::log1p(std::exp(-2.0 * w)) - std::log(2.0)), -v_t * std::tanh(w)};
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
