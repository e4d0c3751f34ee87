// `hertzdash walls` (cli/rig_command.cpp, simulation/rigs/walls_rig.cpp): the impact damper through the command line and its
// JSON (the keys, the damper's balance and amplitudes), the CSV with its provenance, and bad
// input (exit 2, the option named, nothing written).
#include "cli_bad_input.hpp"
#include "cli_runner.hpp"
#include "scratch_dir.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

using hertzdash::test::run_cli;

TEST_CASE("CLI walls: the impact damper's JSON reports the primary with and without the body", "[walls]") {
  // The Masri-Caughey symmetric orbit of tests/test_two_walls.cpp (horizontal box, zeta 0.05,
  // resonance, e = 0.6, gap 10 mm): two impacts a cycle, one on each wall.
  const auto r = run_cli("walls --rig damper --impact-model instantaneous --gravity 0 --restitution 0.6 --gap 0.01 "
                         "--primary-damping-ratio 0.05 --transient 4000 --impacts 8 --json");
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"rig", "gap_m", "frequency_Hz", "impact_model", "period", "impacts_per_period",
                          "impacts_per_cycle", "floor_impacts", "ceiling_impacts", "e_effective", "primary_amplitude_m",
                          "primary_amplitude_bare_m", "primary_amplitude_rigid_m", "energy_J", "impact_time_s",
                          "impact_phase", "wall", "impact_speed_mps", "rebound_speed_mps", "box_displacement_m",
                          "warnings", "inputs"})
    CHECK(j.contains(key));
  CHECK(j["rig"] == "damper");
  CHECK(j["impact_model"] == "instantaneous");
  CHECK(j["period"] == 1);
  CHECK(j["impacts_per_cycle"] == 2.0);
  CHECK(j["floor_impacts"] == 4);
  CHECK(j["ceiling_impacts"] == 4);
  // The bare primary at resonance: |Q| = F0 / (c w), c = 2 zeta sqrt(k M), defaults F0 = 100 N,
  // k = 157914 N/m, M = 10 kg, w = 40 pi: 6.33 mm; the body, at rest, reduces it.
  const double bare = 100.0 / (0.1 * std::sqrt(157914.0 * 10.0) * 40 * std::numbers::pi);
  CHECK(j["primary_amplitude_bare_m"].get<double>() == Approx(bare).epsilon(1e-4));  // k = 157914 is 20 Hz to 1e-6
  CHECK(j["primary_amplitude_m"].get<double>() < bare);
  const nlohmann::json& E = j["energy_J"];
  CHECK(E["drive_work"].get<double>() - E["damping_dissipation"].get<double>() - E["impact_loss"].get<double>() ==
        Approx(E["final"].get<double>() - E["initial"].get<double>()).margin(1e-9 * E["drive_work"].get<double>()));
}

TEST_CASE("CLI walls: --csv writes one row per kept impact below its provenance", "[walls]") {
  const hertzdash::test::ScratchDir dir;
  const std::string csv = (dir.path / "impacts.csv").string();
  const auto r = run_cli("walls --rig damper --impact-model instantaneous --gravity 0 --restitution 0.6 "
                         "--primary-damping-ratio 0.05 --transient 100 --impacts 6 --csv " + csv);
  REQUIRE(r.exit_code == 0);
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  CHECK(line == "n,impact_time_s,impact_phase,wall,impact_speed_mps,rebound_speed_mps,contact_time_s,peak_force_N,"
                "box_displacement_m");
  int rows = 0;
  bool git = false, amplitude = false;
  while (std::getline(in, line)) {
    if (line.rfind("#", 0) == 0) {
      git = git || line.rfind("# git_revision:", 0) == 0;
      amplitude = amplitude || line.rfind("# primary_amplitude_m:", 0) == 0;
    } else {
      ++rows;
    }
  }
  CHECK(rows == 6);
  CHECK(git);
  CHECK(amplitude);
}

TEST_CASE("CLI walls: bad input exits 2 naming the option", "[walls]") {
  hertzdash::test::check_bad_inputs(
      "walls --transient 10 --impacts 5",
      {{"--gap 0", "--gap"}, {"--gap -1", "--gap"}, {"--rig drum", "--rig"}, {"--rig damper --gamma 2", "--gamma"},
       {"--rig damper --amplitude 0.001", "--amplitude"}, {"--primary-mass 2", "--primary-mass"},
       {"--force-amplitude 3", "--force-amplitude"}, {"--rig damper --primary-damping-ratio 1", "--primary-damping-ratio"},
       {"--rig damper --primary-stiffness 0", "--primary-stiffness"}, {"--rig damper --impact-model hard", "--impact-model"},
       {"--gravity 0 --gamma 2", "--gamma"}, {"--gamma 2 --amplitude 0.001", "--gamma"}, {"--height 0.01", "--height"},
       {"--impact-velocity 1", "--impact-velocity"}, {"--integrator rk4", "--integrator"}, {"--impacts 1.5", "--impacts"},
       // Instantaneous impacts read e, g and (the damper's momentum) the body's mass only.
       {"--impact-model instantaneous --ball-E 9e9", "--ball-E"}, {"--impact-model instantaneous --mass 0.1", "--mass"},
       {"--rig damper --impact-model instantaneous --rtol 1e-3", "--rtol"}});
}

// Issue 45: the classic undamped impact damper (instantaneous impacts, gravity 0, primary
// damping 0) was refused by a Hertz speed limit (the bare primary's resonant speed, 38,000 m/s)
// that Newton's law does not have. It runs now; with no dashpot, the drive's work goes into the
// impacts' loss and the energy: W - L = E(end) - E(0), D = 0 (the 8-point Gauss-Legendre pieces
// of the drive's work are exact to rounding here, 1e-9 of W allowed as above).
TEST_CASE("CLI walls: the undamped impact damper with instantaneous impacts and no gravity runs", "[walls]") {
  const auto r = run_cli("walls --rig damper --impact-model instantaneous --gravity 0 --primary-damping-ratio 0 "
                         "--impacts 50 --transient 200 --json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["floor_impacts"].get<int>() + j["ceiling_impacts"].get<int>() == 50);
  const nlohmann::json& E = j["energy_J"];
  CHECK(E["damping_dissipation"].get<double>() == 0.0);
  CHECK(E["drive_work"].get<double>() - E["impact_loss"].get<double>() ==
        Approx(E["final"].get<double>() - E["initial"].get<double>()).margin(1e-9 * E["drive_work"].get<double>()));
}

// Issue 45: `walls --rig damper --force-amplitude 1e12` reported e_effective 1 with "0 steps" and
// nothing said: the box moves at thousands of m/s, so every impact was below the driver's
// touch threshold (1e-6 of the rig's speed scale) and no contact ran. A touch is checked
// against the Hertz scale as a contact is (the steel rod on nylon: 81.34 m/s), in the words of
// `simulate`'s refusal.
TEST_CASE("CLI walls: impacts far beyond the Hertz scale are flagged even where no contact runs", "[walls]") {
  const auto r = run_cli("walls --rig damper --force-amplitude 1e12 --impacts 5 --transient 10");
  INFO(r.err);
  CHECK(r.err.find("soft impacts came at up to") != std::string::npos);
  CHECK(r.err.find("beyond 81.34 m/s, where the undamped Hertz deformation reaches the ball radius") != std::string::npos);
}
