#pragma once
// A contact as a discrete-element engine takes it (docs/engines.md): identical spheres, each of
// radius R, mass m (density rho = m / (4/3 pi R^3)), modulus E and Poisson ratio nu, and a flat
// wall (E_w, nu_w; E_w = inf: rigid), with a damping law and its constants; and hertzdash's own
// prediction of the two impacts an engine deck runs:
//   - sphere on sphere, head-on at relative speed v: one contact of reduced mass m/2, reduced
//     radius R/2 and E* = E / (2 (1 - nu^2)) (eq. 3 with both bodies of one material);
//   - sphere on the wall at speed v: mass m, radius R, E* = 1 / ((1 - nu^2)/E + (1 - nu_w^2)/E_w).
// Both are the paper's contact phase (no gravity, tension allowed: the engines allow it too).
// The law's constants are those of the sphere pair: a material time constant (kuwabara-kono's A)
// is calibrated once, on the pair at the reference speed (`reference-velocity`, default v), and the
// wall runs with the same A.
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <string>

namespace hertzdash {

/// The two impacts of an engine deck.
enum class EngineImpactKind { sphere_sphere, sphere_wall };
const char* to_string(EngineImpactKind k);

/// What one impact gives, by hertzdash or by an engine.
struct EngineImpactResult {
  double restitution = 0;     ///< rebound over approach speed (relative for the pair)
  double contact_time_s = 0;  ///< onset to separation [s]
  double peak_force_N = 0;    ///< largest contact force [N]
};

struct EngineContact {
  std::string law;                ///< the hertzdash damping law (registered name)
  double radius_m = 0;            ///< each sphere's radius R [m]
  double mass_kg = 0;             ///< each sphere's mass m [kg]
  Material sphere;                ///< each sphere's E [Pa] and nu
  Material wall;                  ///< the wall's E [Pa] (inf: rigid) and nu
  double restitution = 0;         ///< the law's input e (kuwabara-kono: e of the pair at speed_mps)
  DampingSettings damping;        ///< the law's settings
  /// The law's material constant (kuwabara-kono's A [s], lee-herrmann's gamma [1/s]), calibrated on
  /// the pair; 0 for a law without one.
  double material_constant = 0;
  /// Where it was calibrated: the pair's approach speed at which its e is `restitution` [m/s]
  /// (`reference-velocity`, default speed_mps); 0 for a law without a material constant.
  double calibration_speed_mps = 0;
  double speed_mps = 0;           ///< the approach speed of both impacts [m/s] (relative for the pair)
  /// The engine clamps the force at zero (YADE): the law runs with the tension clamp, and
  /// tsuji-dem at the zeta whose clamped e is `restitution` (zeta_from_clamped_restitution).
  bool tension_clamped = false;
  EngineImpactResult pair, on_wall;  ///< hertzdash's prediction of each impact

  double density_kg_per_m3() const;
  /// E* of the impact [Pa].
  double effective_modulus_Pa(EngineImpactKind k) const;
  /// m* [kg] and R* [m] of the impact: m/2 and R/2 for the pair, m and R on the wall.
  double reduced_mass_kg(EngineImpactKind k) const;
  double reduced_radius_m(EngineImpactKind k) const;
  const EngineImpactResult& predicted(EngineImpactKind k) const { return k == EngineImpactKind::sphere_sphere ? pair : on_wall; }
};

/// The contact of `setup` read as an engine's: the falling body's mass and the sphere's radius
/// and material are each sphere's (docs/balls.md: `--mass`, `--ball-radius`, `--ball-E`,
/// `--ball-nu`), the flat's (`--rod-E`, `--rod-nu`) the wall's, the approach speed the set-up's;
/// the law `law` is calibrated on the pair and both impacts are predicted (gbs8-regularized at
/// rtol 1e-10). `tension_clamped`: an engine that clamps the force at zero (EngineModel::
/// tension_clamped), for tsuji-dem alone (std::invalid_argument otherwise). Throws
/// InvalidParameter as the set-up's own checks do.
EngineContact make_engine_contact(const DropTestSetup& setup, const std::string& law, bool tension_clamped = false);

/// The same contact at another approach speed, its constants kept (kuwabara-kono's A is the
/// material's), both impacts predicted again.
EngineContact at_speed(const EngineContact& c, double speed_mps);

/// The hertzdash set-up of one impact of the contact (its contact phase: no gravity).
DropTestSetup engine_impact_setup(const EngineContact& c, EngineImpactKind k);

}  // namespace hertzdash
