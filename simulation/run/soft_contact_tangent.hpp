#pragma once
// One soft contact with a harmonically moving wall (HarmonicForcing: the shaker's table, the
// driven box's walls, the oscillator's stop) or with the damper's primary (SprungPrimary) and its
// derivatives with respect to its onset time, approach speed and (the primary) the other body's
// state at onset, from the contact's variational equations (model/contact_tangent_system.hpp)
// integrated by adaptive Dormand-Prince 5(4) at the run's tolerances (rtol, atol x the state's
// scales). What the stroboscopic map of a soft impact orbit needs for its monodromy matrix
// (simulation/orbits/stroboscopic_map.hpp). The laws: those that declare dF/dv0
// (SpeedDerivativeLaw: hongo, the Hunt-Crossley family, kuwabara-kono, none); the contact is the one
// `make_soft_contact` runs for the same law and set-up (kuwabara-kono's time constant calibrated
// the same way), integrated again with its tangents.
#include "hertzdash/model/contact_environments.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <Eigen/Core>

#include <functional>
#include <string>
#include <string_view>

namespace hertzdash {

/// One contact and its derivatives.
struct ContactTangent {
  bool separated = false;        ///< false: still in contact at the observation time
  double contact_time_s = 0;     ///< t_c, onset to separation [s]
  double rebound_speed_mps = 0;  ///< v_sep, the relative speed at separation [m/s]
  /// The other body's state at separation (SprungPrimary: X [m], V [m/s]); empty for a wall.
  Eigen::VectorXd other_state;
  /// d(t_c, v_sep, other_state)/d(t_on, v0, the other body's state at onset): rows t_c [s],
  /// v_sep [m/s], then X [m], V [m/s]; columns t_on [s], v0 [m/s], then X0 [m], V0 [m/s].
  Eigen::MatrixXd jacobian;
  IntegrationStats work;
};

/// The contact with the environment `env` (its onset time in env.t_onset_s, the other body's
/// state in it) at approach speed v0 [m/s], followed for at most t_obs [s].
template <class Env>
using ContactTangentRun = std::function<ContactTangent(const Env& env, double v0_mps, double t_obs_s)>;

/// The contacts of the registered law `law` with the environment Env (HarmonicForcing,
/// SprungPrimary) on the validated `setup` with the tolerances of `solver`; empty for a law that
/// does not declare dF/dv0 (contact_tangent_laws() lists those that do). InvalidParameter("damping",
/// ...) for an unknown law.
template <class Env>
ContactTangentRun<Env> make_contact_tangent(std::string_view law, const DropTestSetup& setup, const SolverSettings& solver);

/// The laws make_contact_tangent takes, comma-separated.
std::string contact_tangent_laws();

}  // namespace hertzdash
