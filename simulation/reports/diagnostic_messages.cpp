#include "hertzdash/simulation/reports/diagnostic_messages.hpp"

#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/result_checks.hpp"
#include "hertzdash/simulation/run/step_resolution.hpp"

#include <fmt/format.h>

#include <cmath>

namespace hertzdash {

namespace {

std::string stability_note(const ImpactSummary& s, const SolverSettings& solver) {
  return fmt::format("the elastic rod's fastest mode limits {} to steps of {:.6g} s; it ran with that step instead of "
                     "`dt` {:.6g} s",
                     to_string(s.integrator_used), s.elastic_rod->step_used_s, solver.dt_s);
}

std::string resolution_warning(const ImpactSummary& s, const DropTestSetup& setup, const SolverSettings& solver) {
  const auto res = under_resolved_contact(s, setup.mass_kg, solver);
  return fmt::format(
      "the fixed step resolved the contact with only {:.0f} steps per undamped Hertz contact time (t_H = {:.6g} s, "
      "`dt` {:.6g} s); the convergence study needs at least {} steps per t_H with {} ({}) for errors below {:g} % "
      "(docs/convergence.md)",
      res->steps_per_contact, res->hertz_contact_time_s, solver.dt_s, res->required, to_string(solver.integrator),
      solver.locate_events ? "events located" : "`no-event-location`", 100 * step_resolution_target_error);
}

std::string tolerance_warning(const ImpactSummary& s, const SolverSettings& solver) {
  const bool rtol_loose = solver.rtol > loose_rtol_limit;
  const std::string option = key_reference(rtol_loose ? "rtol" : "atol");
  return fmt::format("{} {:g} is above {:g}: measured on the paper's impacts, {} and the other adaptive integrators "
                     "give e_effective within the {:g} % the fixed steps are held to at {:g}, not all of them at {:g} "
                     "(tests/test_tolerance_limit.cpp); use a smaller {}",
                     option, rtol_loose ? solver.rtol : solver.atol, loose_rtol_limit, to_string(s.integrator_used),
                     100 * step_resolution_target_error, loose_rtol_limit, 10 * loose_rtol_limit, option);
}

std::string yield_warning(const ImpactSummary& s, const DropTestSetup& setup) {
  const double p0 = s.peak_contact_pressure_Pa,
               onset = hertz_yield_onset_pressure_Pa(setup.ball_yield_stress_Pa, setup.ball.nu);
  return fmt::format("the Hertz peak pressure {:.4g} MPa exceeds the onset of yield in the sphere, {:.3g} Y = {:.4g} "
                     "MPa (`ball-yield-stress` {:.4g} Pa, `ball-nu` {:.3g}): the contact may deform plastically, which "
                     "the elastic contact law does not model (docs/bounce.md)",
                     p0 / 1e6, hertz_yield_onset_factor(setup.ball.nu), onset / 1e6, setup.ball_yield_stress_Pa,
                     setup.ball.nu);
}

std::string deformation_warning(const ImpactSummary& s, const DropTestSetup& setup) {
  const double x = s.max_deformation_m, R = setup.ball_radius_m;
  return fmt::format("the maximum deformation {:.4g} mm is {:.3g} % of the ball radius {:.4g} mm (contact radius a = "
                     "{:.3g} R): the sphere departs from the paraboloid Hertz theory assumes by {:.3g} % at the contact's "
                     "edge, more than {:g} %; the small-deformation contact law is outside its range (model/hertz.hpp)",
                     1e3 * x, 100 * x / R, 1e3 * R, std::sqrt(x / R), 100 * hertz_profile_error(x, R),
                     100 * hertz_profile_error_limit);
}

}  // namespace

std::string fallback_note(IntegratorKind asked, IntegratorKind used, const std::string& why) {
  if (used == asked) return {};
  return fmt::format("`integrator` {} fell back to {}: {}", to_string(asked), to_string(used), why);
}

std::string diagnostic_message(Diagnostic code, const ImpactSummary& s, const DropTestSetup& setup,
                               const SolverSettings& solver, const std::string& fallback_reason) {
  switch (code) {
    case Diagnostic::integrator_fallback: return fallback_note(solver.integrator, s.integrator_used, fallback_reason);
    case Diagnostic::stability_limit: return stability_note(s, solver);
    case Diagnostic::under_resolved: return resolution_warning(s, setup, solver);
    case Diagnostic::loose_tolerance: return tolerance_warning(s, solver);
    case Diagnostic::yield_onset: return yield_warning(s, setup);
    case Diagnostic::large_deformation: return deformation_warning(s, setup);
    case Diagnostic::not_separated:
      return "the rod did not separate from the ball within the simulated time (it came to rest on it); e_effective, "
             "rebound velocity and contact time are not defined";
    case Diagnostic::no_rebound:
      return fmt::format("the rod left the hemisphere still moving down, its centre of mass at {:.4g} m/s: the "
                         "hemisphere sank away from it faster on its load cell (`cell-stiffness` {:g} N/m), so the "
                         "contact ended without a rebound; e_effective is 0 and no bounce follows",
                         s.elastic_rod ? -s.elastic_rod->separation_velocity_mps : 0.0,
                         setup.elastic_rod ? setup.elastic_rod->cell_stiffness_N_per_m : 0.0);
    case Diagnostic::preset_restitution:
      return fmt::format("the input e = {:g} is the {} rod's, measured for that rod on the hemisphere (Table 2); the "
                         "run changed the pair (a mass, modulus, Poisson ratio or radius of its own), for which e is "
                         "not known: give `restitution` for it",
                         setup.restitution, setup.rod_preset);
    case Diagnostic::rig_warning:
      return "the rig's run warned: `hertzdash RIG` with the run's inputs prints why";
  }
  return {};
}

std::vector<RunDiagnostic> impact_diagnostic_list(const ImpactSummary& s, const DropTestSetup& setup,
                                                  const SolverSettings& solver, const std::string& fallback_reason) {
  std::vector<RunDiagnostic> out;
  for (const DiagnosticInfo& d : diagnostic_table)
    if (s.diagnostics.has(d.code))
      out.push_back({std::string(d.kind), std::string(d.name), diagnostic_message(d.code, s, setup, solver, fallback_reason), {}});
  return out;
}

nlohmann::ordered_json to_json(const std::vector<RunDiagnostic>& diagnostics) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const RunDiagnostic& d : diagnostics) {
    // The JSON is the program's output (Python's dicts are the same): options spelled --key.
    nlohmann::ordered_json item{
        {"kind", d.kind}, {"code", d.code}, {"message", spell_key_references(d.message, KeySpelling::command_line)}};
    if (d.impact) item["impact"] = *d.impact;
    list.push_back(item);
  }
  return list;
}

}  // namespace hertzdash
