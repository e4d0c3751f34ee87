#include "hertzdash/simulation/run_reports.hpp"

#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/io/decimal_number.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/omega_n_variant.hpp"
#include "hertzdash/simulation/calibrate_restitution.hpp"
#include "hertzdash/simulation/impact_history.hpp"
#include "hertzdash/simulation/impact_simulator.hpp"
#include "hertzdash/simulation/result_output.hpp"
#include "hertzdash/simulation/step_resolution.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <map>
#include <type_traits>

namespace hertzdash {

namespace {

// Parameters are text; numbers and booleans go into JSON as such.
nlohmann::ordered_json json_value(const std::string& text) {
  if (text == "true" || text == "false") return text == "true";
  if (const std::optional<double> v = parse_decimal(text)) return *v;
  return text;
}

// The closing keys of a run's report: "inputs" (numbers as numbers) and "git_revision".
void add_inputs_and_revision(nlohmann::ordered_json& j, const Parameters& inputs) {
  nlohmann::ordered_json in;
  for (const auto& [name, value] : inputs) in[name] = json_value(value);
  j["inputs"] = in;
  j["git_revision"] = git_revision();
}

// The names of a set's codes, as a JSON array.
nlohmann::ordered_json codes_json(DiagnosticSet set) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const DiagnosticInfo& d : diagnostic_table)
    if (set.has(d.code)) list.push_back(d.name);
  return list;
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

std::vector<RunDiagnostic> run_diagnostics(const SimulateRun& run, const std::string& trace_note) {
  std::vector<RunDiagnostic> out = impact_diagnostic_list(run.summary, run.setup, run.solver, run.fallback_reason);
  if (!trace_note.empty()) out.push_back({"note", "interpolated_samples", trace_note, {}});
  return out;
}

nlohmann::ordered_json to_json(const SimulateRun& run, const std::string& trace_note) {
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  add_result_fields(j, run.summary, run.setup, to_json(run_diagnostics(run, trace_note)));
  add_inputs_and_revision(j, run.inputs);
  return j;
}

RestitutionRun run_restitution(const RunOptions& options, const PaperParameters& paper, std::optional<double> e_target) {
  RestitutionRun r;
  r.law = options.damping;
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
  j["warnings"] = to_json(run_diagnostics(run));
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

namespace {

// Codes about how a run was made rather than about one impact's result.
bool run_level(Diagnostic d) {
  return d == Diagnostic::integrator_fallback || d == Diagnostic::stability_limit || d == Diagnostic::loose_tolerance;
}

}  // namespace

std::vector<RunDiagnostic> run_diagnostics(const BounceRun& run) {
  const BounceSequence& b = run.sequence;
  std::vector<RunDiagnostic> out;
  std::vector<ImpactSummary> impacts;
  DiagnosticSet any;
  for (const BounceImpact& i : b.impacts) {
    impacts.push_back(bounce_impact_summary(i, b, run.setup));
    for (const DiagnosticInfo& d : diagnostic_table)
      if (i.diagnostics.has(d.code)) any.add(d.code);
  }
  for (const DiagnosticInfo& d : diagnostic_table)
    if (run_level(d.code) && any.has(d.code))
      out.push_back({std::string(d.kind), std::string(d.name),
                     diagnostic_message(d.code, impacts.front(), run.setup, run.solver, run.fallback_reason), {}});
  for (std::size_t n = 0; n < impacts.size(); ++n)
    for (const DiagnosticInfo& d : diagnostic_table)
      if (!run_level(d.code) && d.code != Diagnostic::not_separated && impacts[n].diagnostics.has(d.code))
        out.push_back({std::string(d.kind), std::string(d.name),
                       fmt::format("impact {}: {}", n, diagnostic_message(d.code, impacts[n], run.setup, run.solver,
                                                                           run.fallback_reason)),
                       static_cast<int>(n)});
  return out;
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
                       {"separated", i.separated},
                       {"warnings", codes_json(i.diagnostics)}});
  j["impacts"] = impacts;
  j["onset_times_s"] = b.onset_times_s;
  j["e_from_intervals"] = b.e_from_intervals;
  j["e_velocity_ratio"] = b.e_velocity_ratio;
  j["flights"] = b.flights_integrated ? "integrated" : "closed form";
  j["end_reason"] = b.end_reason;
  j["steps"] = b.work.steps;
  j["rhs_evaluations"] = b.work.rhs_evaluations;
  j["integrator_used"] = to_string(b.integrator_used);
  j["warnings"] = to_json(run_diagnostics(run));
  add_inputs_and_revision(j, run.inputs);
  return j;
}

MeasuredTrace virtual_measurement(const SimulateRun& run, const std::string& rod, const MeasurementChain& chain) {
  MeasuredTrace m = record_virtual_measurement(ImpactHistory(run.trace, run.setup.gravity_mps2), chain);
  const double v = run.summary.impact_velocity_mps, g = run.setup.gravity_mps2;
  m.source = "SYNTHETIC: a virtual experiment made by hertzdash simulate --trace-format measured (the model through "
             "a simulated measurement chain; not a measurement)";
  m.rod = rod;
  m.height_m = run.setup.impact_velocity_mps && g > 0 ? v * v / (2 * g) : run.setup.height_m;
  return m;
}

std::string virtual_measurement_note(const SimulateRun& run, const MeasurementChain& chain) {
  double longest = 0;
  for (std::size_t i = 1; i < run.trace.size(); ++i) longest = std::max(longest, run.trace[i].t_s - run.trace[i - 1].t_s);
  if (!(longest > 1.0 / chain.sample_rate_Hz)) return {};
  return fmt::format("{} took steps up to {:.3g} s, longer than the sampling interval {:.3g} s: the samples between its "
                     "steps are linear interpolations (bound the step with --max-step, or use a fixed --dt, for a "
                     "faithful virtual experiment)",
                     to_string(run.summary.integrator_used), longest, 1.0 / chain.sample_rate_Hz);
}

Parameters virtual_measurement_parameters(const SimulateRun& run, const MeasurementChain& chain) {
  Parameters p = run.inputs;
  p.emplace_back("integrator_used", to_string(run.summary.integrator_used));
  p.emplace_back("sample_rate_Hz", fmt::format("{}", chain.sample_rate_Hz));
  p.emplace_back("anti_alias_cutoff_Hz", fmt::format("{}", chain.anti_alias_cutoff_Hz));
  p.emplace_back("noise_fraction", fmt::format("{}", chain.noise_fraction));
  p.emplace_back("noise_seed", std::to_string(chain.seed));
  return p;
}

FitRun run_fit(const std::string& trace_path, const RunOptions& base, const PaperParameters& paper,
               const TraceFitSettings& settings, bool compare_all_laws) {
  FitRun r;
  r.settings = settings;
  resolve_setup(base, paper);  // bad options are reported before the file is read
  r.trace = read_measured_trace(trace_path);
  if (compare_all_laws) {
    LawComparison c = compare_laws(r.trace, base, paper, settings);
    r.fits = std::move(c.fits);
    r.failures = std::move(c.failures);
  } else {
    r.fits.push_back(fit_trace(r.trace, base, paper, settings));
  }
  return r;
}

namespace {

nlohmann::ordered_json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

}  // namespace

nlohmann::ordered_json to_json(const TraceFit& f, const PaperParameters& paper) {
  nlohmann::ordered_json j;
  j["law"] = f.law;
  nlohmann::ordered_json parameters = nlohmann::ordered_json::array();
  for (const FittedParameter& p : f.parameters)
    parameters.push_back({{"name", p.name},
                          {"initial", p.initial},
                          {"estimate", p.estimate},
                          {"standard_error", number_or_null(p.standard_error)},
                          {"lower", number_or_null(p.lower)},
                          {"upper", number_or_null(p.upper)},
                          {"at_bound", p.at_bound}});
  j["parameters"] = parameters;
  nlohmann::ordered_json correlation = nlohmann::ordered_json::array();
  for (const auto& row : f.correlation) {
    nlohmann::ordered_json r = nlohmann::ordered_json::array();
    for (double c : row) r.push_back(number_or_null(c));
    correlation.push_back(r);
  }
  j["correlation"] = correlation;
  nlohmann::ordered_json channels = nlohmann::ordered_json::array();
  for (const ChannelFit& c : f.channels)
    channels.push_back({{"name", c.name},
                        {"samples", c.samples},
                        {"noise_sigma", c.noise_sigma},
                        {"residual_rms", c.residual_rms}});
  j["channels"] = channels;
  j["samples"] = f.samples;
  j["chi_square"] = f.chi_square;
  j["reduced_chi_square"] = f.reduced_chi_square;
  j["condition_number"] = number_or_null(f.condition_number);
  j["identifiable"] = f.identifiable;
  j["aic"] = f.aic;
  j["bic"] = f.bic;
  j["iterations"] = f.iterations;
  j["model_runs"] = f.model_runs;
  j["stop_reason"] = f.stop_reason;
  j["converged"] = f.converged;
  j["contact_time_s"] = f.contact_time_s;
  nlohmann::ordered_json in;
  const DropTestSetup s = resolve_setup(f.fitted_options, paper);
  for (const auto& [name, value] : describe_run(s, f.law, f.model_solver)) in[name] = json_value(value);
  j["fitted_inputs"] = in;
  return j;
}

nlohmann::ordered_json to_json(const FitRun& run, const PaperParameters& paper) {
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["trace"] = {{"path", run.trace.path.string()},   {"source", run.trace.source},
                {"rod", run.trace.rod},               {"height_m", run.trace.height_m},
                {"synthetic", run.trace.synthetic},   {"samples", run.trace.t_s.size()}};
  nlohmann::ordered_json fits = nlohmann::ordered_json::array();
  for (const TraceFit& f : run.fits) fits.push_back(to_json(f, paper));
  j["fits"] = fits;
  nlohmann::ordered_json failures = nlohmann::ordered_json::array();
  for (const auto& [law, why] : run.failures) failures.push_back({{"law", law}, {"error", why}});
  j["failures"] = failures;
  j["warnings"] = to_json(fit_diagnostics(run, paper));
  j["git_revision"] = git_revision();
  return j;
}

void write_fit_curves(const TraceFit& f, const MeasuredTrace& trace, const std::filesystem::path& path) {
  std::vector<std::string> columns{"t_s"};
  for (const ChannelFit& c : f.channels)
    for (const char* what : {"measured", "model", "residual"}) columns.push_back(c.name + "_" + what);
  Parameters header{{"trace", trace.path.string()}, {"trace_source", trace.source},
                    {"synthetic", trace.synthetic ? "true" : "false"}, {"damping", f.law}};
  for (const FittedParameter& p : f.parameters) header.emplace_back(p.name + "_estimate", fmt::format("{}", p.estimate));
  CsvWriter csv("hertzdash fit: the trace, the fitted model and the residuals (time on the trace's clock)", header,
                columns);
  std::map<double, std::vector<CsvWriter::Cell>> rows;  // by sample time: channels may have gaps
  for (std::size_t c = 0; c < f.channels.size(); ++c) {
    const ChannelFit& ch = f.channels[c];
    for (std::size_t i = 0; i < ch.t_s.size(); ++i) {
      auto& row = rows[ch.t_s[i]];
      if (row.empty()) row.assign(columns.size(), std::string());
      row[0] = ch.t_s[i];
      row[1 + 3 * c] = ch.measured[i];
      row[2 + 3 * c] = ch.model[i];
      row[3 + 3 * c] = ch.measured[i] - ch.model[i];
    }
  }
  for (const auto& [t, row] : rows) csv.add_row(row);
  csv.save(path);
}

std::vector<RunDiagnostic> fit_diagnostics(const FitRun& run, const PaperParameters& paper) {
  std::vector<RunDiagnostic> w;
  auto warn = [&w](const char* code, std::string message) { w.push_back({"warning", code, std::move(message), {}}); };
  if (run.trace.synthetic) warn("synthetic_trace", "the trace says 'synthetic: true': it is not a measurement");
  for (const TraceFit& f : run.fits) {
    const std::string law = run.fits.size() > 1 ? " (" + f.law + ")" : "";
    if (!f.converged)
      warn("not_converged",
           fmt::format("the fit{} did not converge ({}): the estimates are where it stopped", law, f.stop_reason));
    if (!f.identifiable)
      warn("not_identifiable",
           fmt::format("the trace does not determine the parameters{}: condition number {:.3g} (limit {:g}), a "
                       "correlation beyond {:g} or an infinite standard error; fit fewer parameters or add a channel",
                       law, f.condition_number, identifiable_condition_limit, identifiable_correlation_limit));
    for (const FittedParameter& p : f.parameters)
      if (p.at_bound)
        warn("at_bound", fmt::format("{}{} ended at a bound ({:.6g}); its standard error does not hold", p.name, law,
                                     p.estimate));
    if (f.reduced_chi_square > 2)
      warn("poor_fit", fmt::format("the model{} does not explain the trace to its noise: reduced chi-square {:.3g} "
                                   "(about 1 if it did); the standard errors are scaled by it",
                                   law, f.reduced_chi_square));
    DropTestSetup s = resolve_setup(f.fitted_options, paper);
    s.impact_velocity_mps = approach_speed(s);  // the fit's model starts at contact onset
    for (RunDiagnostic& d : impact_diagnostic_list(f.model_summary, s, f.model_solver, {})) {
      d.message = "the fitted model" + law + ": " + d.message;
      w.push_back(std::move(d));
    }
  }
  return w;
}

nlohmann::ordered_json registered_laws_json() {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for_each_damping_law([&]<class Law>(std::type_identity<Law>) {
    const LawInfo& l = Law::info;
    list.push_back({{"name", l.name},
                    {"citation", l.citation},
                    {"formula", l.formula},
                    {"coefficients", l.coefficients},
                    {"validity", l.validity},
                    {"force_continuous_at_onset", l.force_continuous_at_onset},
                    {"dissipative", !ConservativeLaw<Law>}});
  });
  return list;
}

}  // namespace hertzdash
