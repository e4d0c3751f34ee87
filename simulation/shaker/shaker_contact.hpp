#pragma once
// The soft contact of the shaker: one contact of the body with the moving wall, integrated in
// regularising variables with the wall's acceleration as a prescribed forcing
// (model/shaken_contact.hpp), with any registered damping law and any integrator row in
// regularising variables (dopri5-regularized, cvode-regularized, gbs8-regularized,
// taylor-regularized; the table's fall-back for a law without the polynomial form). The rows in
// physical variables (euler, rk4, cvode, dopri5) are refused: their system is the drop test's,
// which has no wall motion, and the tension clamp and the elastic rod (which need them) with it.
//
// One ShakerContact per run (or thread): it keeps the law's type, the integrator row and its
// workspace (CVODE's memory reinitialised, not rebuilt), so that a contact allocates nothing.
// Each registered law's contact is compiled in a translation unit of its own, generated from
// shaker_contact_instantiation.cpp.in as the law's impact runs are (simulation/run/law_runs.hpp).
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/wall_motion.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <memory>
#include <string_view>

namespace hertzdash {

/// What one contact gave.
struct ShakerContactOutcome {
  bool separated = false;        ///< false: still in contact at the observation time
  double contact_time_s = 0;     ///< onset to separation (or to the observation time) [s]
  double rebound_speed_mps = 0;  ///< the relative speed x' at separation, upward [m/s]
  double peak_force_N = 0;       ///< the largest contact force [N]
  IntegrationStats work;
};

class ShakerContact {
 public:
  virtual ~ShakerContact() = default;
  /// The contact beginning at t_onset_s [s] at relative impact speed v0_mps > 0 [m/s], followed
  /// for at most t_obs_s [s].
  virtual ShakerContactOutcome run(double t_onset_s, double v0_mps, double t_obs_s) = 0;
  /// The integrator row that runs the contacts (after the table's fall-back).
  virtual IntegratorKind integrator_used() const = 0;
};

/// The contacts of the registered law `law` on the validated `setup` (its body, contact, e,
/// gravity; not its height) with the wall `wall`. InvalidParameter("integrator", ...) for a
/// row in physical variables, ("no-tension", ...) and ("rod-model", ...) for what needs one.
std::unique_ptr<ShakerContact> make_shaker_contact(std::string_view law, const DropTestSetup& setup,
                                                   const SolverSettings& solver, const HarmonicWallMotion& wall);

/// The same for a law known at compile time; compiled once per registered law.
template <DampingLaw Law>
std::unique_ptr<ShakerContact> make_shaker_contact_of(const DropTestSetup& setup, const SolverSettings& solver,
                                                      const HarmonicWallMotion& wall);

}  // namespace hertzdash
