// `hertzdash restitution`: the effective coefficient of restitution of a damping
// law in the contact phase alone (no gravity), against a rigid wall unless the wall's
// moduli are given (--rod-E, --rod-nu), at the approach speed --impact-velocity
// (default: sqrt(2 g h) of --height and --gravity), with or without the tension clamp. With --target-restitution it instead solves for the input e that
// makes the effective restitution equal the target (GSL Brent root finder).
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/setup_options.hpp"
#include "hertzdash/simulation/reports/result_output.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <optional>

namespace hertzdash::cli {

namespace {

struct RestitutionOptions {
  RunOptions run;
  std::optional<double> target;
  bool json = false;
};

}  // namespace

Command add_restitution_command(CLI::App& app) {
  auto opt = std::make_shared<RestitutionOptions>();
  CLI::App* sub = app.add_subcommand(
      "restitution",
      "Effective restitution of a damping law in the contact phase alone (no gravity; a rigid wall unless --rod-E "
      "is given)");
  add_run_options(*sub, opt->run);
  auto o = [](std::string_view key) { return declared_option("restitution", key); };
  add_number_option(*sub, o("target-restitution").flag, opt->target, o("target-restitution").help);
  sub->add_flag(o("json").flag, opt->json, o("json").help);

  return {sub, [opt]() {
            const RestitutionRun r = run_restitution(opt->run, load_paper_parameters(), opt->target);
            const IntegratorKind asked = r.solver.integrator;
            report_diagnostics(run_diagnostics(r));
            if (opt->json) {
              std::cout << to_json(r).dump(2) << "\n";
              return 0;
            }
            const std::string wall = std::isinf(r.setup.rod.E_Pa)
                                         ? std::string("rigid wall")
                                         : fmt::format("wall E = {:.4g} Pa, nu = {:.3g}", r.setup.rod.E_Pa, r.setup.rod.nu);
            std::cout << fmt::format("hertzdash restitution: law '{}', tension {}, v0 = {:.6g} m/s ({}, "
                                     "no gravity)\n",
                                     r.law, r.setup.no_tension ? "clamped" : "allowed", *r.setup.impact_velocity_mps, wall);
            if (r.e_target) std::cout << fmt::format("  e_target     {:.6g}\n", *r.e_target);
            std::cout << fmt::format("  e_input      {:.6g}\n", r.e_input);
            std::cout << fmt::format("  e_effective  {:.6g}\n", r.e_effective);
            std::cout << law_coefficients_line(r.summary.law_coefficients);  // at e_input
            if (r.integrator_used != asked)
              std::cout << fmt::format("  integrator   {} (ran {})\n", to_string(asked), to_string(r.integrator_used));
            return 0;
          }};
}

}  // namespace hertzdash::cli
