#pragma once
// Mindlin's no-slip tangential stiffness with a Coulomb limit: k_t = 8 G* a, a = sqrt(R* x) the
// contact radius (Mindlin, J. Appl. Mech. 16 (1949) 259), the tangential spring of the DEM codes'
// Hertz-Mindlin contact, here incremental (dT = -k_t ds) as YADE's Law2_ScGeom_MindlinPhys_Mindlin
// and Kratos write it; LAMMPS's `tangential mindlin` and LIGGGHTS's keep the displacement instead.
// Its onset criterion of sliding is Maw, Barber and Fawcett's (1976). An incremental spring whose
// stiffness falls while it unloads (the overlap shrinking) returns more than it stored: at large mu
// and small angles the sphere can leave with a little more tangential energy (the rig warns);
// mindlin-rescale (model/tangential/mindlin_rescale.hpp) is the same spring without that defect.
#include "hertzdash/model/tangential/tangential_model.hpp"

#include <cmath>

namespace hertzdash {

/// Mindlin's no-slip stiffness k_t = 8 G* a, a = sqrt(R* x) [N/m].
inline double mindlin_stiffness_N_per_m(const TangentialPair& p, const TangentialState& s) {
  return 8 * p.shear_modulus_Pa * std::sqrt(p.radius_m * s.overlap_m);
}

inline constexpr TangentialModelInfo mindlin_no_slip{
    .name = "mindlin-no-slip",
    .citation = "Mindlin, J. Appl. Mech. 16 (1949) 259; the DEM codes' Hertz-Mindlin",
    .formula = "k_t = 8 G* sqrt(R* x), |T| <= mu F_n",
    .stiffness_N_per_m = mindlin_stiffness_N_per_m};

}  // namespace hertzdash
