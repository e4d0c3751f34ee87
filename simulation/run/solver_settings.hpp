#pragma once
// How to integrate: which integrator, and the settings that apply to it. One set of
// settings serves every integrator; the integrator table (simulation/run/integrator_table.hpp)
// says which of them each integrator reads, and turns them into its options.
#include "hertzdash/integrators/cvode_integrator.hpp"

namespace hertzdash {

/// The integrators, one per row of the integrator table (same order).
enum class IntegratorKind {
  euler,
  rk4,
  cvode,
  dopri5,
  dopri5_regularized,
  cvode_regularized,
  gbs8_regularized,
  taylor_regularized,
};

struct SolverSettings {
  IntegratorKind integrator = IntegratorKind::cvode;
  // Fixed-step integrators (euler, rk4):
  double dt_s = 1e-6;          ///< the step [s], > 0
  bool locate_events = true;   ///< cut steps at located event crossings (false: at the step's end)
  // Adaptive integrators (cvode, dopri5, the regularised paths):
  double rtol = 1e-8;          ///< relative tolerance, > 0
  /// Absolute tolerance relative to the impact's scales, > 0 (dimensionless): component i of
  /// the state is held to atol x its scale (ode/ode_system.hpp, state_scale): X for lengths,
  /// v0 for speeds, t_H for times (X^{1/2} for u = x^{1/2}, (1/2) m v0^2 for energies), X and
  /// t_H the undamped Hertz maximum compression and contact time at the impact speed v0. So
  /// the accuracy does not depend on the units, the impact speed or the mass.
  double atol = 1e-12;
  double max_step_s = 0;       ///< largest step [s], physical variables only; 0: no limit
  CvodeMethod cvode_method = CvodeMethod::adams;  ///< cvode, cvode-regularized

  friend bool operator==(const SolverSettings&, const SolverSettings&) = default;
};

/// Throws InvalidParameter, naming the option, for any setting out of range, whether or not
/// the chosen integrator reads it (a bad value is a mistake even where it does not matter):
/// a non-positive step [s], a tolerance outside (0, 1), a negative largest step [s], or a
/// largest step other than 0 for a regularised path (whose steps are in tau, not in time).
void validate(const SolverSettings& s);

}  // namespace hertzdash
