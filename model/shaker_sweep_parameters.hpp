#pragma once
// The inputs of a shaker sweep (a bifurcation diagram: one parameter of the wall swept over a
// range, one independent shaker run per value; simulation/reports/shaker_sweep_report.hpp,
// docs/shaker.md), each declared once (model/parameter.hpp).
#include "hertzdash/model/parameter.hpp"

namespace hertzdash::shaker_sweep_parameters {

using R = NumberRange;
using T = ParameterType;

inline constexpr ParameterDecl sweep{
    .key = "sweep", .type = T::text, .choices = "KEY:FROM:TO:COUNT, KEY one of gamma, amplitude, frequency",
    .default_value = "none", .default_source = "one run",
    .help = "Sweep KEY linearly from FROM to TO in COUNT values (2 to 100000; the ends exact), one independent run "
            "per value on all cores (or MPI processes), one `csv` row per kept impact: a bifurcation diagram"};
inline constexpr ParameterDecl threads{
    .key = "threads", .range = R::integer(0, 4096), .default_value = "0", .default_number = 0,
    .default_source = "0: $HERTZDASH_THREADS if set, else the machine's cores",
    .help = "Threads of a `sweep` (the rows do not depend on it)"};

/// In the order of the options.
inline constexpr ParameterDecl all[] = {sweep, threads};

}  // namespace hertzdash::shaker_sweep_parameters
