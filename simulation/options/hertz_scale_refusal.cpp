#include "hertzdash/simulation/options/hertz_scale_refusal.hpp"

#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

namespace {

struct ScaleInput {
  const char* key;
  double value;
  const char* unit;
  bool given;
};

std::string listed(const ScaleInput& i) {
  return fmt::format("{} {:g}{}{}", is_parameter_key(i.key) ? key_reference(i.key) : std::string(i.key), i.value,
                     i.unit, i.given ? "" : " (default)");
}

}  // namespace

void refuse_hertz_scale(const DropTestSetup& s, const HertzScale& h, const RunOptions& o) {
  const bool fall = !s.impact_velocity_mps;
  const double v0 = h.approach_speed_mps, g = s.gravity_mps2;
  const ScaleInput height{"height", s.height_m, " m", o.height_m.has_value()},
      gravity{"gravity", g, " m/s^2", o.gravity_mps2.has_value()},
      velocity{o.impact_velocity_origin.empty() ? "impact-velocity" : o.impact_velocity_origin.c_str(), v0, " m/s", true},
      mass{"mass", s.mass_kg, " kg", o.mass_kg.has_value()},
      radius{"ball-radius", s.ball_radius_m, " m", o.ball_radius_m.has_value()};
  // The inputs of K, eq. (3), in the order a refusal names them.
  const std::vector<ScaleInput> moduli{{"ball-E", s.ball.E_Pa, " Pa", o.ball_E_Pa.has_value()},
                                       {"rod-E", s.rod.E_Pa, " Pa", o.rod_E_Pa.has_value()},
                                       {"ball-nu", s.ball.nu, "", o.ball_nu.has_value()},
                                       {"rod-nu", s.rod.nu, "", o.rod_nu.has_value()}};

  std::string inputs = fall ? listed(height) + ", " + listed(gravity) : listed(velocity);
  inputs += ", " + listed(mass) + ", " + listed(radius) +
            fmt::format(" and K = {:.4g} N/m^1.5 from", h.stiffness_N_per_m1_5);
  for (std::size_t i = 0; i < moduli.size(); ++i) inputs += (i == 0 ? " " : ", ") + listed(moduli[i]);
  const std::string why = fmt::format("(with {}, the undamped Hertz deformation X = (5 m v0^2 / 4K)^(2/5) is {:.3g} m; {})",
                                      inputs, h.deformation_m, h.reason());
  const char* side = h.too_large ? "below" : "at least";
  const double v_bound = h.speed_at_bound_mps;

  const std::string speed_bound = fmt::format("{} {:.4g} m/s {}", side, v_bound, why);
  if (!fall && o.impact_velocity_origin.empty()) throw InvalidParameter("impact-velocity", format_value(v0), speed_bound);
  if (fall && o.air_density_kg_per_m3 && s.air_drag.active()) {  // the drag, not the height, slows the fall
    const double free_fall = std::sqrt(2.0 * g * s.height_m);
    if (h.too_large ? free_fall < v_bound : free_fall >= v_bound)
      throw InvalidParameter("air-density", format_value(*o.air_density_kg_per_m3),
                             fmt::format("a value at which the fall still reaches the ball with a speed {} {:.4g} m/s (it would "
                                         "without drag, at {:.4g} m/s; with the drag it arrives at {:.3g} m/s) {}",
                                         side, v_bound, free_fall, v0, why));
  }
  if (fall && height.given)
    throw InvalidParameter("height", format_value(s.height_m),
                           fmt::format("{} {:.4g} m {}", side, v_bound * v_bound / (2.0 * g), why));
  if (fall && gravity.given)
    throw InvalidParameter("gravity", format_value(g),
                           fmt::format("{} {:.4g} m/s^2 {}", side, v_bound * v_bound / (2.0 * s.height_m), why));
  if (mass.given)
    throw InvalidParameter("mass", format_value(s.mass_kg), fmt::format("{} {:.4g} kg {}", side, h.mass_at_bound_kg, why));
  std::vector<ScaleInput> others{radius};
  others.insert(others.end(), moduli.begin(), moduli.end());
  for (const ScaleInput& i : others)
    if (i.given)
      throw InvalidParameter(i.key, format_value(i.value),
                             std::string("a value that, with the others, gives a Hertz deformation X ") +
                                 (h.too_large ? "below the ball radius " : "of at least 1e-12 m ") + why);
  if (!fall) throw InvalidParameter(o.impact_velocity_origin, format_value(v0), speed_bound);  // no input's fault
  throw InvalidParameter("height", format_value(s.height_m) + " (default)",
                         fmt::format("{} {:.4g} m {}", side, v_bound * v_bound / (2.0 * g), why));
}

}  // namespace hertzdash
