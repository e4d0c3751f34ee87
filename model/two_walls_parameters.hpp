#pragma once
// The inputs of a body between two walls (simulation/shaker/two_walls.hpp): the box's clearance,
// the rig (a harmonically driven box, or the impact damper: the box on a primary oscillator under
// a harmonic force), and the primary, each declared once (model/parameter.hpp). The body, the
// contact, the law and e are the drop test's; the drive's frequency, the box's amplitude or
// gamma (with a default of its own), the impact counts and the impact model are the shaker's
// (model/shaker_parameters.hpp).
#include "hertzdash/model/parameter.hpp"
#include "hertzdash/model/shaker_parameters.hpp"

namespace hertzdash::two_walls_parameters {

using R = NumberRange;
using T = ParameterType;

inline constexpr ParameterDecl rig{
    .key = "rig", .type = T::text, .choices = "box, damper", .default_value = "box", .default_source = "chosen",
    .help = "box: the box moves as s(t) = A sin(2 pi f t); damper: the box is the mass of a primary oscillator "
            "driven by the force `force-amplitude` sin(2 pi f t) (the impact damper)"};
inline constexpr ParameterDecl gap{
    .key = "gap", .unit = "m", .column_unit = "m", .range = R::positive(), .default_value = "0.01",
    .default_number = 0.01, .default_source = "chosen",
    .help = "Clearance of the box: the body's free travel between floor and ceiling [m]"};
inline constexpr ParameterDecl primary_mass{
    .key = "primary-mass", .unit = "kg", .column_unit = "kg", .range = R::positive(), .default_value = "10",
    .default_number = 10.0, .default_source = "chosen: mass ratio 0.078 with the paper's steel rod (0.778 kg)",
    .help = "Mass M of the primary oscillator, the box included [kg] (`rig` damper)"};
inline constexpr ParameterDecl primary_stiffness{
    .key = "primary-stiffness", .unit = "N/m", .column_unit = "N_per_m", .range = R::positive(),
    .default_value = "157914", .default_number = 157914.0,
    .default_source = "chosen: natural frequency 20 Hz with the default `primary-mass`",
    .help = "Stiffness k of the primary's spring [N/m] (`rig` damper)"};
inline constexpr ParameterDecl primary_damping_ratio{
    .key = "primary-damping-ratio", .range = R::closed_open(0, 1), .default_value = "0.02", .default_number = 0.02,
    .default_source = "chosen: a lightly damped structure",
    .help = "Damping ratio of the primary, c = 2 zeta sqrt(k M), in [0, 1) (`rig` damper)"};
inline constexpr ParameterDecl force_amplitude{
    .key = "force-amplitude", .unit = "N", .column_unit = "N", .range = R::non_negative(), .default_value = "100",
    .default_number = 100.0, .default_source = "chosen: a bare resonant amplitude of 16 mm",
    .help = "Amplitude F0 of the harmonic force F0 sin(2 pi f t) on the primary [N] (`rig` damper)"};

inline constexpr ParameterDecl gamma = with_default(shaker_parameters::gamma, "1.3", 1.3, "chosen");

/// The two-wall inputs, in the order of the options.
inline constexpr ParameterDecl all[] = {rig, gap, primary_mass, primary_stiffness, primary_damping_ratio,
                                        force_amplitude};

}  // namespace hertzdash::two_walls_parameters
