// `hertzdash shaker`: a body bouncing on a harmonically vibrating wall s(t) = A sin(2 pi f t),
// with the drop test's body, contact and law (soft impacts, integrated with the wall's motion as
// a forcing) or Newton's instantaneous impact with e = --restitution (the textbook bouncing-ball
// map), exact flights between impacts (simulation/shaker/shaker.hpp, docs/shaker.md). Per kept
// impact the table phase, relative impact and rebound speeds, contact time and peak force; the
// detected period (table cycles) and impacts per period.
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/setup_options.hpp"
#include "cli/shaker_sweep.hpp"
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/model/shaker_parameters.hpp"
#include "hertzdash/model/shaker_sweep_parameters.hpp"
#include "hertzdash/simulation/reports/shaker_report.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>

namespace hertzdash::cli {

namespace {

struct ShakerCommandOptions {
  RunOptions run;
  ShakerInputs shaker;
  std::string csv_path, sweep;
  std::optional<double> threads;
  bool json = false, mkdir = false;
};

void print_text(const ShakerCommandRun& r) {
  const ShakerRun& s = r.run;
  const bool soft = s.impact_model == ShakerImpactModel::soft;
  std::cout << fmt::format("hertzdash shaker: {} impacts{}\n", to_string(s.impact_model),
                           soft ? fmt::format(", damping law '{}', integrator {}", r.law, to_string(s.integrator_used))
                                : fmt::format(", e = {}", r.setup.restitution));
  std::cout << fmt::format("  {:<20} {:.6g}\n  {:<20} {:.6g}\n  {:<20} {:.6g}\n", "gamma", s.gamma, "frequency_Hz",
                           r.options.wall.frequency_Hz, "amplitude_m", r.options.wall.amplitude_m);
  std::cout << fmt::format("  {:<20} {}\n  {:<20} {}\n  {:<20} {:.6g}\n  {:<20} {}\n", "period", s.pattern.period,
                           "impacts_per_period", s.pattern.impacts_per_period, "e_effective", s.e_effective,
                           "sticking_episodes", s.sticking_episodes);
  std::cout << fmt::format("  {:>6} {:>16} {:>10} {:>16} {:>17} {:>14} {:>12}\n", "n", "impact_time_s", "phase",
                           "impact_speed_mps", "rebound_speed_mps", "contact_time_s", "peak_force_N");
  for (std::size_t n = 0; n < s.impacts.size(); ++n) {
    const ShakerImpact& i = s.impacts[n];
    std::cout << fmt::format("  {:>6} {:>16.9f} {:>10.7f} {:>16.9g} {:>17.9g} {:>14.6g} {:>12.6g}\n", n, i.time_s,
                             i.phase, i.impact_speed_mps, i.rebound_speed_mps, i.contact_time_s, i.peak_force_N);
  }
  std::cout << fmt::format("  ended: {}", s.end_reason);
  if (soft) std::cout << fmt::format("; {} steps, {} rhs evaluations", s.work.steps, s.work.rhs_evaluations);
  std::cout << "\n";
}

void write_csv(const ShakerCommandRun& r, const std::string& path) {
  CsvWriter csv("hertzdash shaker: one row per kept impact (time from the start, the body at rest on the wall; "
                "phase of s(t) = A sin(2 pi f t) in [0,1); speeds relative to the wall)",
                r.inputs, shaker_csv_columns());
  csv.add_comment(fmt::format("gamma: {}", r.run.gamma));
  csv.add_comment(fmt::format("period: {}", r.run.pattern.period));
  csv.add_comment(fmt::format("impacts_per_period: {}", r.run.pattern.impacts_per_period));
  for (const std::string& w : r.run.warnings) csv.add_comment("warning: " + w);
  for (std::size_t n = 0; n < r.run.impacts.size(); ++n) {
    std::vector<CsvWriter::Cell> row;
    const std::vector<double> cells = shaker_csv_row(r.run.impacts[n], n);
    row.emplace_back(static_cast<long>(n));
    for (std::size_t c = 1; c < cells.size(); ++c) row.emplace_back(cells[c]);
    csv.add_row(row);
  }
  csv.save(path);
}

}  // namespace

Command add_shaker_command(CLI::App& app) {
  namespace p = shaker_parameters;
  auto opt = std::make_shared<ShakerCommandOptions>();
  opt->run.integrator = shaker_default_integrator;  // the shaker's contact runs in regularising variables
  CLI::App* sub = app.add_subcommand(
      "shaker", "A body bouncing on a vibrating wall: soft contacts or instantaneous impacts, exact flights");
  add_run_options(*sub, opt->run);
  // Two of simulate's options mean something else here (simulation/shaker/shaker.hpp).
  sub->get_option("--integrator")
      ->description("Integrator of the soft contacts, one in regularising variables (docs/shaker.md): "
                    "dopri5-regularized, cvode-regularized, gbs8-regularized, taylor-regularized (default: "
                    "gbs8-regularized)");
  sub->get_option("--height")
      ->description("Height [m] above the wall's mean position from which the body is released at rest at "
                    "--start-phase; 0: at rest on the wall (default: the apex of the instantaneous map's "
                    "period-1 orbit, docs/shaker.md)");
  auto help = [](const ParameterDecl& d) { return help_text(d, KeySpelling::command_line); };
  const std::string group = "Shaker";
  add_number_option(*sub, "--frequency", opt->shaker.frequency_Hz, help(p::frequency))->group(group);
  add_number_option(*sub, "--amplitude", opt->shaker.amplitude_m, help(p::amplitude))->group(group);
  add_number_option(*sub, "--gamma", opt->shaker.gamma, help(p::gamma))->group(group);
  add_number_option(*sub, "--impacts", opt->shaker.impacts, help(p::impacts))->type_name("INT")->group(group);
  add_number_option(*sub, "--transient", opt->shaker.transient, help(p::transient))->type_name("INT")->group(group);
  sub->add_option_function<std::string>("--impact-model", [opt](const std::string& v) { opt->shaker.impact_model = v; },
                                        help(p::impact_model))
      ->group(group);
  add_number_option(*sub, "--start-phase", opt->shaker.start_phase, help(p::start_phase))->group(group);
  namespace q = shaker_sweep_parameters;
  sub->add_option("--sweep", opt->sweep, help(q::sweep))->type_name("KEY:FROM:TO:COUNT")->group(group);
  add_number_option(*sub, "--threads", opt->threads, help(q::threads))->type_name("INT")->group(group);
  sub->add_flag("--json", opt->json, "Print the result as one JSON object");
  add_output_file_option(*sub, "--csv", opt->csv_path, "Write the kept impacts to this CSV file, one row each");
  add_mkdir_flag(*sub, opt->mkdir);

  return {sub, [opt]() {
            prepare_output_file("--csv", opt->csv_path, opt->mkdir);
            if (!opt->sweep.empty() || opt->threads)
              return run_shaker_sweep_command(
                  {opt->run, opt->shaker, opt->sweep, opt->csv_path, opt->threads, opt->json, opt->mkdir});
            const ShakerCommandRun r = run_shaker_command(opt->run, load_paper_parameters(), opt->shaker);
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
