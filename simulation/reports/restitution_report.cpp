// `restitution`'s run and report (simulation/reports/run_reports.hpp): a law's effective restitution in
// the contact phase alone, or the input e calibrated to a target, its notes and warnings, and
// its JSON.
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/omega_n_variant.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "hertzdash/simulation/reports/result_output.hpp"
#include "hertzdash/simulation/run/calibrate_restitution.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

namespace hertzdash {

RestitutionRun run_restitution(const RunOptions& options, const PaperParameters& paper, std::optional<double> e_target) {
  RestitutionRun r;
  r.law = options.damping;
  if (e_target && options.restitution)
    throw InvalidParameter("restitution", format_value(*options.restitution),
                           "omitted with `target-restitution` (the calibration finds the input e)");
  const DropTestSetup drop = resolve_setup(options, paper);
  // The contact phase alone: the rigid rod against a rigid wall unless the wall's moduli are
  // given, no gravity in contact (gravity only turns `height` into the approach speed).
  if (options.rod_model != "rigid")
    throw InvalidParameter("rod-model", options.rod_model,
                           "rigid for hertzdash restitution, the contact phase alone (the elastic rod on its load cell runs "
                           "in hertzdash simulate and bounce)");
  if (options.rod_nu && !options.rod_E_Pa)
    throw InvalidParameter("rod-nu", format_value(*options.rod_nu),
                           "given only with `rod-E` for hertzdash restitution (against its default rigid wall the wall's "
                           "Poisson ratio does not enter)");
  if (options.gravity_mps2 && options.impact_velocity_mps)
    throw InvalidParameter("gravity", format_value(*options.gravity_mps2),
                           "omitted with `impact-velocity` for hertzdash restitution (the contact phase has no gravity; "
                           "gravity only turns `height` into the approach speed)");
  r.setup = contact_phase_setup(drop);
  if (options.rod_E_Pa) {  // the wall the user gave, not the rigid one
    r.setup.rod.E_Pa = *options.rod_E_Pa;
    validate(r.setup);
  }
  if (is_iterated(r.setup.damping.omega_n)) {
    throw InvalidParameter("omega-n", to_string(r.setup.damping.omega_n),
                           "a closed-form variant for hertzdash restitution: paper, impact-energy, rebound-energy or "
                           "as-printed (the iterated variants need hertzdash simulate)");
  }
  r.solver = resolve_solver(options);
  ImpactSimulator simulator(r.solver);
  r.integrator_used = integrator_used(r.solver, r.setup, r.law, &r.fallback_reason);
  r.e_target = e_target;
  if (e_target) {
    const RestitutionCalibration c = calibrate_restitution(simulator, r.setup, r.law, *e_target);
    r.e_input = c.e_input;
    r.e_effective = c.e_effective;
    r.iterations = c.iterations;
    DropTestSetup found = r.setup;
    found.restitution = c.e_input;
    found.restitution_of_other_pair = false;  // e is now this pair's own, found for the target
    r.summary = simulator.run(found, r.law);  // the run at the input found, for its diagnostics
  } else {
    r.e_input = r.setup.restitution;
    r.summary = simulator.run(r.setup, r.law);
    r.e_effective = r.summary.e_effective;
  }
  return r;
}

std::vector<RunDiagnostic> run_diagnostics(const RestitutionRun& run) {
  DropTestSetup s = run.setup;
  s.restitution = run.e_input;
  return impact_diagnostic_list(run.summary, s, run.solver, run.fallback_reason);
}

nlohmann::ordered_json to_json(const RestitutionRun& run) {
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["damping"] = run.law;
  j["tension"] = run.setup.no_tension ? "clamped" : "allowed";
  j["impact_velocity_mps"] = *run.setup.impact_velocity_mps;
  if (run.e_target) j["e_target"] = *run.e_target;
  j["e_input"] = run.e_input;
  j["e_effective"] = run.e_effective;
  if (run.iterations) j["iterations"] = *run.iterations;
  j["integrator_used"] = to_string(run.integrator_used);
  // The law's constants at e_input (kuwabara-kono's A, hunt-crossley's chi, the paper's c_e, ...).
  j["law_coefficients"] = law_coefficients_json(run.summary.law_coefficients);
  j["warnings"] = to_json(run_diagnostics(run));
  j["git_revision"] = git_revision();
  return j;
}

}  // namespace hertzdash
