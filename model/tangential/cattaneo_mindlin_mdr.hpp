#pragma once
// Cattaneo and Mindlin's partial slip with Coulomb's law at every point of the contact: Maw, Barber
// and Fawcett's theory of the elastic oblique impact (Wear 38 (1976) 101), computed by the method
// of dimensionality reduction (Popov and Hess 2015) in model/oblique_contact_mdr.hpp. Unlike the
// springs under one Coulomb cone, the edge of the contact, where the pressure vanishes, slips from
// the first instant, and a shrinking contact releases the force its edge carried; while every
// point sticks the contact is Mindlin's no-slip spring k_t = 8 G* a.
#include "hertzdash/model/tangential/mindlin_no_slip.hpp"

namespace hertzdash {

inline constexpr TangentialModelInfo cattaneo_mindlin_mdr{
    .name = "cattaneo-mindlin-mdr",
    .citation = "Maw, Barber and Fawcett, Wear 38 (1976) 101; Popov and Hess, Method of Dimensionality Reduction (2015)",
    .formula = "cells of stiffness 8 G* dl on xi in [0, a], each under mu F_n W_i/W, W_i = int (x - xi^2/R) dxi",
    .stiffness_N_per_m = mindlin_stiffness_N_per_m,
    .resolves_contact_area = true};

}  // namespace hertzdash
