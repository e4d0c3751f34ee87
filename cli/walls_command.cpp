// `hertzdash walls`: a body between two walls, a box of clearance --gap either driven
// harmonically (--rig box: X(t) = A sin(2 pi f t)) or mounted on a primary oscillator under a
// harmonic force (--rig damper: the impact damper), soft contacts or instantaneous impacts,
// exact flights between impacts (simulation/shaker/two_walls.hpp,
// docs/shaker.md). Per kept impact the wall, drive phase, relative speeds, contact time, peak
// force and the box's displacement; the period, impacts per cycle, and for the damper the
// primary's amplitude with the body and without it; --json, or --csv FILE (one row per kept impact).
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/setup_options.hpp"
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/model/shaker_parameters.hpp"
#include "hertzdash/model/two_walls_parameters.hpp"
#include "hertzdash/simulation/reports/shaker_report.hpp"
#include "hertzdash/simulation/reports/two_walls_report.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>

namespace hertzdash::cli {

namespace {

struct WallsCommandOptions {
  RunOptions run;
  TwoWallsInputs walls;
  std::string csv_path;
  bool json = false, mkdir = false;
};

void print_text(const TwoWallsCommandRun& r) {
  const TwoWallsRun& s = r.run;
  const bool soft = s.impact_model == ShakerImpactModel::soft, box = s.rig == TwoWallsRig::box;
  std::cout << fmt::format("hertzdash walls: {}, {} impacts{}\n", box ? "driven box" : "impact damper",
                           to_string(s.impact_model),
                           soft ? fmt::format(", damping law '{}', integrator {}", r.law, to_string(s.integrator_used))
                                : fmt::format(", e = {}", r.setup.restitution));
  auto line = [](std::string_view key, const std::string& value) { std::cout << fmt::format("  {:<26} {}\n", key, value); };
  line("gap_m", fmt::format("{:.6g}", r.options.gap_m));
  line("frequency_Hz", fmt::format("{:.6g}", r.options.drive.frequency_Hz));
  if (box) line("amplitude_m", fmt::format("{:.6g}", r.options.drive.amplitude_m));
  line("period", std::to_string(s.pattern.period));
  line("impacts_per_period", std::to_string(s.pattern.impacts_per_period));
  line("impacts_per_cycle", fmt::format("{:.6g}", s.impacts_per_cycle));
  line("floor_impacts", std::to_string(s.floor_impacts));
  line("ceiling_impacts", std::to_string(s.ceiling_impacts));
  line("e_effective", fmt::format("{:.6g}", s.e_effective));
  if (!box) {
    line("primary_amplitude_m", fmt::format("{:.6g}", s.primary_amplitude_m));
    line("primary_amplitude_bare_m", fmt::format("{:.6g}", s.primary_amplitude_bare_m));
    line("primary_amplitude_rigid_m", fmt::format("{:.6g}", s.primary_amplitude_rigid_m));
  }
  line("sticking_episodes", std::to_string(s.sticking_episodes));
  std::cout << fmt::format("  {:>6} {:>16} {:>10} {:>7} {:>16} {:>17} {:>14} {:>12}\n", "n", "impact_time_s", "phase",
                           "wall", "impact_speed_mps", "rebound_speed_mps", "contact_time_s", "peak_force_N");
  for (std::size_t n = 0; n < s.impacts.size(); ++n) {
    const TwoWallsImpact& i = s.impacts[n];
    std::cout << fmt::format("  {:>6} {:>16.9f} {:>10.7f} {:>7} {:>16.9g} {:>17.9g} {:>14.6g} {:>12.6g}\n", n,
                             i.time_s, i.phase, to_string(i.wall), i.impact_speed_mps, i.rebound_speed_mps,
                             i.contact_time_s, i.peak_force_N);
  }
  std::cout << fmt::format("  ended: {}", s.end_reason);
  if (soft) std::cout << fmt::format("; {} steps, {} rhs evaluations", s.work.steps, s.work.rhs_evaluations);
  std::cout << "\n";
}

void write_csv(const TwoWallsCommandRun& r, const std::string& path) {
  CsvWriter csv("hertzdash walls: one row per kept impact (time from the start, the body at rest at mid-gap; phase "
                "of the drive sin(2 pi f t) in [0,1); wall 0 floor, 1 ceiling; speeds relative to the box)",
                r.inputs,
                {"n", "impact_time_s", "impact_phase", "wall", "impact_speed_mps", "rebound_speed_mps", "contact_time_s",
                 "peak_force_N", "box_displacement_m"});
  const TwoWallsRun& s = r.run;
  csv.add_comment(fmt::format("period: {}", s.pattern.period));
  csv.add_comment(fmt::format("impacts_per_period: {}", s.pattern.impacts_per_period));
  if (s.rig == TwoWallsRig::damper) {
    csv.add_comment(fmt::format("primary_amplitude_m: {}", s.primary_amplitude_m));
    csv.add_comment(fmt::format("primary_amplitude_bare_m: {}", s.primary_amplitude_bare_m));
    csv.add_comment(fmt::format("primary_amplitude_rigid_m: {}", s.primary_amplitude_rigid_m));
  }
  for (const std::string& w : s.warnings) csv.add_comment("warning: " + w);
  for (std::size_t n = 0; n < s.impacts.size(); ++n) {
    const TwoWallsImpact& i = s.impacts[n];
    csv.add_row({static_cast<long>(n), i.time_s, i.phase, static_cast<long>(i.wall), i.impact_speed_mps,
                 i.rebound_speed_mps, i.contact_time_s, i.peak_force_N, i.box_displacement_m});
  }
  csv.save(path);
}

}  // namespace

Command add_walls_command(CLI::App& app) {
  namespace s = shaker_parameters;
  namespace p = two_walls_parameters;
  auto opt = std::make_shared<WallsCommandOptions>();
  opt->run.integrator = shaker_default_integrator;  // the soft contact runs in regularising variables
  CLI::App* sub = app.add_subcommand(
      "walls", "A body between two walls: a harmonically driven box, or the impact damper (a box on a primary "
               "oscillator under a harmonic force); exact flights");
  add_run_options(*sub, opt->run);
  sub->get_option("--integrator")
      ->description("Integrator of the soft contacts, one in regularising variables (docs/shaker.md): "
                    "dopri5-regularized, cvode-regularized, gbs8-regularized, taylor-regularized (default: "
                    "gbs8-regularized)");
  auto help = [](const ParameterDecl& d) { return help_text(d, KeySpelling::command_line); };
  const std::string group = "Two walls";
  sub->add_option_function<std::string>("--rig", [opt](const std::string& v) { opt->walls.rig = v; }, help(p::rig))
      ->group(group);
  add_number_option(*sub, "--gap", opt->walls.gap_m, help(p::gap))->group(group);
  add_number_option(*sub, "--frequency", opt->walls.frequency_Hz, help(s::frequency))->group(group);
  add_number_option(*sub, "--amplitude", opt->walls.amplitude_m, help(s::amplitude))->group(group);
  add_number_option(*sub, "--gamma", opt->walls.gamma, help(s::gamma))->group(group);
  add_number_option(*sub, "--primary-mass", opt->walls.primary_mass_kg, help(p::primary_mass))->group(group);
  add_number_option(*sub, "--primary-stiffness", opt->walls.primary_stiffness_N_per_m, help(p::primary_stiffness))
      ->group(group);
  add_number_option(*sub, "--primary-damping-ratio", opt->walls.primary_damping_ratio, help(p::primary_damping_ratio))
      ->group(group);
  add_number_option(*sub, "--force-amplitude", opt->walls.force_amplitude_N, help(p::force_amplitude))->group(group);
  add_number_option(*sub, "--impacts", opt->walls.impacts, help(s::impacts))->type_name("INT")->group(group);
  add_number_option(*sub, "--transient", opt->walls.transient, help(s::transient))->type_name("INT")->group(group);
  sub->add_option_function<std::string>("--impact-model", [opt](const std::string& v) { opt->walls.impact_model = v; },
                                        help(s::impact_model))
      ->group(group);
  sub->add_flag("--json", opt->json, "Print the result as one JSON object");
  add_output_file_option(*sub, "--csv", opt->csv_path, "Write the kept impacts to this CSV file, one row each");
  add_mkdir_flag(*sub, opt->mkdir);

  return {sub, [opt]() {
            prepare_output_file("--csv", opt->csv_path, opt->mkdir);
            const TwoWallsCommandRun r = run_two_walls_command(opt->run, load_paper_parameters(), opt->walls);
            if (!opt->csv_path.empty()) {
              create_output_directories(opt->csv_path, opt->mkdir);
              write_csv(r, opt->csv_path);
            }
            for (const std::string& w : r.run.warnings) std::cerr << "hertzdash: warning: " << w << "\n";
            if (opt->json) std::cout << to_json(r).dump(2) << "\n";
            else print_text(r);
            return 0;
          }};
}

}  // namespace hertzdash::cli
