#pragma once
// A linear tangential spring with a Coulomb limit: k_t constant (Cundall and Strack,
// Geotechnique 29 (1979) 47), the linear DEM contact's tangential spring (LAMMPS `tangential
// linear_history`).
#include "hertzdash/model/tangential/tangential_model.hpp"

namespace hertzdash {

inline constexpr TangentialModelInfo linear_spring{
    .name = "linear-spring",
    .citation = "Cundall and Strack, Geotechnique 29 (1979) 47",
    .formula = "k_t constant, |T| <= mu F_n",
    .stiffness_N_per_m = [](const TangentialPair& p, const TangentialState&) { return p.linear_stiffness_N_per_m; }};

}  // namespace hertzdash
