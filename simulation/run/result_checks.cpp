#include "hertzdash/simulation/run/result_checks.hpp"

#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/step_resolution.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace hertzdash {

namespace {

bool adaptive(IntegratorKind k) { return integrator_traits(k).step_control == StepControl::adaptive; }

// hertz_yield_onset_factor(nu) is a golden-section search: remembered per thread for the last nu,
// since a sweep's impacts mostly share it.
double yield_onset_pressure_Pa(const DropTestSetup& s) {
  thread_local double last_nu = -2, last_factor = 0;
  if (s.ball.nu != last_nu) {
    last_factor = hertz_yield_onset_factor(s.ball.nu);
    last_nu = s.ball.nu;
  }
  return last_factor * s.ball_yield_stress_Pa;
}

}  // namespace

double run_tolerance(const SolverSettings& solver) { return std::max(solver.rtol, solver.atol); }

double restitution_limit() { return 1 + step_resolution_target_error; }

void require_physical_restitution(const ImpactSummary& s, const SolverSettings& solver, const LawInfo& law,
                                  bool dissipative) {
  const double limit = restitution_limit();
  if (!s.separated || !(s.e_effective > limit)) return;
  const std::string change =
      adaptive(solver.integrator)
          ? fmt::format("a tighter `rtol` and `atol` (they are {:g} and {:g}; at most {:g} keeps e_effective within "
                        "{:g} %)",
                        solver.rtol, solver.atol, loose_rtol_limit, 100 * step_resolution_target_error)
          : fmt::format("a smaller `dt` (it is {:g} s; the convergence study needs {} steps per undamped Hertz contact "
                        "time with {}) or an adaptive integrator",
                        solver.dt_s, min_steps_per_contact(solver.integrator, solver.locate_events),
                        to_string(solver.integrator));
  throw std::runtime_error(fmt::format(
      "the run is under-resolved: e_effective = {:.6g} exceeds {:.6g}, 1 plus the accuracy of {}, but the law '{}' {} "
      "and cannot return more energy than it received; use {}",
      s.e_effective, limit, to_string(s.integrator_used), law.name,
      dissipative ? "dissipates energy (e_effective < 1)" : "conserves energy (e_effective = 1)", change));
}

DiagnosticSet impact_diagnostics(const ImpactSummary& s, const DropTestSetup& setup, const SolverSettings& solver) {
  DiagnosticSet d;
  if (s.integrator_used != solver.integrator) d.add(Diagnostic::integrator_fallback);
  if (const auto& e = s.elastic_rod; e && e->step_used_s > 0 && e->step_used_s < solver.dt_s)
    d.add(Diagnostic::stability_limit);
  if (under_resolved_contact(s, setup.mass_kg, solver)) d.add(Diagnostic::under_resolved);
  if (adaptive(s.integrator_used) && run_tolerance(solver) > loose_rtol_limit) d.add(Diagnostic::loose_tolerance);
  if (s.peak_contact_pressure_Pa > yield_onset_pressure_Pa(setup)) d.add(Diagnostic::yield_onset);
  if (hertz_profile_error(s.max_deformation_m, setup.ball_radius_m) > hertz_profile_error_limit)
    d.add(Diagnostic::large_deformation);
  if (!s.separated) d.add(Diagnostic::not_separated);
  if (s.separated && s.elastic_rod && s.elastic_rod->separation_velocity_mps < 0) d.add(Diagnostic::no_rebound);
  if (setup.restitution_of_other_pair) d.add(Diagnostic::preset_restitution);
  return d;
}

}  // namespace hertzdash
