#pragma once
// The fit of a virtual measurement of the paper's 20 mm drop, for a CLI test of `fit` that reads its JSON only:
// `simulate --trace-format measured` (RK4 at 5e-7 s) into DIR/m.csv, then `fit --json --trace` of it.
#include "cli_runner.hpp"
#include "scratch_dir.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <string>

namespace hertzdash::test {

/// The fit's JSON (REQUIREs that both commands succeed).
inline nlohmann::json fit_json_of_virtual_drop(const ScratchDir& dir) {
  const std::string trace = (dir.path / "m.csv").string();
  REQUIRE(run_cli("simulate --trace-format measured --integrator rk4 --dt 5e-7 --trace " + trace).exit_code == 0);
  const CliResult r = run_cli("fit --json --trace " + trace);
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(r.out);
}

}  // namespace hertzdash::test
