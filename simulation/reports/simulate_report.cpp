// `simulate`'s run and report (simulation/reports/run_reports.hpp): resolve, validate and run one drop
// test, list its notes and warnings, and build its JSON.
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/result_output.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

namespace hertzdash {

using report_detail::add_inputs_and_revision;

SimulateRun run_simulate(const RunOptions& options, const PaperParameters& paper, bool record_trace) {
  SimulateRun r;
  r.setup = resolve_setup(options, paper);
  if (!record_trace) refuse_trace_only_options(options, "hertzdash simulate without a trace file");
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

}  // namespace hertzdash
