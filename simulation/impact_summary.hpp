#pragma once
// What one impact produces: the summary every run reports, and the samples of the
// contact phase a run records on request.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/solver_settings.hpp"

#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

/// How the fixed point of an iterated omega_n variant was found (simulation/omega_n_fixed_point.hpp).
struct OmegaNIteration {
  int iterations = 0;           ///< simulations run
  bool converged = false;
  double relative_change = 0;   ///< |w_k - w_{k-1}| / w_k at the last iteration
  double contraction = 0;       ///< last observed |dG| / |dw| (< 1 for a contraction)
  std::string failure;          ///< why it stopped unconverged (empty if converged)
};

/// The result of one impact. Velocities are speeds (>= 0).
struct ImpactSummary {
  double K = 0;                        ///< Hertz stiffness [N/m^{3/2}]
  double impact_velocity_mps = 0;      ///< approach speed at contact onset
  double rebound_velocity_mps = 0;     ///< rebound speed at separation (0 if none)
  double e_effective = 0;              ///< rebound / approach speed
  double peak_force_N = 0;             ///< largest contact force
  double max_deformation_m = 0;        ///< largest x
  double contact_time_s = 0;           ///< separation minus onset time
  double t_onset_s = 0, t_separation_s = 0;
  bool separated = false;              ///< false if the rod came to rest on the ball
  IntegrationStats work;               ///< steps and right-hand-side evaluations, whole run
  std::vector<NamedValue> law_coefficients;
  IntegratorKind integrator_used = IntegratorKind::cvode;  ///< set by ImpactSimulator::run: the one asked for, or its fall-back
  std::optional<OmegaNIteration> omega_n_iteration;  ///< iterated omega_n variants only
};

/// One sample of the contact phase (the --trace columns).
struct TraceSample {
  double t_s, x_m, xdot_mps, force_N, accel_mps2, rod_displacement_m, rod_velocity_mps;
};
std::vector<std::string> trace_columns();

}  // namespace hertzdash
