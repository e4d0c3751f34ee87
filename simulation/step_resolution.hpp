#pragma once
// How many fixed steps a contact needs, from the convergence study
// (validation/convergence), and the check `hertzdash simulate` warns with.
//
// The study solves the paper's steel-rod impact (h = 20 mm) with both the undamped
// and the paper's law at N = 10, 20, 40, ... steps per contact time and reports, per
// method, the smallest N of that doubling sweep from which on every quantity
// (restitution, peak force, maximum deformation, contact time, state inside the
// contact) is within step_resolution_target_error of the reference, for both laws
// and the worst of four positions of onset inside a step. The study prints its
// findings beside these constants and flags any mismatch; the convergence tests
// re-check that each constant meets the target.
//
// The numbers follow the orders the study establishes (README, "Convergence"):
// Euler is first order with an error of about 6/N, so it needs thousands of steps;
// RK4 with located events is of order 1.5 to 2.5 but with small constants; RK4
// without event location knows the contact time only to a step (error ~ 1/(2N)).
#include "simulation/impact_simulator.hpp"

#include <optional>

namespace hertzdash {

/// Largest relative error the thresholds below allow: 0.1 %, below the last digit of
/// the restitution the paper prints (Table 2, e.g. e = 0.795).
inline constexpr double step_resolution_target_error = 1e-3;

inline constexpr long min_steps_per_contact_euler = 10240;           ///< located or not
inline constexpr long min_steps_per_contact_rk4_located = 10;
inline constexpr long min_steps_per_contact_rk4_unlocated = 1280;

/// Steps per contact time a fixed-step method needs for step_resolution_target_error
/// (0 for the adaptive CVODE and dopri5, whose accuracy is set by their tolerances).
inline long min_steps_per_contact(IntegratorKind integrator, bool locate_events) {
  switch (integrator) {
    case IntegratorKind::euler: return min_steps_per_contact_euler;
    case IntegratorKind::rk4: return locate_events ? min_steps_per_contact_rk4_located : min_steps_per_contact_rk4_unlocated;
    case IntegratorKind::cvode:
    case IntegratorKind::dopri5:
    case IntegratorKind::dopri5_regularized:
    case IntegratorKind::cvode_regularized:
    case IntegratorKind::gbs8_regularized: return 0;
  }
  return 0;
}

/// How finely a fixed step resolved the contact of a run.
struct ContactResolution {
  double steps_per_contact;  ///< contact time / dt
  long required;             ///< min_steps_per_contact for the method
};

/// The resolution of a fixed-step run whose contact got fewer steps than the study
/// shows are needed; nothing for CVODE, for a resolved contact, or if the rod never
/// separated (no contact time).
inline std::optional<ContactResolution> under_resolved_contact(const ImpactSummary& s, const SolverSettings& solver) {
  const long required = min_steps_per_contact(solver.integrator, solver.fixed_step.locate_events);
  if (required == 0 || !s.separated) return std::nullopt;
  const double steps = s.contact_time_s / solver.fixed_step.dt;
  if (steps >= static_cast<double>(required)) return std::nullopt;
  return ContactResolution{steps, required};
}

}  // namespace hertzdash
