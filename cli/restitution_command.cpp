// `hertzdash restitution`: the effective coefficient of restitution of a damping
// law in the rigid-wall contact phase (rod E = inf, no gravity), at the approach
// speed --impact-velocity (default: sqrt(2 g h) of --height), with or without the
// tension clamp. With --target-restitution it instead solves for the input e that
// makes the effective restitution equal the target (GSL Brent root finder).
#include "cli/command.hpp"
#include "cli/setup_options.hpp"
#include "model/invalid_parameter.hpp"
#include "model/omega_n_variant.hpp"
#include "simulation/calibrate_restitution.hpp"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace hertzdash::cli {

namespace {

struct RestitutionOptions {
  SetupOptions setup;
  SolverOptions solver;
  CLI::Option* target_opt = nullptr;
  double target = 0;
  bool json = false;
};

}  // namespace

Command add_restitution_command(CLI::App& app) {
  auto opt = std::make_shared<RestitutionOptions>();
  CLI::App* sub = app.add_subcommand(
      "restitution", "Effective restitution of a damping law, rigid wall, no gravity (contact phase only)");
  opt->setup.add_to(*sub);
  opt->solver.add_to(*sub);
  opt->target_opt = sub->add_option("--target-restitution", opt->target,
                                    "Calibrate: find the input e whose effective restitution is this, in (0,1]");
  sub->add_flag("--json", opt->json, "Print the result as one JSON object");

  return {sub, [opt]() {
            const std::string& law = opt->setup.damping();
            const DropTestSetup setup = contact_phase_setup(opt->setup.resolve(load_paper_parameters()));
            if (is_iterated(setup.damping.omega_n)) {
              throw InvalidParameter("--omega-n", to_string(setup.damping.omega_n),
                                     "a closed-form variant for `restitution`: paper, impact-energy, rebound-energy or "
                                     "as-printed (the iterated variants need `simulate`)");
            }
            const SolverSettings solver = opt->solver.resolve();
            ImpactSimulator simulator(solver);
            const IntegratorKind used = report_integrator_used(solver, setup, law);

            nlohmann::ordered_json j;
            j["damping"] = law;
            j["tension"] = setup.no_tension ? "clamped" : "allowed";
            j["impact_velocity_mps"] = *setup.impact_velocity_mps;
            if (opt->target_opt->count()) {
              const RestitutionCalibration c = calibrate_restitution(simulator, setup, law, opt->target);
              j["e_target"] = opt->target;
              j["e_input"] = c.e_input;
              j["e_effective"] = c.e_effective;
              j["iterations"] = c.iterations;
            } else {
              j["e_input"] = setup.restitution;
              j["e_effective"] = simulator.run(setup, law).e_effective;
            }
            j["integrator_used"] = to_string(used);
            j["git_revision"] = git_revision();
            if (opt->json) {
              std::cout << j.dump(2) << "\n";
            } else {
              std::cout << fmt::format("hertzdash restitution: law '{}', tension {}, v0 = {:.6g} m/s (rigid wall, "
                                       "no gravity)\n",
                                       law, j["tension"].get<std::string>(), *setup.impact_velocity_mps);
              if (opt->target_opt->count()) std::cout << fmt::format("  e_target     {:.6g}\n", opt->target);
              std::cout << fmt::format("  e_input      {:.6g}\n", j["e_input"].get<double>());
              std::cout << fmt::format("  e_effective  {:.6g}\n", j["e_effective"].get<double>());
              if (used != solver.integrator)
                std::cout << fmt::format("  integrator   {} (ran {})\n", to_string(solver.integrator), to_string(used));
            }
            return 0;
          }};
}

}  // namespace hertzdash::cli
