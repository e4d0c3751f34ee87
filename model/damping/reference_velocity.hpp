#pragma once
// The input every law with a material constant shares (MaterialTimeConstantLaw,
// model/damping/damping_law.hpp): the speed at which the simulator calibrates that constant so that
// the law's restitution is the input e (simulation/run/viscous_time_constant.hpp). Declared once;
// each such law lists it among its `parameters`, so the option's readers are those laws.
#include "hertzdash/model/parameter.hpp"

namespace hertzdash {

inline constexpr ParameterDecl reference_velocity_parameter{
    .key = "reference-velocity",
    .unit = "m/s",
    .column_unit = "mps",
    .range = NumberRange::positive(),
    .default_value = "the approach speed",
    .default_source = "computed: the approach speed of the run's first impact",
    .help = "Approach speed [m/s] > 0 at which the law's restitution is the input e (the calibration of its material "
            "constant)"};

}  // namespace hertzdash
