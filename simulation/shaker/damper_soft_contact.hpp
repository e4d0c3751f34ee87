#pragma once
// The soft contact of the impact damper (simulation/shaker/two_walls.hpp): one contact of the
// body with the floor or the ceiling of the primary's box, the contact force acting on both
// (model/damper_contact.hpp), integrated with any registered law and any integrator row in
// regularising variables, as the shaker's contact is (simulation/shaker/shaker_contact.hpp: the
// rows in physical variables, the tension clamp and the elastic rod are refused the same way).
// One DamperSoftContact per run: it keeps the law's type, the row and its workspace. Each
// registered law's is compiled in a translation unit of its own, generated from
// damper_soft_contact_instantiation.cpp.in.
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/forced_oscillator.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <memory>
#include <string_view>

namespace hertzdash {

/// What one contact gave.
struct DamperContactOutcome {
  bool separated = false;        ///< false: still in contact at the observation time
  double contact_time_s = 0;     ///< onset to separation (or to the observation time) [s]
  double rebound_speed_mps = 0;  ///< the relative speed at separation, away from the wall [m/s]
  double peak_force_N = 0;       ///< the largest contact force [N]
  double X_m = 0, V_mps = 0;     ///< the primary's displacement and velocity at separation
  IntegrationStats work;
};

class DamperSoftContact {
 public:
  virtual ~DamperSoftContact() = default;
  /// The contact with the wall `sigma` (+1 floor, -1 ceiling) beginning at t_onset_s [s] at
  /// relative speed v0_mps > 0, the primary at X0_m, V0_mps, followed for at most t_obs_s [s].
  virtual DamperContactOutcome run(double sigma, double t_onset_s, double v0_mps, double X0_m, double V0_mps,
                                   double t_obs_s) = 0;
  virtual IntegratorKind integrator_used() const = 0;
};

/// The contacts of the registered law `law` on the validated `setup` (its body mass, contact, e,
/// gravity) with the primary `primary` (its omega set). InvalidParameter as make_shaker_contact.
std::unique_ptr<DamperSoftContact> make_damper_soft_contact(std::string_view law, const DropTestSetup& setup,
                                                            const SolverSettings& solver,
                                                            const ForcedOscillator& primary);

template <DampingLaw Law>
std::unique_ptr<DamperSoftContact> make_damper_soft_contact_of(const DropTestSetup& setup, const SolverSettings& solver,
                                                               const ForcedOscillator& primary);

}  // namespace hertzdash
