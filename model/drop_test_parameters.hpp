#pragma once
// The inputs of the paper's drop test (Fig. 4): the falling body, the sphere it strikes, the
// flat, gravity and the impact, each declared once (model/parameter.hpp). The paper's two
// bodies are the sphere (s) and the wall (w): in its drop test the falling body is the rod, whose
// flat end face is the wall, and the sphere is the nylon hemisphere ("ball"). A ball dropped on
// a flat is stated with the same inputs: its mass is `mass`, its material and radius the
// sphere's (`ball-*`), the plate's material the flat's (`rod-E`, `rod-nu`); with one body fixed,
// the contact depends only on the mass that moves, R and the pair's E* (docs/balls.md). The defaults are the
// paper's Tables 1-3 and the assumptions of data/assumptions.csv, read by
// simulation/paper/paper_parameters.hpp.
#include "hertzdash/model/parameter.hpp"

namespace hertzdash::drop_test_parameters {

using R = NumberRange;
using T = ParameterType;

inline constexpr ParameterDecl height{
    .key = "height", .unit = "m", .column_unit = "m", .range = R::non_negative(), .default_value = "0.02",
    .default_source = "the paper's drop height (Figs. 5, 6)",
    .help = "Drop height h [m] of the falling body, free fall from rest", .fittable = true};
inline constexpr ParameterDecl impact_velocity{
    .key = "impact-velocity", .unit = "m/s", .column_unit = "mps", .range = R::positive(),
    .default_value = "sqrt(2 g h)", .default_source = "computed from `height` and `gravity`",
    .help = "Approach speed at contact onset [m/s], instead of `height`", .fittable = true};
inline constexpr ParameterDecl mass{
    .key = "mass", .unit = "kg", .column_unit = "kg", .range = R::positive(), .default_value = "Table 1",
    .default_source = "the paper's Table 1 (the rod's mass)",
    .help = "Mass of the falling body [kg]: the paper's rod, or a dropped ball",
    .fittable = true};
inline constexpr ParameterDecl density{
    .key = "density", .unit = "kg/m^3", .column_unit = "kg_per_m3", .range = R::positive(), .default_value = "none",
    .default_source = "not used: the falling body's mass is `mass` unless this is given",
    .help = "Density of a dropped ball [kg/m^3], instead of `mass`: the falling body is the sphere, of mass (4/3) pi "
            "R^3 rho (R `ball-radius`)"};
inline constexpr ParameterDecl restitution{
    .key = "restitution", .range = R::open_closed(0, 1), .default_value = "Table 2",
    .default_source = "the paper's Table 2 (measured from bounce intervals)",
    .help = "Input coefficient of restitution e in (0,1] (1 = undamped)", .fittable = true};
inline constexpr ParameterDecl ball_E{
    .key = "ball-E", .unit = "Pa", .column_unit = "Pa", .range = R::positive(), .default_value = "2.0e9",
    .default_source = "assumed, middle of Table 3's catalogue range (data/assumptions.csv)",
    .help = "Young's modulus of the sphere [Pa]: the paper's nylon hemisphere, or a dropped ball",
    .fittable = true};
inline constexpr ParameterDecl ball_nu{
    .key = "ball-nu", .range = R::open(-1, 0.5), .default_value = "0.40",
    .default_source = "assumed (data/assumptions.csv)",
    .help = "Poisson ratio of the sphere (the hemisphere, or a dropped ball)", .fittable = true};
inline constexpr ParameterDecl ball_radius{
    .key = "ball-radius", .unit = "m", .column_unit = "m", .range = R::positive(), .default_value = "0.0127",
    .default_source = "half the 1-inch ball of Table 1 (data/assumptions.csv)", .help = "Radius R of the sphere [m]",
    .fittable = true};
inline constexpr ParameterDecl ball_yield_stress{
    .key = "ball-yield-stress", .unit = "Pa", .column_unit = "Pa", .range = R::positive_or_infinite(),
    .default_value = "7.0e7", .default_source = "assumed, unfilled nylon datasheets (data/assumptions.csv), for the paper's "
                                                "hemisphere only: inf (no check) for a sphere of the user's own (`ball-E`, `ball-nu` and "
                                                "`ball-radius` all given, or `density`)",
    .help = "Yield stress Y of the sphere [Pa]; a Hertz peak pressure above the onset of yield (Y times a factor "
            "of `ball-nu`, Johnson; model/hertz.hpp) is flagged; inf: no check"};
inline constexpr ParameterDecl rod_E{
    .key = "rod-E", .unit = "Pa", .column_unit = "Pa", .range = R::positive_or_infinite(),
    .default_value = "Table 3", .default_source = "the paper's Table 3",
    .help = "Young's modulus of the flat [Pa]: the paper's rod end face, or the plate a ball falls on; inf for a "
            "rigid flat", .fittable = true};
inline constexpr ParameterDecl rod_nu{
    .key = "rod-nu", .range = R::open(-1, 0.5), .default_value = "0.30 steel, 0.33 duralumin",
    .default_source = "assumed (data/assumptions.csv)",
    .help = "Poisson ratio of the flat (the rod end face, or the plate)",
    .fittable = true};
inline constexpr ParameterDecl gravity{
    .key = "gravity", .unit = "m/s^2", .column_unit = "mps2", .range = R::non_negative(), .default_value = "9.80665",
    .default_source = "standard gravity (data/assumptions.csv)", .help = "Gravity g [m/s^2], 0 allowed",
    .fittable = true};
inline constexpr ParameterDecl no_tension{
    .key = "no-tension", .type = T::flag, .default_value = "off", .default_source = "the paper's model",
    .help = "Clamp the contact force at >= 0; contact ends where it reaches zero"};

/// The drop test's inputs, in the order of the options.
inline constexpr ParameterDecl all[] = {height, impact_velocity, mass,   density, restitution, ball_E,    ball_nu,
                                        ball_radius, ball_yield_stress, rod_E, rod_nu, gravity, no_tension};

}  // namespace hertzdash::drop_test_parameters
