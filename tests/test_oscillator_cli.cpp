// `hertzdash oscillator` (the rig simulation/rigs/oscillator_rig.hpp through the command line): its
// JSON (the keys, the closed-form steady amplitude, the energy balance) and bad input (exit 2, the
// option named, nothing written).
#include "cli_bad_input.hpp"
#include "cli_runner.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <string>

using hertzdash::test::run_cli;

TEST_CASE("CLI oscillator: the JSON reports the impacts, the closed-form amplitude and a balanced energy", "[oscillator]") {
  // The defaults: k = 1e4 N/m, zeta = 0.05, F = 10 N at 20 Hz, the stop at 2 mm, the paper's steel
  // rod. Without the stop |X| = (F / k) / sqrt((1 - r^2)^2 + (2 zeta r)^2), r = w / sqrt(k / m),
  // m the mass the run reports among its inputs; the stop is inside it, so the body strikes it.
  const auto r = run_cli("oscillator --impact-model instantaneous --restitution 0.7 --transient 100 --impacts 10 --json");
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"period", "impacts_per_period", "e_effective", "amplitude_m", "peak_phase",
                          "steady_amplitude_m", "energy_J", "impact_time_s", "impact_phase", "impact_speed_mps",
                          "rebound_speed_mps", "contact_time_s", "peak_force_N", "sticking_episodes", "impacts_run",
                          "end_reason", "warnings", "inputs"})
    CHECK(j.contains(key));
  CHECK(j["impact_time_s"].size() == 10);
  CHECK(j["e_effective"].get<double>() == Approx(0.7).epsilon(1e-12));
  const double m = j["inputs"]["mass_kg"].get<double>(), w = 40 * std::numbers::pi;
  const double r_ = w / std::sqrt(1e4 / m);
  const double steady = 10.0 / 1e4 / std::hypot(1 - r_ * r_, 0.1 * r_);
  CHECK(j["steady_amplitude_m"].get<double>() == Approx(steady).epsilon(1e-9));
  CHECK(steady > 0.002);
  // The body reaches the stop: its largest x over the kept window is d, at an impact's phase, so
  // its amplitude is at least d / 2 (the smallest x is below the rest position, x = 0).
  CHECK(j["amplitude_m"].get<double>() >= 0.001);
  CHECK(j["peak_phase"].get<double>() == Approx(j["impact_phase"][0].get<double>()).margin(1e-9));
  // W - D - L = E(end) - E(0) (tests/test_oscillator.cpp derives it), to 1e-9 of W.
  const nlohmann::json& E = j["energy_J"];
  const double W = E["drive_work"].get<double>();
  CHECK(W - E["damping_dissipation"].get<double>() - E["impact_loss"].get<double>() ==
        Approx(E["change"].get<double>()).margin(1e-9 * W));
}

TEST_CASE("CLI oscillator: bad input exits 2 naming the option and writes nothing", "[oscillator]") {
  hertzdash::test::check_bad_inputs(
      "oscillator --transient 10 --impacts 5",
      {{"--stop-distance 0", "--stop-distance"}, {"--stiffness -1", "--stiffness"},
       {"--damping-ratio 1", "--damping-ratio"}, {"--frequency 0", "--frequency"},
       {"--force-amplitude -1", "--force-amplitude"}, {"--start-position 0.01", "--start-position"},
       {"--impacts 1.5", "--impacts"}, {"--impact-model hard", "--impact-model"}, {"--height 0.1", "--height"},
       {"--gravity 1", "--gravity"}, {"--impact-velocity 1", "--impact-velocity"}, {"--integrator rk4", "--integrator"},
       // Instantaneous impacts read e and the mass only.
       {"--impact-model instantaneous --ball-E 9e9", "--ball-E"},
       {"--impact-model instantaneous --rtol 1e-3", "--rtol"}});
}
