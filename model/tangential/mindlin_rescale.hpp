#pragma once
// Mindlin's no-slip spring rescaled with the contact radius while the overlap falls: dT/dt =
// -8 G* a s + T (da/dt)/a for da/dt < 0, a = sqrt(R* x), under the Coulomb cone (LAMMPS's
// `tangential mindlin_rescale/force`). With the stiffness proportional to a the rescaling makes
// U = T^2/(2 k_t) a bound on what the spring can return: loading adds the work done on it and
// takes T^2 (da/a)/(2 k_t) as the contact grows, unloading takes as much again, so the force's
// work on the sphere is never positive (mindlin-no-slip, the incremental spring as YADE and Kratos
// write it, returns more than it stored at large mu).
#include "hertzdash/model/tangential/mindlin_no_slip.hpp"

namespace hertzdash {

inline constexpr TangentialModelInfo mindlin_rescale{
    .name = "mindlin-rescale",
    .citation = "Mindlin, J. Appl. Mech. 16 (1949) 259; LAMMPS's pair granular, tangential mindlin_rescale/force",
    .formula = "k_t = 8 G* sqrt(R* x), T scaled with a while x falls, |T| <= mu F_n",
    .stiffness_N_per_m = mindlin_stiffness_N_per_m,
    .rescales_with_contact_radius = true};

}  // namespace hertzdash
