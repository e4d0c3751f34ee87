#pragma once
// One soft contact with any environment (model/contact_environments.hpp): the contact system
// (model/contact_system.hpp) of any registered damping law, integrated by any integrator row in
// regularising variables (dopri5-regularized, cvode-regularized, gbs8-regularized,
// taylor-regularized; the table's fall-back for a law without the polynomial form). The rows in
// physical variables (euler, rk4, cvode, dopri5) are refused: their system is the drop test's,
// which has no moving other body, and the tension clamp and the elastic rod (which need them)
// with it.
//
// One SoftContact per run (or thread): it keeps the law's type, the integrator row and its
// workspace (CVODE's memory reinitialised, not rebuilt), so that a contact allocates nothing.
// Each contact is given its environment at onset (the other body's state then, the drive's
// phase), the impact speed and how long to follow it. The contacts of every law and environment
// are compiled in the law's own generated translation unit (simulation/run/law_runs.hpp).
#include "hertzdash/model/contact_environments.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/run/law_runs.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <array>
#include <memory>
#include <string_view>
#include <tuple>

namespace hertzdash {

/// What one contact gave.
template <class Env>
struct SoftContactOutcome {
  bool separated = false;        ///< false: still in contact at the observation time
  double contact_time_s = 0;     ///< onset to separation (or to the observation time) [s]
  double rebound_speed_mps = 0;  ///< the relative speed at separation, away from the other body [m/s]
  double peak_force_N = 0;       ///< the largest contact force [N]
  std::array<double, Env::extra_dimension> environment{};  ///< the environment's state z at the end
  IntegrationStats work;
  /// The speed v = sqrt(4 K R^{5/2}/(5 m)) [m/s] at which the undamped Hertz deformation reaches the
  /// ball radius R: the contact model holds below it (HertzScale; `simulate` refuses one above it).
  double hertz_speed_limit_mps = 0;
};

template <class Env>
class SoftContact {
 public:
  virtual ~SoftContact() = default;
  /// The contact with the environment `env` (at onset) at relative impact speed v0_mps > 0
  /// [m/s], followed for at most t_obs_s [s].
  virtual SoftContactOutcome<Env> run(const Env& env, double v0_mps, double t_obs_s) = 0;
  /// The integrator row that runs the contacts (after the table's fall-back).
  virtual IntegratorKind integrator_used() const = 0;
};

/// The contacts of the registered law `law` on the validated `setup` (its body, contact, e; a
/// material time constant calibrated if not given; not its height or gravity) for the command
/// `command`. InvalidParameter("integrator", ...) for a row in physical variables,
/// ("no-tension", ...) and ("rod-model", ...) for what needs one, ("damping", ...) for an
/// unknown law.
template <class Env>
std::unique_ptr<SoftContact<Env>> make_soft_contact(std::string_view law, const DropTestSetup& setup,
                                                    const SolverSettings& solver, std::string_view command) {
  return std::get<SoftContactMaker<Env>>(law_runs(law).make_soft_contact)(setup, solver, command);
}

}  // namespace hertzdash
