// `bounce`'s run and report (simulation/reports/run_reports.hpp): a drop and its bounces, with the input
// e calibrated to an interval ratio if asked, the sequence's notes and warnings (each code once,
// with the impacts it holds for), and its JSON.
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <fmt/format.h>

namespace hertzdash {

using report_detail::add_inputs_and_revision;

namespace {

// The names of a set's codes, as a JSON array.
nlohmann::ordered_json codes_json(DiagnosticSet set) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const DiagnosticInfo& d : diagnostic_table)
    if (set.has(d.code)) list.push_back(d.name);
  return list;
}

// Ascending indices as runs: {0, 1, 2, 4, 6, 7} -> "0-2, 4, 6-7".
std::string index_ranges(const std::vector<std::size_t>& indices) {
  std::string text;
  for (std::size_t i = 0; i < indices.size();) {
    std::size_t j = i;
    while (j + 1 < indices.size() && indices[j + 1] == indices[j] + 1) ++j;
    text += (text.empty() ? "" : ", ") +
            (j == i ? std::to_string(indices[i]) : fmt::format("{}-{}", indices[i], indices[j]));
    i = j + 1;
  }
  return text;
}

// Codes about how a run was made rather than about one impact's result.
bool run_level(Diagnostic d) {
  return d == Diagnostic::integrator_fallback || d == Diagnostic::stability_limit || d == Diagnostic::loose_tolerance;
}

}  // namespace

BounceRun run_bounce(const RunOptions& options, const PaperParameters& paper, const BounceOptions& bounce,
                     std::optional<double> interval_target) {
  BounceRun r;
  if (interval_target && options.restitution)
    throw InvalidParameter("restitution", format_value(*options.restitution),
                           "omitted with `target-interval-restitution` (the calibration finds the input e)");
  RunOptions flying = options;
  flying.follows_flights = true;  // the sequence's flights read the air drag
  r.setup = resolve_setup(flying, paper);
  refuse_trace_only_options(options, "hertzdash bounce");
  r.law = options.damping;
  r.solver = resolve_solver(flying);
  r.options = bounce;
  validate(r.options);
  r.interval_target = interval_target;
  if (interval_target) {
    r.calibration = calibrate_interval_restitution(r.setup, r.law, r.solver, *interval_target);
    r.setup.restitution = r.calibration->e_input;
    r.setup.restitution_of_other_pair = false;  // e is now this pair's own, found for the target
  }
  r.inputs = describe_run(r.setup, r.law, r.solver);
  r.inputs.emplace_back("bounces", std::to_string(bounce.impacts));
  r.inputs.emplace_back("min_rebound_velocity_mps", fmt::format("{}", bounce.min_rebound_velocity_mps));
  integrator_used(r.solver, r.setup, r.law, &r.fallback_reason);
  r.sequence = run_bounce_sequence(r.setup, r.law, r.solver, r.options);
  return r;
}

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
  // A code about an impact's result once, with the impacts it holds for and the message of the
  // first of them: "impacts 0-4 (5 of 5); at impact 0: ...".
  for (const DiagnosticInfo& d : diagnostic_table) {
    if (run_level(d.code) || d.code == Diagnostic::not_separated) continue;
    std::vector<std::size_t> with;
    for (std::size_t n = 0; n < impacts.size(); ++n)
      if (impacts[n].diagnostics.has(d.code)) with.push_back(n);
    if (with.empty()) continue;
    const std::size_t first = with.front();
    const std::string where =
        with.size() == 1 ? fmt::format("impact {}", first)
                         : fmt::format("impacts {} ({} of {}); at impact {}", index_ranges(with), with.size(),
                                       impacts.size(), first);
    out.push_back({std::string(d.kind), std::string(d.name),
                   where + ": " + diagnostic_message(d.code, impacts[first], run.setup, run.solver, run.fallback_reason),
                   static_cast<int>(first)});
  }
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

}  // namespace hertzdash
