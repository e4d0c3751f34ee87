// The rig table (simulation/rigs/rig.hpp) and what every front end makes of it: each registered
// rig is a command whose --help lists every declared input, its run fills one scalar per result
// field and one cell per table column, and its JSON holds every field the run has under its name.
#include "cli_runner.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/reports/rig_report.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <variant>

using hertzdash::test::run_cli;

TEST_CASE("every registered rig is a command taking its declared inputs", "[rigs]") {
  REQUIRE(hertzdash::rigs().size() >= 2);
  for (const hertzdash::Rig& rig : hertzdash::rigs()) {
    INFO(rig.name);
    CHECK(hertzdash::find_rig(rig.name) == &rig);
    const auto help = run_cli(std::string(rig.name) + " --help");
    CHECK(help.exit_code == 0);
    for (const hertzdash::ParameterDecl& d : rig.inputs) CHECK(help.out.find("--" + std::string(d.key)) != std::string::npos);
  }
}

TEST_CASE("a rig's result has a value per field and a cell per column, and its JSON every field it has", "[rigs]") {
  // The instantaneous map of the shaker with e = 0.5: every rebound is e times the impact speed
  // relative to the wall (u+ - s' = -e (u- - s')), so e_effective is e to round-off.
  const hertzdash::Rig& rig = *hertzdash::find_rig("shaker");
  hertzdash::RunOptions options;
  options.integrator = std::string(rig.default_integrator);
  options.restitution = 0.5;
  hertzdash::RigInputs inputs;
  inputs.texts["impact-model"] = "instantaneous";
  inputs.numbers["impacts"] = 3;
  inputs.numbers["transient"] = 100;
  const hertzdash::RigResult r = hertzdash::run_rig(rig, options, hertzdash::load_paper_parameters(), inputs);
  REQUIRE(r.scalars.size() == rig.results.size());
  REQUIRE(r.rows.size() == 3);
  for (const auto& row : r.rows) CHECK(row.size() == rig.table.size());
  const auto json = hertzdash::to_json(rig, r);
  for (std::size_t k = 0; k < rig.results.size(); ++k) {
    const std::string name(rig.results[k].name);
    const bool present = !std::holds_alternative<std::monostate>(r.scalars[k]);
    CHECK(json.contains(name) == present);
  }
  CHECK(json["e_effective"].get<double>() == Approx(0.5).epsilon(1e-12));
  CHECK_FALSE(json.contains("integrator_used"));  // soft impacts only
  for (const hertzdash::RigColumn& c : rig.table) CHECK(json[std::string(c.name)].size() == 3);
}
