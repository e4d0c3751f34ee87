// `shaker`'s run and report (simulation/reports/shaker_report.hpp).
#include "hertzdash/simulation/reports/shaker_report.hpp"

#include "hertzdash/model/shaker_parameters.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"

#include <fmt/format.h>

namespace hertzdash {

namespace {

double given_or_default(const std::optional<double>& v, const ParameterDecl& p) {
  const double x = v.value_or(p.default_number);
  require_in_range(p, x);
  return x;
}

}  // namespace

ShakerCommandRun resolve_shaker_command(const RunOptions& options, const PaperParameters& paper, const ShakerInputs& in) {
  namespace p = shaker_parameters;
  if (options.impact_velocity_mps)
    throw InvalidParameter("impact-velocity", format_value(*options.impact_velocity_mps),
                           "not given for `shaker` (the body starts at rest, at `height` above the wall's mean position)");
  if (in.amplitude_m && in.gamma)
    throw InvalidParameter("gamma", format_value(*in.gamma), "omitted with `amplitude` (one sets the other)");
  ShakerCommandRun r;
  r.setup = resolve_setup(options, paper);
  refuse_trace_only_options(options, "hertzdash shaker");
  r.law = options.damping;
  r.solver = resolve_solver(options);
  ShakerOptions& o = r.options;
  o.wall.frequency_Hz = given_or_default(in.frequency_Hz, p::frequency);
  if (in.amplitude_m) {
    require_in_range(p::amplitude, *in.amplitude_m);
    o.wall.amplitude_m = *in.amplitude_m;
  } else {
    o.wall.amplitude_m =
        shaker_amplitude_m(given_or_default(in.gamma, p::gamma), o.wall.frequency_Hz, r.setup.gravity_mps2);
  }
  o.impacts = static_cast<int>(given_or_default(in.impacts, p::impacts));
  o.transient = static_cast<int>(given_or_default(in.transient, p::transient));
  o.start_height_m = options.height_m;
  if (in.start_phase) require_in_range(p::start_phase, *in.start_phase);
  o.start_phase = in.start_phase;
  o.impact_model = parse_shaker_impact_model(in.impact_model.value_or(std::string(p::impact_model.default_value)));
  if (o.impact_model == ShakerImpactModel::instantaneous) {  // Newton's law reads e, the flights g
    RunOptions defaults;
    defaults.integrator = shaker_default_integrator;
    static constexpr std::string_view read[] = {"rod", "restitution", "gravity", "height"};
    refuse_options_not_read(options, defaults, read,
                            "`impact-model` soft (the instantaneous map reads `restitution`, `gravity` and `height`)");
  }
  r.inputs = describe_run(r.setup, r.law, r.solver);
  r.inputs.emplace_back("frequency_Hz", fmt::format("{}", o.wall.frequency_Hz));
  r.inputs.emplace_back("amplitude_m", fmt::format("{}", o.wall.amplitude_m));
  r.inputs.emplace_back("impacts", std::to_string(o.impacts));
  r.inputs.emplace_back("transient", std::to_string(o.transient));
  r.inputs.emplace_back("impact_model", to_string(o.impact_model));
  const ShakerStart start = shaker_start(o, r.setup.restitution, r.setup.gravity_mps2);
  r.inputs.emplace_back("start_height_m", fmt::format("{}", start.height_m));
  r.inputs.emplace_back("start_phase", fmt::format("{}", start.phase));
  return r;
}

ShakerCommandRun run_shaker_command(const RunOptions& options, const PaperParameters& paper, const ShakerInputs& in) {
  ShakerCommandRun r = resolve_shaker_command(options, paper, in);
  r.run = run_shaker(r.setup, r.law, r.solver, r.options);
  return r;
}

nlohmann::ordered_json to_json(const ShakerCommandRun& r) {
  using report_detail::number_or_null;
  const ShakerRun& s = r.run;
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["gamma"] = s.gamma;
  j["frequency_Hz"] = r.options.wall.frequency_Hz;
  j["amplitude_m"] = r.options.wall.amplitude_m;
  j["impact_model"] = to_string(s.impact_model);
  j["damping"] = r.law;
  if (s.impact_model == ShakerImpactModel::soft) j["integrator_used"] = to_string(s.integrator_used);
  j["period"] = s.pattern.period;
  j["impacts_per_period"] = s.pattern.impacts_per_period;
  j["e_effective"] = number_or_null(s.e_effective);
  auto column = [&](auto field) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const ShakerImpact& i : s.impacts) a.push_back(field(i));
    return a;
  };
  j["impact_time_s"] = column([](const ShakerImpact& i) { return i.time_s; });
  j["impact_phase"] = column([](const ShakerImpact& i) { return i.phase; });
  j["impact_speed_mps"] = column([](const ShakerImpact& i) { return i.impact_speed_mps; });
  j["rebound_speed_mps"] = column([](const ShakerImpact& i) { return i.rebound_speed_mps; });
  j["contact_time_s"] = column([](const ShakerImpact& i) { return i.contact_time_s; });
  j["peak_force_N"] = column([](const ShakerImpact& i) { return i.peak_force_N; });
  j["sticking_episodes"] = s.sticking_episodes;
  j["impacts_run"] = s.impacts_run;
  j["end_reason"] = s.end_reason;
  j["warnings"] = s.warnings;
  if (s.impact_model == ShakerImpactModel::soft)
    j["work"] = {{"steps", s.work.steps}, {"rhs_evaluations", s.work.rhs_evaluations}};
  report_detail::add_inputs_and_revision(j, r.inputs);
  return j;
}

std::vector<std::string> shaker_csv_columns() {
  return {"n", "impact_time_s", "impact_phase", "impact_speed_mps", "rebound_speed_mps", "contact_time_s",
          "peak_force_N"};
}

std::vector<double> shaker_csv_row(const ShakerImpact& i, std::size_t n) {
  return {static_cast<double>(n), i.time_s, i.phase, i.impact_speed_mps, i.rebound_speed_mps, i.contact_time_s,
          i.peak_force_N};
}

}  // namespace hertzdash
