#pragma once
// The glass beads of the engine export (docs/engines.md): R = 1 mm, E = 63 GPa, nu = 0.22,
// 2500 kg/m^3 (m = (4/3) pi R^3 rho), on steel (200 GPa, 0.3), e = 0.9 at 1 m/s, no gravity.
// Shared by validation/engine_conformance and tests/test_engine_export.cpp.
#include "hertzdash/model/drop_test_setup.hpp"

#include <numbers>

namespace hertzdash {

inline DropTestSetup glass_beads_on_steel() {
  DropTestSetup s{};
  s.mass_kg = 2500 * 4.0 / 3.0 * std::numbers::pi * 1e-9;
  s.ball_radius_m = 1e-3;
  s.ball = {63e9, 0.22};
  s.rod = {200e9, 0.3};
  s.restitution = 0.9;
  s.impact_velocity_mps = 1.0;
  s.gravity_mps2 = 0;
  return s;
}

}  // namespace hertzdash
