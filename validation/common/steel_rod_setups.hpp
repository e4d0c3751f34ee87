#pragma once
// The set-ups the orbit studies and their tests share: the paper's steel rod (Table 1, dropped
// from 20 mm) with a chosen restitution, and the same rod on a steel hemisphere with both moduli
// multiplied by k, a stiff pair whose contact time falls as k^{-2/5} (the rigid limit of a soft
// contact, validation/orbit_soft_rigid, tests/test_orbit_soft.cpp), and the contacts' integrator
// at a tight tolerance.
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

namespace hertzdash {

/// The paper's steel rod with restitution e.
inline DropTestSetup paper_steel_rod(double e) {
  DropTestSetup rod = paper_setup(load_paper_parameters(), "steel", 0.02);
  rod.restitution = e;
  return rod;
}

/// The steel rod on a steel hemisphere, E = 200 GPa x k and nu = 0.3 for both, restitution e.
inline DropTestSetup stiffened_steel_pair(double k, double e) {
  DropTestSetup s = paper_steel_rod(e);
  s.ball = {2.0e11 * k, 0.3};
  s.rod = {2.0e11 * k, 0.3};
  return s;
}

/// gbs8 in regularising variables at relative tolerance rtol.
inline SolverSettings gbs8_regularized_solver(double rtol) {
  SolverSettings s;
  s.integrator = IntegratorKind::gbs8_regularized;
  s.rtol = rtol;
  return s;
}

}  // namespace hertzdash
