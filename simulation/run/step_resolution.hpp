#pragma once
// How many fixed steps a contact needs, from the convergence study
// (validation/convergence), and the check `hertzdash simulate` warns with.
//
// The study solves the paper's steel-rod impact (h = 20 mm) with both the undamped
// and the paper's law at N = 5, 10, 20, ... steps per undamped Hertz contact time t_H
// (eq. 3's spring alone; the paper's law's contact lasts longer) and reports, per
// method, the smallest N of that doubling sweep from which on every quantity
// (restitution, peak force, maximum deformation, contact time, state inside the
// contact) is within step_resolution_target_error of the reference, for both laws
// and the worst of four positions of onset inside a step. The thresholds are the
// rows' min_steps_per_contact_* in simulation/run/integrator_table.hpp; the study prints
// its findings beside them and flags any mismatch, and the convergence tests re-check
// that each meets the target.
//
// The numbers follow the orders the study establishes (docs/convergence.md):
// Euler is first order with an error of about 6/N, so it needs thousands of steps;
// RK4 with located events is of order 1.5 to 2.5 but with small constants; RK4
// without event location knows the contact time only to a step (error ~ 1/(2N)).
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>

namespace hertzdash {

/// Largest relative error the thresholds allow: 0.1 %, below the last digit of the
/// restitution the paper prints (Table 2, e.g. e = 0.795).
inline constexpr double step_resolution_target_error = 1e-3;

/// Steps per undamped Hertz contact time a fixed-step method needs for step_resolution_target_error
/// (the integrator table's min_steps_per_contact_*; 0 for the adaptive integrators,
/// whose accuracy is set by their tolerances).
constexpr long min_steps_per_contact(IntegratorKind integrator, bool locate_events) {
  const IntegratorTraits& row = integrator_traits(integrator);
  return locate_events ? row.min_steps_per_contact_located : row.min_steps_per_contact_unlocated;
}

/// Fewest fixed steps per undamped Hertz contact time a run may take: the coarsest resolution
/// the convergence study measures (N = 5). Below it the contact is not represented at all
/// (--dt 0.01 on the steel rod, 0.01 steps per t_H, gave e_effective 2.8e4; --dt 1e308 gave 0).
inline constexpr long min_steps_per_hertz_contact = 5;

/// Throws InvalidParameter naming --dt when a fixed-step integrator's step exceeds
/// t_H / min_steps_per_hertz_contact, t_H the undamped Hertz contact time of the set-up
/// (model/hertz.hpp: t_H ~= 2.9432 X / v0). Adaptive integrators: nothing to check; the
/// elastic rod neither: it steps at min(--dt, its stability limit), a fraction of the rod's
/// wave transit, and under_resolved_contact() reports the resolution it reached.
inline void validate_fixed_step(const DropTestSetup& setup, const SolverSettings& solver) {
  if (integrator_traits(solver.integrator).step_control != StepControl::fixed_step || setup.elastic_rod) return;
  const double v0 = approach_speed(setup);
  const double t_hertz = undamped_hertz_impact(hertz_stiffness(setup), setup.mass_kg, v0).contact_time_s;
  const double dt_max = t_hertz / static_cast<double>(min_steps_per_hertz_contact);
  if (!(solver.dt_s <= dt_max))
    throw InvalidParameter("dt", format_value(solver.dt_s),
                           fmt::format("> 0 and at most {:.4g} s for this impact: t_H / {}, t_H = {:.4g} s its undamped "
                                       "Hertz contact time at {:.4g} m/s (coarser steps do not resolve the contact; "
                                       "the convergence study needs {} steps per t_H with {} for errors below {:g} %)",
                                       dt_max, min_steps_per_hertz_contact, t_hertz, v0,
                                       min_steps_per_contact(solver.integrator, solver.locate_events),
                                       integrator_traits(solver.integrator).name, 100 * step_resolution_target_error));
}

/// Throws std::runtime_error when an impact's summary holds a non-finite number (a run that
/// diverged): results are errors, never silent inf or NaN.
inline void require_finite_results(const ImpactSummary& s) {
  const std::pair<const char*, double> results[] = {{"e_effective", s.e_effective},
                                                    {"peak_force_N", s.peak_force_N},
                                                    {"max_deformation_m", s.max_deformation_m},
                                                    {"contact_time_s", s.contact_time_s},
                                                    {"rebound_velocity_mps", s.rebound_velocity_mps}};
  for (const auto& [name, value] : results)
    if (!std::isfinite(value))
      throw std::runtime_error(fmt::format("the run diverged: {} = {} (a non-finite result); a finer `dt` or a tighter "
                                           "`rtol` may resolve it",
                                           name, value));
}

/// How finely a fixed step resolved the contact of a run.
struct ContactResolution {
  double steps_per_contact;    ///< t_H / dt
  double hertz_contact_time_s; ///< t_H: the undamped Hertz contact time of the same K, m and v0
  long required;               ///< min_steps_per_contact for the method
};

/// The resolution of a fixed-step run whose contact got fewer steps than the study
/// shows are needed; nothing for an adaptive integrator, for a resolved contact, or if
/// the rod never reached the ball. Steps are counted per undamped Hertz contact time, the
/// unit the study measured them in, so the threshold means the same for every law.
inline std::optional<ContactResolution> under_resolved_contact(const ImpactSummary& s, double mass_kg,
                                                               const SolverSettings& solver) {
  const long required = min_steps_per_contact(solver.integrator, solver.locate_events);  // fixed steps never fall back
  if (required == 0 || !(s.impact_velocity_mps > 0) || !(s.K > 0)) return std::nullopt;
  const double t_hertz = undamped_hertz_impact(s.K, mass_kg, s.impact_velocity_mps).contact_time_s;
  const double dt = s.elastic_rod && s.elastic_rod->step_used_s > 0 ? s.elastic_rod->step_used_s : solver.dt_s;
  const double steps = t_hertz / dt;
  if (steps >= static_cast<double>(required)) return std::nullopt;
  return ContactResolution{steps, t_hertz, required};
}

}  // namespace hertzdash
