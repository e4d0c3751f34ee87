// The damping-law commands: `hertzdash models` lists every registered law with its
// citation; `hertzdash restitution` prints e_effective of the rigid-wall contact phase
// and calibrates; bad input exits 2 naming the parameter.
#include "cli_runner.hpp"
#include "hertzdash/model/damping/registry.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

using hertzdash::test::run_cli;

TEST_CASE("CLI models lists every registered law with its citation", "[cli][damping]") {
  const auto r = run_cli("models --json");
  REQUIRE(r.exit_code == 0);
  const auto list = nlohmann::json::parse(r.out);
  const auto laws = hertzdash::registered_laws();
  REQUIRE(list.size() == laws.size());
  for (std::size_t i = 0; i < laws.size(); ++i) {
    CHECK(list[i]["name"] == std::string(laws[i].name));
    CHECK(list[i]["citation"].get<std::string>().size() > 20);
    // Only the undamped Hertz law ("none") conserves energy.
    CHECK(list[i]["dissipative"] == (laws[i].name != "none"));
  }
  const auto text = run_cli("models");
  REQUIRE(text.exit_code == 0);
  for (const auto& l : laws) CHECK(text.out.find(std::string(l.citation)) != std::string::npos);
}

TEST_CASE("CLI restitution: Kelvin-Voigt returns its input e, calibration inverts the paper's law",
          "[cli][damping]") {
  // Kelvin-Voigt with tension allowed: e_effective = e exactly (closed form); the CLI's
  // default CVODE tolerance rtol 1e-8 gives ~1e-7 error: bound 1e-6.
  const auto r = run_cli("restitution --damping kelvin-voigt --restitution 0.5 --impact-velocity 1 --json");
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(std::abs(j["e_effective"].get<double>() - 0.5) < 1e-6);
  CHECK(j["tension"] == "allowed");

  // Calibrating to a target, then running the found input e forward, gives the target back.
  const auto cal = run_cli("restitution --damping hongo --target-restitution 0.795 --json");
  REQUIRE(cal.exit_code == 0);
  const double e_input = nlohmann::json::parse(cal.out)["e_input"].get<double>();
  const auto fwd = run_cli("restitution --damping hongo --restitution " + std::to_string(e_input) + " --json");
  REQUIRE(fwd.exit_code == 0);
  // std::to_string keeps 6 decimals: e_input moves by <= 5e-7, e_effective by less.
  CHECK(std::abs(nlohmann::json::parse(fwd.out)["e_effective"].get<double>() - 0.795) < 2e-6);
}

TEST_CASE("CLI restitution: the law's calibrated constants are reported, Hunt-Crossley's chi as its closed form",
          "[cli][damping]") {
  // Hunt-Crossley: chi = 3 (1 - e) / (2 v0) = 3 x 0.5 / 2 = 0.75 s/m at e = 0.5, v0 = 1 m/s; its
  // damping coefficient K chi. The text output's `law` line carries the same.
  const auto r = run_cli("restitution --damping hunt-crossley --restitution 0.5 --impact-velocity 1 --json");
  REQUIRE(r.exit_code == 0);
  const auto c = nlohmann::json::parse(r.out)["law_coefficients"];
  CHECK(c["chi_s_per_m"].get<double>() == Approx(0.75).epsilon(1e-15));
  CHECK(c["damping_coefficient_N_s_per_m_2_5"].get<double>() > 0);
  CHECK_THAT(run_cli("restitution --damping hunt-crossley --restitution 0.5 --impact-velocity 1").out,
             Catch::Contains("  law          chi_s_per_m 0.75, damping_coefficient_N_s_per_m_2_5 "));
}

TEST_CASE("CLI restitution: bad input exits 2 naming the parameter", "[cli][damping]") {
  const auto unknown = run_cli("restitution --damping no-such-law --json");
  CHECK(unknown.exit_code == 2);
  CHECK(unknown.err.find("--damping") != std::string::npos);
  const auto target = run_cli("restitution --damping hongo --target-restitution 1.5");
  CHECK(target.exit_code == 2);
  CHECK(target.err.find("--target-restitution") != std::string::npos);
  const auto unreachable = run_cli("restitution --damping hunt-crossley --target-restitution 0.2");
  CHECK(unreachable.exit_code == 2);
  CHECK(unreachable.err.find("--target-restitution") != std::string::npos);
  const auto simulate = run_cli("simulate --damping no-such-law");
  CHECK(simulate.exit_code == 2);
}
