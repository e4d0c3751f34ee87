#pragma once
// The second sphere of a two-sphere contact, declared once for the rigs that take one (`spheres`
// head-on, `oblique` at an angle): its radius, modulus, Poisson ratio and mass (or density), each
// defaulting to the first sphere's, and the resolution of those inputs.
#include "hertzdash/model/two_spheres.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/rigs/rig.hpp"

#include <optional>

namespace hertzdash::second_sphere_inputs {

using R = NumberRange;
inline constexpr ParameterDecl radius{.key = "second-radius", .unit = "m", .column_unit = "m", .range = R::positive(),
    .default_value = "the first sphere's", .default_source = "`ball-radius`", .help = "Radius of the second sphere [m]"};
inline constexpr ParameterDecl E{.key = "second-E", .unit = "Pa", .column_unit = "Pa", .range = R::positive(),
    .default_value = "the first sphere's", .default_source = "`ball-E`", .help = "Young's modulus of the second sphere [Pa]"};
inline constexpr ParameterDecl nu{.key = "second-nu", .range = R::open(-1, 0.5), .default_value = "the first sphere's",
    .default_source = "`ball-nu`", .help = "Poisson ratio of the second sphere"};
inline constexpr ParameterDecl mass{.key = "second-mass", .unit = "kg", .column_unit = "kg", .range = R::positive(),
    .default_value = "the first sphere's", .default_source = "`mass` (or `density`)",
    .help = "Mass of the second sphere [kg]"};
inline constexpr ParameterDecl density{.key = "second-density", .unit = "kg/m^3", .column_unit = "kg_per_m3",
    .range = R::positive(), .default_value = "none", .default_source = "not used unless given",
    .help = "Density of the second sphere [kg/m^3], instead of `second-mass`"};

/// Refuses `second-density` beside `second-mass` (InvalidParameter).
void refuse_both_masses(const RigInputs& in);

/// The second sphere: each input given, else the first sphere's; its mass given, or from its
/// density, or from the first's density (`density`) at its own radius, or the first's mass.
Sphere resolve(const RunOptions& options, const RigInputs& in, const Sphere& first);

}  // namespace hertzdash::second_sphere_inputs
