#pragma once
// Quadratic air drag on the falling body in flight, and the flights it gives in closed form.
//
// Drag. F_d = (1/2) rho C_d A v^2 opposing the velocity, A = pi R^2 the frontal area of the
// sphere of radius R (`ball-radius`: a ball that falls is the sphere; for the paper's rod, whose
// flat end leads, it is the sphere the rod strikes, an approximation that the terminal speed
// below shows negligible for the rod). With the terminal speed
//   v_t = sqrt(2 m g / (rho C_d A)),
// the vertical motion is u'' = g (1 - v^2 / v_t^2) falling and u'' = -g (1 + v^2 / v_t^2) rising,
// whose closed forms (e.g. Landau and Lifshitz's exercise; any mechanics text) are:
//   rising from speed v_r: time to the apex t_up = (v_t / g) atan(v_r / v_t),
//                          height of the apex   H = (v_t^2 / (2 g)) ln(1 + v_r^2 / v_t^2);
//   falling from rest through D: speed v = v_t sqrt(1 - exp(-2 g D / v_t^2)),
//                                time  t_down = (v_t / g) atanh(v / v_t).
// Without air (rho = 0, v_t infinite) they are the vacuum parabola's: t_up = v_r / g,
// H = v_r^2 / (2 g), v = sqrt(2 g D), t_down = v / g; the forms above are evaluated with atan,
// log1p, expm1 and atanh so that they reach that limit without cancellation as v_t grows.
//
// Scale. A 2.7 g ping-pong ball (R = 20 mm, C_d = 0.47, rho = 1.204 kg/m^3) has v_t = 8.6 m/s:
// at 2 m/s the drag is (2 / 8.6)^2 = 5 % of its weight. The paper's 0.778 kg steel rod (its
// 25 mm face about the area of the 12.7 mm sphere) has v_t = 230 m/s: at its 0.63 m/s impacts,
// 7e-6 of its weight.
//
// During contact drag is left out: over a contact time t_c it changes the speed by at most
// g (v0 / v_t)^2 t_c, beside the contact's 2 v0 (docs/bounce.md states the ratio for a run).
#include "hertzdash/model/parameter.hpp"

#include <cmath>
#include <limits>
#include <optional>

namespace hertzdash {

/// The air around the falling body: constant for a run.
struct AirDrag {
  double air_density_kg_per_m3 = 0;  ///< rho [kg/m^3] >= 0; 0: no drag (vacuum flights)
  double drag_coefficient = 0.47;    ///< C_d > 0, on the frontal area pi R^2
  bool active() const { return air_density_kg_per_m3 > 0; }
};

namespace air_drag_parameters {

inline constexpr ParameterDecl air_density{
    .key = "air-density", .unit = "kg/m^3", .column_unit = "kg_per_m3", .range = NumberRange::non_negative(),
    .default_value = "0", .default_source = "no drag; air at 20 C and 1 atm is 1.204",
    .help = "Density rho [kg/m^3] of the air the body flies through: quadratic drag (1/2) rho C_d pi R^2 v^2 in "
            "every flight, R `ball-radius` (model/air_drag.hpp)"};
inline constexpr ParameterDecl drag_coefficient{
    .key = "drag-coefficient", .range = NumberRange::positive(), .default_value = "0.47",
    .default_source = "a smooth sphere at Reynolds numbers 1e3-2e5 (Hoerner, Fluid-Dynamic Drag, 1965)",
    .help = "Drag coefficient C_d on the frontal area pi R^2, with `air-density`"};

inline constexpr ParameterDecl all[] = {air_density, drag_coefficient};

}  // namespace air_drag_parameters

/// Throws InvalidParameter naming `air-density` or `drag-coefficient`.
void validate(const AirDrag& d);

/// Air at 20 C and 1 atm [kg/m^3]: what a verdict takes for the air a recording flew through
/// when no --air-density is given (simulation/reports/fit_verdict.hpp).
inline constexpr double standard_air_density_kg_per_m3 = 1.204;

/// v_t = sqrt(2 m g / (rho C_d pi R^2)) [m/s]; +inf without air or without gravity's pull
/// being resisted (rho = 0). mass_kg, radius_m, gravity_mps2 > 0.
double terminal_speed_mps(const AirDrag& d, double mass_kg, double radius_m, double gravity_mps2);

/// A fall from rest through `distance_m` >= 0 at terminal speed v_t (+inf: vacuum).
struct Fall {
  double time_s = 0;
  double speed_mps = 0;
};
Fall fall_from_rest(double distance_m, double gravity_mps2, double terminal_speed_mps);

/// A rise from speed `speed_mps` >= 0 to the apex.
struct Rise {
  double time_s = 0;
  double height_m = 0;
};
Rise rise_to_apex(double speed_mps, double gravity_mps2, double terminal_speed_mps);

/// Where a body is a time `tau` >= 0 after leaving upward at `speed_mps`: its height above the
/// start [m] and its upward velocity [m/s]. Rising (tau <= t_up), with phi0 = atan(v_r / v_t):
/// y = (v_t^2 / g) ln(cos(phi0 - g tau / v_t) / cos phi0), u = v_t tan(phi0 - g tau / v_t);
/// then falling from the apex H for s = tau - t_up: y = H - (v_t^2 / g) ln cosh(g s / v_t),
/// u = -v_t tanh(g s / v_t). In vacuum y = v_r tau - g tau^2 / 2, u = v_r - g tau.
struct FlightPoint {
  double height_m = 0;
  double upward_velocity_mps = 0;
};
FlightPoint flight_point(double speed_mps, double tau_s, double gravity_mps2, double terminal_speed_mps);

/// The flight of a body that leaves the contact at speed `rebound_speed_mps` from a depth
/// `depth_m` >= 0 below the level where contact begins (x_s > 0 where a tension clamp ended the
/// contact), rises to its apex and falls back to that level: its duration and landing speed;
/// empty when the apex does not clear the level. In vacuum exactly v = sqrt(v_r^2 - 2 g x_s),
/// t = (v_r + v) / g (v = v_r for x_s = 0); with drag rise_to_apex then fall_from_rest through
/// H - x_s, which for x_s = 0 gives 1 / v^2 = 1 / v_r^2 + 1 / v_t^2.
struct ReturnFlight {
  double time_s = 0;
  double landing_speed_mps = 0;
};
std::optional<ReturnFlight> return_flight(double rebound_speed_mps, double depth_m, double gravity_mps2,
                                          double terminal_speed_mps);

}  // namespace hertzdash
