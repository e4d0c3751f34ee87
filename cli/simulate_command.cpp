// `hertzdash simulate`: one drop test of the paper's set-up, any law, any integrator.
#include "cli/command.hpp"
#include "cli/setup_options.hpp"
#include "io/csv_writer.hpp"
#include "simulation/impact_simulator.hpp"
#include "simulation/step_resolution.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <memory>

namespace hertzdash::cli {

namespace {

struct SimulateOptions {
  SetupOptions setup;
  SolverOptions solver;
  std::string trace_path;
  bool json = false;
};

// Parameters are text; numbers and booleans go into JSON as such.
nlohmann::ordered_json json_value(const std::string& text) {
  if (text == "true" || text == "false") return text == "true";
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (!text.empty() && end == text.c_str() + text.size() && std::isfinite(v)) return v;
  return text;
}

nlohmann::ordered_json to_json(const ImpactSummary& s, const Parameters& inputs) {
  nlohmann::ordered_json j;
  j["e_effective"] = s.e_effective;
  j["peak_force_N"] = s.peak_force_N;
  j["max_deformation_m"] = s.max_deformation_m;
  j["contact_time_s"] = s.contact_time_s;
  j["impact_velocity_mps"] = s.impact_velocity_mps;
  j["rebound_velocity_mps"] = s.rebound_velocity_mps;
  j["separated"] = s.separated;
  j["K"] = s.K;
  for (const NamedValue& c : s.law_coefficients) j[c.name] = c.value;
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
  nlohmann::ordered_json in;
  for (const auto& [name, value] : inputs) in[name] = json_value(value);
  j["inputs"] = in;
  j["git_revision"] = git_revision();
  return j;
}

void print_text(const ImpactSummary& s, std::string_view law, IntegratorKind integrator) {
  std::cout << fmt::format("hertzdash simulate: damping law '{}', integrator {}{}\n", law, to_string(integrator),
                           s.integrator_used == integrator ? "" : fmt::format(" (ran {})", to_string(s.integrator_used)));
  auto line = [](std::string_view name, double value) { std::cout << fmt::format("  {:<30} {:.6g}\n", name, value); };
  line("impact_velocity_mps", s.impact_velocity_mps);
  line("rebound_velocity_mps", s.rebound_velocity_mps);
  line("e_effective", s.e_effective);
  line("peak_force_N", s.peak_force_N);
  line("max_deformation_m", s.max_deformation_m);
  line("contact_time_s", s.contact_time_s);
  line("K_N_per_m_1_5", s.K);
  for (const NamedValue& c : s.law_coefficients) line(c.name, c.value);
  std::cout << fmt::format("  {:<30} {} steps, {} rhs evaluations\n", "work", s.work.steps, s.work.rhs_evaluations);
  if (const auto& it = s.omega_n_iteration)
    std::cout << fmt::format("  {:<30} {} iterations, {} (last relative change {:.3g}, contraction {:.3g})\n",
                             "omega_n_fixed_point", it->iterations, it->converged ? "converged" : "NOT converged",
                             it->relative_change, it->contraction);
  if (!s.separated) std::cout << "  note: the rod did not separate (it came to rest on the ball)\n";
}

}  // namespace

Command add_simulate_command(CLI::App& app) {
  auto opt = std::make_shared<SimulateOptions>();
  CLI::App* sub = app.add_subcommand("simulate", "Simulate one drop of a rod onto the nylon hemisphere");
  opt->setup.add_to(*sub);
  opt->solver.add_to(*sub);
  sub->add_option("--trace", opt->trace_path, "Write the contact-phase time series to this CSV file");
  sub->add_flag("--json", opt->json, "Print the summary as one JSON object");

  return {sub, [opt]() {
            const PaperParameters paper = load_paper_parameters();
            const DropTestSetup setup = opt->setup.resolve(paper);
            const SolverSettings solver = opt->solver.resolve();
            const Parameters inputs = describe_run(setup, opt->setup.damping(), solver);

            ImpactSimulator simulator(solver);
            std::vector<TraceSample> trace;
            report_integrator_used(solver, setup, opt->setup.damping());
            const ImpactSummary s = simulator.run(setup, opt->setup.damping(), opt->trace_path.empty() ? nullptr : &trace);

            if (!opt->trace_path.empty()) {
              Parameters header = inputs;
              header.emplace_back("integrator_used", to_string(s.integrator_used));
              CsvWriter csv("hertzdash simulate: contact-phase time series (x = deformation, force compressive "
                            "positive, accel/velocity of the rod downward positive)",
                            header, trace_columns());
              for (const TraceSample& r : trace)
                csv.add_row({r.t_s, r.x_m, r.xdot_mps, r.force_N, r.accel_mps2, r.rod_displacement_m,
                             r.rod_velocity_mps});
              csv.save(opt->trace_path);
            }
            if (const auto r = under_resolved_contact(s, solver)) {
              std::cerr << fmt::format(
                  "hertzdash: warning: the fixed step resolved the contact with only {:.0f} steps (contact time {:.6g} s, "
                  "--dt {:.6g} s); the convergence study needs at least {} steps per contact with {} ({}) for errors "
                  "below {:g} % (README, Convergence)\n",
                  r->steps_per_contact, s.contact_time_s, solver.dt_s, r->required, to_string(solver.integrator),
                  solver.locate_events ? "events located" : "--no-event-location",
                  100 * step_resolution_target_error);
            }
            if (opt->json) std::cout << to_json(s, inputs).dump(2) << "\n";
            else print_text(s, opt->setup.damping(), solver.integrator);
            return 0;
          }};
}

}  // namespace hertzdash::cli
