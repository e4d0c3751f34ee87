// `hertzdash shaker` (cli/rig_command.cpp, simulation/rigs/shaker_rig.cpp): the issue's acceptance run of the instantaneous
// map across its period-doubling threshold through the command line and its JSON, the CSV with
// its provenance, and bad input (exit 2, the option named, no output written).
#include "cli_runner.hpp"
#include "scratch_dir.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

using hertzdash::test::run_cli;

namespace {

// The exact bouncing-ball map's period-doubling threshold for e = 0.5 (derived in
// tests/test_shaker.cpp): Gamma_2 = sqrt((pi (1-e)/(1+e))^2 + (2 (1+e^2)/(1+e)^2)^2)
// = sqrt((pi/3)^2 + (10/9)^2) = 1.526824.
const double gamma_2 = std::hypot(std::numbers::pi / 3, 10.0 / 9.0);

nlohmann::json shaker_json(double gamma) {
  const auto r = run_cli("shaker --impact-model instantaneous --restitution 0.5 --transient 20000 --impacts 32 "
                         "--gamma " + std::to_string(gamma) + " --json");
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(r.out);
}

}  // namespace

TEST_CASE("CLI shaker: period 1 just below the period-doubling threshold and period 2 just above", "[shaker]") {
  // 1 % either side of Gamma_2 (see tests/test_shaker.cpp for why 1 % and 20000 transient impacts suffice).
  const nlohmann::json below = shaker_json(0.99 * gamma_2), above = shaker_json(1.01 * gamma_2);
  CHECK(below["period"] == 1);
  CHECK(below["impacts_per_period"] == 1);
  CHECK(above["period"] == 2);
  CHECK(above["impacts_per_period"] == 2);
  for (const char* key : {"gamma", "impact_phase", "impact_speed_mps", "rebound_speed_mps", "contact_time_s",
                          "e_effective", "period", "impacts_per_period", "warnings"})
    CHECK(below.contains(key));
  CHECK(below["gamma"].get<double>() == Approx(0.99 * gamma_2).epsilon(1e-6));  // --gamma printed to 6 decimals
  CHECK(below["impact_phase"].size() == 32);
  CHECK(below["e_effective"].get<double>() == Approx(0.5).epsilon(1e-12));
}

TEST_CASE("CLI shaker: --csv writes one row per kept impact below its provenance", "[shaker]") {
  const hertzdash::test::ScratchDir dir;
  const std::string csv = (dir.path / "impacts.csv").string();
  const auto r = run_cli("shaker --impact-model instantaneous --restitution 0.5 --gamma 1.3 --impacts 5 --transient 50 "
                         "--csv " + csv);
  REQUIRE(r.exit_code == 0);
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  CHECK(line == "n,impact_time_s,impact_phase,impact_speed_mps,rebound_speed_mps,contact_time_s,peak_force_N");
  int rows = 0, comments = 0;
  bool git = false;
  while (std::getline(in, line)) {
    if (line.rfind("#", 0) == 0) {
      ++comments;
      git = git || line.rfind("# git_revision:", 0) == 0;
    } else {
      ++rows;
    }
  }
  CHECK(rows == 5);
  CHECK(git);
  CHECK(comments > 5);
}

TEST_CASE("CLI shaker: bad input exits 2 naming the option and writes nothing", "[shaker]") {
  const hertzdash::test::ScratchDir dir;
  const std::string csv = (dir.path / "never.csv").string();
  struct Case {
    std::string args, option;
  };
  for (const Case& c : {Case{"--gamma 1.3 --amplitude 0.001", "--gamma"}, Case{"--impacts 2.5", "--impacts"},
                        Case{"--frequency 0", "--frequency"}, Case{"--impact-model hard", "--impact-model"},
                        Case{"--integrator cvode", "--integrator"}, Case{"--impact-velocity 1", "--impact-velocity"},
                        Case{"--start-phase 1", "--start-phase"},
                        // The instantaneous map reads e, g and the start height only: a contact, law or
                        // solver option would be ignored, so it is refused.
                        Case{"--impact-model instantaneous --restitution 0.5 --ball-E 9e9", "--ball-E"},
                        Case{"--impact-model instantaneous --restitution 0.5 --mass 3", "--mass"},
                        Case{"--impact-model instantaneous --restitution 0.5 --damping kelvin-voigt", "--damping"},
                        Case{"--impact-model instantaneous --restitution 0.5 --rtol 1e-3", "--rtol"},
                        Case{"--impact-model instantaneous --integrator cvode-regularized", "--integrator"}}) {
    const auto r = run_cli("shaker --transient 10 --impacts 5 " + c.args + " --csv " + csv);
    INFO(c.args << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.option) != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(csv));
  }
}

TEST_CASE("CLI shaker: --height 0 starts the body at rest on the wall, as its help says", "[shaker]") {
  // Before, the drop test's own height check (h > 0: the rod must reach the ball) refused it,
  // although docs/shaker.md, --help and docs/parameters.md document 0 as "at rest on the wall".
  // At rest on a wall whose peak acceleration exceeds g (gamma 1.3), the body is carried until
  // the wall pulls away and then bounces: the run keeps its impacts.
  const auto r = run_cli("shaker --height 0 --impact-model instantaneous --restitution 0.5 --gamma 1.3 --impacts 4 "
                         "--transient 50 --json");
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["inputs"]["start_height_m"] == 0.0);
  CHECK(j["impact_phase"].size() == 4);
}

TEST_CASE("CLI shaker: the default gamma is the middle of the period-1 window of the run's e", "[shaker]") {
  // Before, the default gamma was 1.3, chosen for e = 0.5, while the default rod is the steel rod
  // of Table 2 (e = 0.795), whose period-1 orbit doubles at Gamma_2 = 1.07: the default run was not
  // the period-1 orbit its help promised. The window of the exact map (tests/test_shaker.cpp):
  //   gamma_1 = pi (1-e)/(1+e),  gamma_2 = sqrt(gamma_1^2 + (2 (1+e^2)/(1+e)^2)^2),
  // and the default is (gamma_1 + gamma_2)/2, where the period-1 orbit is stable for every e.
  for (const double e : {0.5, 0.795, 0.95}) {
    INFO("e = " << e);
    const double g1 = std::numbers::pi * (1 - e) / (1 + e);
    const double g2 = std::hypot(g1, 2 * (1 + e * e) / ((1 + e) * (1 + e)));
    const auto r = run_cli("shaker --impact-model instantaneous --restitution " + std::to_string(e) +
                           " --transient 2000 --impacts 8 --json");
    REQUIRE(r.exit_code == 0);
    const nlohmann::json j = nlohmann::json::parse(r.out);
    CHECK(j["gamma"].get<double>() == Approx(0.5 * (g1 + g2)).epsilon(1e-12));
    CHECK(j["period"] == 1);
    CHECK(j["impacts_per_period"] == 1);
  }
  // The default rod, soft contacts: its own e (Table 2) gives the window; one impact per period.
  const auto soft = run_cli("shaker --transient 300 --impacts 4 --json");
  REQUIRE(soft.exit_code == 0);
  CHECK(nlohmann::json::parse(soft.out)["period"] == 1);
}

TEST_CASE("CLI shaker: soft impacts beyond the Hertz scale are flagged, as simulate refuses them", "[shaker]") {
  // Before, `shaker --frequency 0.01` hit the wall at 210-315 m/s with 2.3e6 N, exit 0 and nothing
  // said, while `simulate` refuses an impact above the speed at which the undamped Hertz
  // deformation X = (5 m v^2/(4K))^{2/5} reaches the ball radius R: v = sqrt(4 K R^{5/2}/(5 m)).
  // For the steel rod on nylon: K = (4 sqrt(R)/3)/((1-nu_b^2)/E_b + (1-nu_r^2)/E_r) with Table 1's
  // R = 12.7 mm and the assumed E_b = 2 GPa, nu_b = 0.4 (data/assumptions.csv), m = 0.778 kg:
  // the bound is the 81 m/s that `simulate` names. A wall at 0.01 Hz throws the body up g/f^2
  // ~ 1e5 m, far beyond it; the run says so in its warnings, naming the bound.
  const auto slow = run_cli("shaker --frequency 0.01 --impacts 3 --transient 20 --json");
  REQUIRE(slow.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(slow.out);
  bool flagged = false;
  for (const auto& w : j["warnings"])
    flagged = flagged || w.get<std::string>().find("beyond 81.") != std::string::npos;
  CHECK(flagged);
  CHECK(slow.err.find("small-deformation Hertz contact does not hold") != std::string::npos);
  // The default shaker's impacts stay far below it: no such warning.
  const auto usual = run_cli("shaker --impacts 3 --transient 20 --json");
  REQUIRE(usual.exit_code == 0);
  CHECK(usual.err.find("small-deformation") == std::string::npos);
}

// Issue 45: a run that kept none of the impacts asked for exited 0. With gamma 0 the wall never
// moves: within the default transient (1000 impacts) the instantaneous body comes to rest on it
// for good, the soft one stays in a contact that never ends. Each prints its output (no impact kept: period 0, e_effective null) and exits
// with code 3, naming why it ended.
TEST_CASE("CLI shaker: a run that keeps none of the impacts asked for exits 3", "[shaker]") {
  for (const std::string& model : {"soft", "instantaneous"}) {
    const auto r = run_cli("shaker --gamma 0 --impacts 5 --json --impact-model " + model);
    INFO(model << ": " << r.err);
    CHECK(r.exit_code == 3);
    CHECK(r.err.find("hertzdash: the run kept none of the impacts asked for: ") != std::string::npos);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["period"] == 0);
    CHECK(j["e_effective"].is_null());
  }
  const auto kept = run_cli("shaker --impacts 3 --transient 20");
  CHECK(kept.exit_code == 0);
}
