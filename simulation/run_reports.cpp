#include "hertzdash/simulation/run_reports.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/omega_n_variant.hpp"
#include "hertzdash/simulation/calibrate_restitution.hpp"
#include "hertzdash/simulation/impact_simulator.hpp"
#include "hertzdash/simulation/step_resolution.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

namespace hertzdash {

namespace {

// Parameters are text; numbers and booleans go into JSON as such.
nlohmann::ordered_json json_value(const std::string& text) {
  if (text == "true" || text == "false") return text == "true";
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (!text.empty() && end == text.c_str() + text.size() && std::isfinite(v)) return v;
  return text;
}

// The closing keys of a run's report: "inputs" (numbers as numbers) and "git_revision".
void add_inputs_and_revision(nlohmann::ordered_json& j, const Parameters& inputs) {
  nlohmann::ordered_json in;
  for (const auto& [name, value] : inputs) in[name] = json_value(value);
  j["inputs"] = in;
  j["git_revision"] = git_revision();
}

}  // namespace

SimulateRun run_simulate(const RunOptions& options, const PaperParameters& paper, bool record_trace) {
  SimulateRun r;
  r.setup = resolve_setup(options, paper);
  r.law = options.damping;
  r.solver = resolve_solver(options);
  r.inputs = describe_run(r.setup, r.law, r.solver);
  integrator_used(r.solver, r.setup, r.law, &r.fallback_reason);
  ImpactSimulator simulator(r.solver);
  r.summary = simulator.run(r.setup, r.law, record_trace ? &r.trace : nullptr);
  return r;
}

std::string fallback_note(IntegratorKind asked, IntegratorKind used, const std::string& why) {
  if (used == asked) return {};
  return fmt::format("--integrator {} fell back to {}: {}", to_string(asked), to_string(used), why);
}

std::string stability_note(const SimulateRun& run) {
  const auto& e = run.summary.elastic_rod;
  if (!e || !(e->step_used_s > 0) || !(e->step_used_s < run.solver.dt_s)) return {};
  return fmt::format("the elastic rod's fastest mode limits {} to steps of {:.6g} s; it ran with that step instead of "
                     "--dt {:.6g} s",
                     to_string(run.summary.integrator_used), e->step_used_s, run.solver.dt_s);
}

std::string resolution_warning(const SimulateRun& run) {
  const auto res = under_resolved_contact(run.summary, run.setup.mass_kg, run.solver);
  if (!res) return {};
  return fmt::format(
      "the fixed step resolved the contact with only {:.0f} steps per undamped Hertz contact time (t_H = {:.6g} s, "
      "--dt {:.6g} s); the convergence study needs at least {} steps per t_H with {} ({}) for errors below {:g} % "
      "(docs/convergence.md)",
      res->steps_per_contact, res->hertz_contact_time_s, run.solver.dt_s, res->required,
      to_string(run.solver.integrator), run.solver.locate_events ? "events located" : "--no-event-location",
      100 * step_resolution_target_error);
}

std::string yield_warning(const SimulateRun& run) {
  const DropTestSetup& s = run.setup;
  const double p0 = run.summary.peak_contact_pressure_Pa, onset = hertz_yield_onset_pressure_Pa(s.ball_yield_stress_Pa, s.ball.nu);
  if (!(p0 > onset)) return {};
  return fmt::format("the Hertz peak pressure {:.4g} MPa exceeds the onset of yield in the hemisphere, {:.3g} Y = {:.4g} "
                     "MPa (--ball-yield-stress {:.4g} Pa, --ball-nu {:.3g}): the contact may deform plastically, which "
                     "the elastic contact law does not model (docs/bounce.md)",
                     p0 / 1e6, hertz_yield_onset_factor(s.ball.nu), onset / 1e6, s.ball_yield_stress_Pa, s.ball.nu);
}

nlohmann::ordered_json to_json(const SimulateRun& run) {
  const ImpactSummary& s = run.summary;
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["e_effective"] = s.e_effective;
  j["peak_force_N"] = s.peak_force_N;
  j["max_deformation_m"] = s.max_deformation_m;
  j["peak_contact_pressure_Pa"] = s.peak_contact_pressure_Pa;
  const double yield_onset = hertz_yield_onset_pressure_Pa(run.setup.ball_yield_stress_Pa, run.setup.ball.nu);
  j["yield_onset_pressure_Pa"] = std::isfinite(yield_onset) ? nlohmann::ordered_json(yield_onset) : nlohmann::ordered_json(nullptr);
  j["exceeds_yield_onset"] = s.peak_contact_pressure_Pa > yield_onset;
  j["contact_time_s"] = s.contact_time_s;
  j["impact_velocity_mps"] = s.impact_velocity_mps;
  j["rebound_velocity_mps"] = s.rebound_velocity_mps;
  j["separated"] = s.separated;
  j["K_N_per_m_1_5"] = s.K;
  nlohmann::ordered_json coefficients = nlohmann::ordered_json::object();
  for (const NamedValue& c : s.law_coefficients) coefficients[c.name] = c.value;
  j["law_coefficients"] = coefficients;
  j["steps"] = s.work.steps;
  j["rhs_evaluations"] = s.work.rhs_evaluations;
  j["events"] = s.work.events;
  j["integrator_used"] = to_string(s.integrator_used);
  if (const auto& it = s.omega_n_iteration) {
    j["omega_n_fixed_point"] = {{"iterations", it->iterations},
                                {"converged", it->converged},
                                {"relative_change", it->relative_change},
                                {"contraction", it->contraction}};
  }
  if (const auto& e = s.elastic_rod) {
    nlohmann::ordered_json r;
    r["elements"] = e->elements;
    r["first_frequency_hz"] = e->first_frequency_hz;
    r["wave_round_trip_s"] = e->wave_round_trip_s;
    if (e->step_used_s > 0) {
      r["stable_step_s"] = e->stable_step_s;
      r["step_used_s"] = e->step_used_s;
    }
    r["peak_load_cell_force_N"] = e->peak_load_cell_force_N;
    r["energy_in_J"] = e->energy_in_J;
    r["energy_rigid_body_out_J"] = e->energy_rigid_body_out_J;
    r["energy_rod_vibration_J"] = e->energy_rod_vibration_J;
    r["energy_cell_J"] = e->energy_cell_J;
    r["energy_dissipated_contact_J"] = e->energy_dissipated_contact_J;
    r["energy_dissipated_material_J"] = e->energy_dissipated_material_J;
    r["energy_balance_error_J"] = e->energy_balance_error_J;
    j["elastic_rod"] = r;
  }
  add_inputs_and_revision(j, run.inputs);
  return j;
}

RestitutionRun run_restitution(const RunOptions& options, const PaperParameters& paper, std::optional<double> e_target) {
  RestitutionRun r;
  r.law = options.damping;
  r.setup = contact_phase_setup(resolve_setup(options, paper));
  if (is_iterated(r.setup.damping.omega_n)) {
    throw InvalidParameter("--omega-n", to_string(r.setup.damping.omega_n),
                           "a closed-form variant for `restitution`: paper, impact-energy, rebound-energy or "
                           "as-printed (the iterated variants need `simulate`)");
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
  } else {
    r.e_input = r.setup.restitution;
    r.e_effective = simulator.run(r.setup, r.law).e_effective;
  }
  return r;
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
  j["git_revision"] = git_revision();
  return j;
}

BounceRun run_bounce(const RunOptions& options, const PaperParameters& paper, const BounceOptions& bounce,
                     std::optional<double> interval_target) {
  BounceRun r;
  r.setup = resolve_setup(options, paper);
  r.law = options.damping;
  r.solver = resolve_solver(options);
  r.options = bounce;
  validate(r.options);
  r.interval_target = interval_target;
  if (interval_target) {
    r.calibration = calibrate_interval_restitution(r.setup, r.law, r.solver, *interval_target);
    r.setup.restitution = r.calibration->e_input;
  }
  r.inputs = describe_run(r.setup, r.law, r.solver);
  r.inputs.emplace_back("bounces", std::to_string(bounce.impacts));
  r.inputs.emplace_back("min_rebound_velocity_mps", fmt::format("{}", bounce.min_rebound_velocity_mps));
  integrator_used(r.solver, r.setup, r.law, &r.fallback_reason);
  r.sequence = run_bounce_sequence(r.setup, r.law, r.solver, r.options);
  return r;
}

nlohmann::ordered_json to_json(const BounceRun& run) {
  const BounceSequence& b = run.sequence;
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["damping"] = run.law;
  if (run.calibration) {
    j["interval_calibration"] = {{"e_target_from_intervals", *run.interval_target},
                                 {"e_input", run.calibration->e_input},
                                 {"e_from_intervals", run.calibration->e_effective},
                                 {"iterations", run.calibration->iterations}};
  }
  if (b.viscous_time_constant_s) j["viscous_time_constant_s"] = *b.viscous_time_constant_s;
  nlohmann::ordered_json impacts = nlohmann::ordered_json::array();
  for (const BounceImpact& i : b.impacts)
    impacts.push_back({{"onset_time_s", i.onset_time_s},
                       {"separation_time_s", i.separation_time_s},
                       {"contact_time_s", i.contact_time_s},
                       {"approach_speed_mps", i.approach_speed_mps},
                       {"rebound_speed_mps", i.rebound_speed_mps},
                       {"peak_force_N", i.peak_force_N},
                       {"max_deformation_m", i.max_deformation_m},
                       {"separated", i.separated}});
  j["impacts"] = impacts;
  j["onset_times_s"] = b.onset_times_s;
  j["e_from_intervals"] = b.e_from_intervals;
  j["e_velocity_ratio"] = b.e_velocity_ratio;
  j["flights"] = b.flights_integrated ? "integrated" : "closed form";
  j["end_reason"] = b.end_reason;
  j["steps"] = b.work.steps;
  j["rhs_evaluations"] = b.work.rhs_evaluations;
  j["integrator_used"] = to_string(b.integrator_used);
  add_inputs_and_revision(j, run.inputs);
  return j;
}

nlohmann::ordered_json registered_laws_json() {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const LawInfo& l : registered_laws())
    list.push_back({{"name", l.name},
                    {"citation", l.citation},
                    {"formula", l.formula},
                    {"coefficients", l.coefficients},
                    {"validity", l.validity},
                    {"force_continuous_at_onset", l.force_continuous_at_onset}});
  return list;
}

}  // namespace hertzdash
