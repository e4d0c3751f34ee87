// `walls`' run and report (simulation/reports/two_walls_report.hpp).
#include "hertzdash/simulation/reports/two_walls_report.hpp"

#include "hertzdash/model/shaker_parameters.hpp"
#include "hertzdash/model/two_walls_parameters.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/shaker_report.hpp"
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

/// Refuse an option given where the rig does not read it.
void refuse_unless(bool read, const std::optional<double>& v, const ParameterDecl& p, std::string_view rig) {
  if (!read && v) throw InvalidParameter(std::string(p.key), format_value(*v), fmt::format("not given with `rig` {}", rig));
}

}  // namespace

TwoWallsCommandRun run_two_walls_command(const RunOptions& options, const PaperParameters& paper,
                                         const TwoWallsInputs& in) {
  namespace s = shaker_parameters;
  namespace p = two_walls_parameters;
  if (options.impact_velocity_mps)
    throw InvalidParameter("impact-velocity", format_value(*options.impact_velocity_mps),
                           "not given for `walls` (the body starts at rest at mid-gap)");
  if (options.height_m)
    throw InvalidParameter("height", format_value(*options.height_m),
                           "not given for `walls` (the body starts at rest at mid-gap)");
  TwoWallsCommandRun r;
  TwoWallsOptions& o = r.options;
  o.rig = parse_two_walls_rig(in.rig.value_or(std::string(p::rig.default_value)));
  const bool box = o.rig == TwoWallsRig::box;
  const std::string_view rig = to_string(o.rig);
  refuse_unless(box, in.amplitude_m, s::amplitude, rig);
  refuse_unless(box, in.gamma, s::gamma, rig);
  for (const auto& [value, decl] : {std::pair{&in.primary_mass_kg, &p::primary_mass},
                                    std::pair{&in.primary_stiffness_N_per_m, &p::primary_stiffness},
                                    std::pair{&in.primary_damping_ratio, &p::primary_damping_ratio},
                                    std::pair{&in.force_amplitude_N, &p::force_amplitude}})
    refuse_unless(!box, *value, *decl, rig);
  if (in.amplitude_m && in.gamma)
    throw InvalidParameter("gamma", format_value(*in.gamma), "omitted with `amplitude` (one sets the other)");
  o.gap_m = given_or_default(in.gap_m, p::gap);
  o.drive.frequency_Hz = given_or_default(in.frequency_Hz, s::frequency);
  const double w = o.drive.omega_rad_per_s();
  // The set-up's representative approach speed (its Hertz-scale check; a viscoelastic law's
  // calibration without `reference-velocity`) is the drop test's sqrt(2 g h); with g = 0 (a
  // horizontal box) it is the box's speed scale: A w, or the bare primary's steady amplitude times w.
  RunOptions set_up = options;
  const bool horizontal = options.gravity_mps2 && *options.gravity_mps2 == 0;
  double speed_scale_mps = 0;
  if (box) {
    if (in.amplitude_m) {
      require_in_range(s::amplitude, *in.amplitude_m);
      o.drive.amplitude_m = *in.amplitude_m;
    } else if (horizontal) {
      throw InvalidParameter("gamma", format_value(given_or_default(in.gamma, s::gamma)),
                             "omitted with `gravity` 0 (gamma is in units of g): give `amplitude`");
    }
    speed_scale_mps = o.drive.amplitude_m * w;
  } else {
    o.primary.mass_kg = given_or_default(in.primary_mass_kg, p::primary_mass);
    o.primary.stiffness_N_per_m = given_or_default(in.primary_stiffness_N_per_m, p::primary_stiffness);
    o.primary.damping_ratio = given_or_default(in.primary_damping_ratio, p::primary_damping_ratio);
    o.primary.force_amplitude_N = given_or_default(in.force_amplitude_N, p::force_amplitude);
    ForcedOscillator bare = o.primary;
    bare.omega_rad_per_s = w;
    speed_scale_mps = bare.steady_amplitude_m() * w;
  }
  if (horizontal) {
    if (!(speed_scale_mps > 0))
      throw InvalidParameter(box ? "amplitude" : "force-amplitude",
                             format_value(box ? o.drive.amplitude_m : o.primary.force_amplitude_N),
                             "> 0 with `gravity` 0 (nothing would move the body)");
    set_up.impact_velocity_mps = speed_scale_mps;
  }
  r.setup = resolve_setup(set_up, paper);
  refuse_trace_only_options(options, "hertzdash walls");
  r.law = options.damping;
  r.solver = resolve_solver(options);
  if (box && !in.amplitude_m)
    o.drive.amplitude_m =
        shaker_amplitude_m(given_or_default(in.gamma, s::gamma), o.drive.frequency_Hz, r.setup.gravity_mps2);
  o.impacts = static_cast<int>(given_or_default(in.impacts, s::impacts));
  o.transient = static_cast<int>(given_or_default(in.transient, s::transient));
  o.impact_model = parse_shaker_impact_model(in.impact_model.value_or(std::string(s::impact_model.default_value)));
  if (o.impact_model == ShakerImpactModel::instantaneous) {  // Newton's law reads e, the flights g, momentum m
    RunOptions defaults;
    defaults.integrator = shaker_default_integrator;
    static constexpr std::string_view box_reads[] = {"rod", "restitution", "gravity"};
    static constexpr std::string_view damper_reads[] = {"rod", "restitution", "gravity", "mass"};
    refuse_options_not_read(options, defaults, box ? std::span<const std::string_view>(box_reads) : damper_reads,
                            box ? "`impact-model` soft (the instantaneous box reads `restitution` and `gravity`)"
                                : "`impact-model` soft (the instantaneous damper reads `restitution`, `gravity` and "
                                  "`mass`)");
  }
  r.inputs = describe_run(r.setup, r.law, r.solver);
  r.inputs.emplace_back("rig", std::string(rig));
  r.inputs.emplace_back("gap_m", fmt::format("{}", o.gap_m));
  r.inputs.emplace_back("frequency_Hz", fmt::format("{}", o.drive.frequency_Hz));
  if (box) {
    r.inputs.emplace_back("amplitude_m", fmt::format("{}", o.drive.amplitude_m));
  } else {
    r.inputs.emplace_back("primary_mass_kg", fmt::format("{}", o.primary.mass_kg));
    r.inputs.emplace_back("primary_stiffness_N_per_m", fmt::format("{}", o.primary.stiffness_N_per_m));
    r.inputs.emplace_back("primary_damping_ratio", fmt::format("{}", o.primary.damping_ratio));
    r.inputs.emplace_back("force_amplitude_N", fmt::format("{}", o.primary.force_amplitude_N));
  }
  r.inputs.emplace_back("impacts", std::to_string(o.impacts));
  r.inputs.emplace_back("transient", std::to_string(o.transient));
  r.inputs.emplace_back("impact_model", to_string(o.impact_model));
  r.run = run_two_walls(r.setup, r.law, r.solver, o);
  return r;
}

nlohmann::ordered_json to_json(const TwoWallsCommandRun& r) {
  using report_detail::number_or_null;
  const TwoWallsRun& s = r.run;
  const bool box = s.rig == TwoWallsRig::box;
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["rig"] = to_string(s.rig);
  j["gap_m"] = r.options.gap_m;
  j["frequency_Hz"] = r.options.drive.frequency_Hz;
  if (box) {
    j["amplitude_m"] = r.options.drive.amplitude_m;
    j["gamma"] = number_or_null(shaker_gamma(r.options.drive, r.setup.gravity_mps2));
  }
  j["impact_model"] = to_string(s.impact_model);
  j["damping"] = r.law;
  if (s.impact_model == ShakerImpactModel::soft) j["integrator_used"] = to_string(s.integrator_used);
  j["period"] = s.pattern.period;
  j["impacts_per_period"] = s.pattern.impacts_per_period;
  j["impacts_per_cycle"] = s.impacts_per_cycle;
  j["floor_impacts"] = s.floor_impacts;
  j["ceiling_impacts"] = s.ceiling_impacts;
  j["e_effective"] = number_or_null(s.e_effective);
  if (!box) {
    j["primary_amplitude_m"] = number_or_null(s.primary_amplitude_m);
    j["primary_amplitude_bare_m"] = s.primary_amplitude_bare_m;
    j["primary_amplitude_rigid_m"] = s.primary_amplitude_rigid_m;
  }
  if (!box && s.impact_model == ShakerImpactModel::instantaneous) {
    j["energy_J"] = {{"initial", s.energy.initial_J},
                     {"final", s.energy.final_J},
                     {"drive_work", s.energy.drive_work_J},
                     {"damping_dissipation", s.energy.damping_dissipation_J},
                     {"impact_loss", s.energy.impact_loss_J}};
  }
  auto column = [&](auto field) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const TwoWallsImpact& i : s.impacts) a.push_back(field(i));
    return a;
  };
  j["impact_time_s"] = column([](const TwoWallsImpact& i) { return i.time_s; });
  j["impact_phase"] = column([](const TwoWallsImpact& i) { return i.phase; });
  j["wall"] = column([](const TwoWallsImpact& i) { return to_string(i.wall); });
  j["impact_speed_mps"] = column([](const TwoWallsImpact& i) { return i.impact_speed_mps; });
  j["rebound_speed_mps"] = column([](const TwoWallsImpact& i) { return i.rebound_speed_mps; });
  j["contact_time_s"] = column([](const TwoWallsImpact& i) { return i.contact_time_s; });
  j["peak_force_N"] = column([](const TwoWallsImpact& i) { return i.peak_force_N; });
  j["box_displacement_m"] = column([](const TwoWallsImpact& i) { return i.box_displacement_m; });
  j["sticking_episodes"] = s.sticking_episodes;
  j["impacts_run"] = s.impacts_run;
  j["end_reason"] = s.end_reason;
  j["warnings"] = s.warnings;
  if (s.impact_model == ShakerImpactModel::soft)
    j["work"] = {{"steps", s.work.steps}, {"rhs_evaluations", s.work.rhs_evaluations}};
  report_detail::add_inputs_and_revision(j, r.inputs);
  return j;
}

}  // namespace hertzdash
