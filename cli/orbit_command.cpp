// `hertzdash orbit RIG`: a periodic orbit of a rig, its Floquet multipliers and its stability
// (simulation/rigs/rig_orbit.hpp, docs/orbits.md). One subcommand per registered rig with an
// impact sequence, with the rig's options (cli/rig_options.hpp) and the orbit's own, declared in
// simulation/options/command_options.cpp: --period, --section-phase, --guess-position,
// --guess-velocity, --json. Exit 0 with an orbit,
// 3 when Newton does not converge or the rig's run gives no guess (the output stands), 2 for bad
// input.
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/rig_options.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/reports/orbit_report.hpp"

#include <iostream>
#include <memory>
#include <vector>

namespace hertzdash::cli {

Command add_orbit_command(CLI::App& app) {
  struct Request {
    const Rig* rig = nullptr;
    CLI::App* sub = nullptr;
    RunOptions run;
    RigInputs inputs, orbit;
    bool json = false;
  };
  CLI::App* orbit = app.add_subcommand("orbit", "A rig's periodic orbit by shooting: its Floquet multipliers and stability");
  orbit->require_subcommand(1);
  auto requests = std::make_shared<std::vector<std::shared_ptr<Request>>>();
  for (const Rig& rig : rigs()) {
    if (!rig.sequence) continue;
    auto r = std::make_shared<Request>();
    r->rig = &rig;
    if (!rig.default_integrator.empty()) r->run.integrator = rig.default_integrator;
    r->sub = orbit->add_subcommand(std::string(rig.name), "The periodic orbit of `hertzdash " + std::string(rig.name) + "`");
    add_rig_options(*r->sub, rig, r->run, r->inputs, true);
    for (const ParameterDecl& d : options_of_command("orbit")) {
      const std::string flag = "--" + std::string(d.key), key(d.key), help = help_text(d, KeySpelling::command_line);
      if (d.type == ParameterType::flag) {
        r->sub->add_flag(flag, r->json, help)->group("The orbit");
        continue;
      }
      CLI::Option* o = add_number_option(*r->sub, flag, [r, key](double v) { r->orbit.numbers[key] = v; }, help);
      if (d.range.kind == NumberRange::Kind::integer) o->type_name("INT");
      // The guess's two halves, a group --guess-position switches on (cli/help_formatter.hpp).
      o->group(key.starts_with("guess-") ? "Newton's start (--guess-position)" : "The orbit");
    }
    requests->push_back(r);
  }
  return {orbit, [requests]() {
            for (const auto& r : *requests) {
              if (!r->sub->parsed()) continue;
              const OrbitRequest request = orbit_request(r->orbit);
              const OrbitResult result = run_orbit(*r->rig, r->run, load_paper_parameters(), r->inputs, request);
              if (r->json) std::cout << to_json(*r->rig, result).dump(2) << "\n";
              else std::cout << orbit_text(*r->rig, result);
              if (result.orbit.converged) return 0;
              std::cerr << "hertzdash: no periodic orbit found: " << result.orbit.failure << "\n";
              return 3;
            }
            return 2;
          }};
}

}  // namespace hertzdash::cli
