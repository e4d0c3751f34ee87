// `hertzdash orbit RIG` (cli/orbit_command.cpp, simulation/rigs/rig_orbit.hpp): the bouncing
// ball's stable orbit from the rig's own run and its saddle from a guess, through the command
// line's JSON; bad input (exit 2, the option named) and an orbit that cannot be found (exit 3,
// the output standing).
#include "cli_runner.hpp"
#include "scratch_dir.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

using hertzdash::test::run_cli;

namespace {

const std::string ball = "orbit shaker --restitution 0.5 --frequency 20 ";

nlohmann::json orbit_json(const std::string& args) {
  const auto r = run_cli(ball + args + " --json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(r.out);
}

std::complex<double> multiplier(const nlohmann::json& j, int k) {
  return {j["multipliers"][k][0].get<double>(), j["multipliers"][k][1].get<double>()};
}

}  // namespace

TEST_CASE("CLI orbit: the shaker's stable period-1 orbit from its own run, with the closed-form multipliers", "[orbit]") {
  // e = 0.5, Gamma = 1.3 (tests/test_orbits.cpp derives them): the impact phase 0.10093859,
  // the relative impact speed g T/(1 + e) = 9.80665/20/1.5 = 0.32688833 m/s and
  // lambda = -0.24159860 +- 0.43775577 i, |lambda| = e.
  const nlohmann::json j = orbit_json("--gamma 1.3");
  for (const char* key : {"schema_version", "rig", "method", "converged", "period", "section_phase", "guess",
                          "impacts_per_period", "section_state", "multipliers", "multiplier_moduli", "stable",
                          "newton_residual", "newton_iterations", "min_impact_speed_mps", "impact_time_s",
                          "impact_phase", "impact_speed_mps", "rebound_speed_mps", "inputs", "git_revision"})
    CHECK(j.contains(key));
  CHECK(j["converged"] == true);
  CHECK(j["period"] == 1);
  CHECK(j["impacts_per_period"] == 1);
  CHECK(j["stable"] == true);
  CHECK(j["newton_residual"].get<double>() <= 1e-11);
  CHECK(j["impact_phase"][0].get<double>() == Approx(0.10093859).margin(1e-8));
  CHECK(j["impact_speed_mps"][0].get<double>() == Approx(9.80665 / 20 / 1.5).epsilon(1e-10));
  CHECK(std::abs(multiplier(j, 0).real() + 0.24159860) < 1e-8);
  CHECK(std::abs(std::abs(multiplier(j, 0).imag()) - 0.43775577) < 1e-8);
  CHECK(j["multiplier_moduli"][1].get<double>() == Approx(0.5).epsilon(1e-12));
  CHECK(j["inputs"]["period"] == 1);
  CHECK(j["inputs"]["amplitude_m"].get<double>() > 0);
}

TEST_CASE("CLI orbit: the saddle from a guess, unstable, which the rig's own run never shows", "[orbit]") {
  // The saddle leaves the wall at theta = -theta* (sin theta < 0), impact phase 1 - 0.10093859;
  // half a period later the body is at its apex, y = A sin theta + g T^2/8, u = 0, at the section
  // phase 0.5 - 0.10093859. Its multipliers are 2.89689799 and 0.08629921.
  const double g = 9.80665, T = 1.0 / 20, gamma = 1.3, A = gamma * g / std::pow(2 * std::numbers::pi / T, 2);
  const double c = std::numbers::pi / 3 / gamma, apex = -A * std::sqrt(1 - c * c) + g * T * T / 8;
  // Guessed 2 % of g T^2 high and 1 % of g T fast: Newton's start, not the answer.
  const nlohmann::json j = orbit_json("--gamma 1.3 --section-phase 0.39906141 --guess-position " +
                                      std::to_string(apex + 0.02 * g * T * T) + " --guess-velocity " +
                                      std::to_string(0.01 * g * T));
  CHECK(j["guess"] == "the given guess");
  CHECK(j["stable"] == false);
  CHECK(j["newton_iterations"].get<int>() >= 1);
  CHECK(j["impact_phase"][0].get<double>() == Approx(0.89906141).margin(1e-8));
  CHECK(multiplier(j, 0).real() == Approx(2.89689799).epsilon(1e-8));
  CHECK(multiplier(j, 1).real() == Approx(0.08629921).epsilon(1e-7));
}

TEST_CASE("CLI orbit: bad input exits 2 naming the option", "[orbit]") {
  // Soft contacts need a law that declares dF/dv0 (model/damping/damping_law.hpp); kelvin-voigt does not.
  const auto soft = run_cli("orbit shaker --impact-model soft --damping kelvin-voigt --gamma 1.3");
  CHECK(soft.exit_code == 2);
  CHECK_THAT(soft.err, Catch::Contains("--damping = kelvin-voigt") && Catch::Contains("hongo") &&
                           Catch::Contains("--impact-model instantaneous"));
  CHECK(run_cli("orbit shaker --gamma 1.3 --restitution 0.5").exit_code == 0);
  // The help lists the options instantaneous impacts read, not the soft contact's.
  const auto help = run_cli("orbit shaker --help");
  CHECK_THAT(help.out, Catch::Contains("--restitution") && !Catch::Contains("--ball-E") && !Catch::Contains("--integrator"));
  const auto half = run_cli(ball + "--gamma 1.3 --section-phase 0.5 --guess-position 0.01");
  CHECK(half.exit_code == 2);
  CHECK_THAT(half.err, Catch::Contains("--guess-velocity"));
  const auto phase = run_cli(ball + "--gamma 1.3 --guess-position 0.01 --guess-velocity 0");
  CHECK(phase.exit_code == 2);
  CHECK_THAT(phase.err, Catch::Contains("--section-phase"));
  const auto period = run_cli(ball + "--gamma 1.3 --period 0");
  CHECK(period.exit_code == 2);
  CHECK_THAT(period.err, Catch::Contains("--period"));
  // No rig: the rigs `orbit` takes are listed.
  const auto none = run_cli("orbit");
  CHECK(none.exit_code == 2);
  CHECK(none.out.empty());
  CHECK(none.err == "hertzdash: `hertzdash orbit` takes one of: shaker, walls, oscillator (hertzdash orbit --help)\n");
  // The box's half of a guess belongs to a box of its own (the damper), which needs it.
  const auto box_half = run_cli(ball + "--gamma 1.3 --section-phase 0.5 --guess-position 0.01 --guess-velocity 0 "
                                       "--guess-box-position 0");
  CHECK(box_half.exit_code == 2);
  CHECK_THAT(box_half.err, Catch::Contains("--guess-box-position = 0") && Catch::Contains("damper"));
  const auto damper_half = run_cli("orbit walls --rig damper --section-phase 0.5 --guess-position 0.01 --guess-velocity 0");
  CHECK(damper_half.exit_code == 2);
  CHECK_THAT(damper_half.err, Catch::Contains("--guess-box-position"));
  // The damper's soft contacts need a law that declares dF/dv0 as the prescribed box's do.
  const auto soft_damper = run_cli("orbit walls --rig damper --impact-model soft --damping kelvin-voigt");
  CHECK(soft_damper.exit_code == 2);
  CHECK(soft_damper.out.empty());
  CHECK_THAT(soft_damper.err, Catch::Contains("--damping = kelvin-voigt"));
}

TEST_CASE("CLI orbit: the impact damper's four-dimensional section from its own run, rigid and soft", "[orbit]") {
  // The default damper settles on a period-1 orbit with 3 impacts (the rig's own run). Its
  // multipliers' product is det M = e^(2k) exp(-C T/M) (simulation/orbits/stroboscopic_map.hpp):
  // k = 3 impacts, e = 0.795 (the paper's steel rod), C/M = 2 zeta sqrt(k/M) = 2 (0.02) sqrt(15791.4)
  // = 5.02654 1/s over T = 1/20 s (the default frequency).
  const auto r = run_cli("orbit walls --rig damper --json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["converged"] == true);
  CHECK(j["impacts_per_period"] == 3);
  for (const char* key : {"position_m", "velocity_mps", "box_position_m", "box_velocity_mps"})
    CHECK(j["section_state"].contains(key));
  REQUIRE(j["multiplier_moduli"].size() == 4);
  double product = 1;
  for (const auto& m : j["multiplier_moduli"]) product *= m.get<double>();
  const double e = j["inputs"]["restitution"].get<double>();
  CHECK(product == Approx(std::pow(e, 6) * std::exp(-2 * 0.02 * std::sqrt(157914.0 / 10) / 20)).epsilon(1e-9));
  // Soft impacts (the paper's law): the contacts' variational equations with the primary's state.
  const auto soft = run_cli("orbit walls --rig damper --impact-model soft --json");
  INFO(soft.err);
  REQUIRE(soft.exit_code == 0);
  const nlohmann::json s = nlohmann::json::parse(soft.out);
  CHECK(s["converged"] == true);
  CHECK_THAT(s["method"].get<std::string>(), Catch::Contains("variational"));
  CHECK(s["multiplier_moduli"].size() == 4);
}

TEST_CASE("CLI orbit: no orbit to find exits 3 with the reason, the output standing", "[orbit]") {
  // Gamma = 1.02 < Gamma_1 = pi/3 for e = 0.5: no bouncing period-1 orbit; the body chatters and
  // sticks to the wall once a period, where the map is not smooth: the rig's own run shows it.
  const auto r = run_cli(ball + "--gamma 1.02 --json");
  CHECK(r.exit_code == 3);
  CHECK_THAT(r.err, Catch::Contains("no periodic orbit found"));
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["converged"] == false);
  CHECK_THAT(j["failure"].get<std::string>(), Catch::Contains("sticks to the wall"));
}

TEST_CASE("CLI continue: the shaker's branches in gamma, their doublings as events, the CSV", "[orbit]") {
  // From the stable period-1 orbit at Gamma = 1.3 (e = 0.5) up to 1.6: the period doubling at the
  // closed form Gamma_2 = 1.52682372 (tests/test_orbits.cpp), the doubled branch followed from it.
  const hertzdash::test::ScratchDir dir;
  const std::string csv = (dir.path / "branches.csv").string();
  const auto r = run_cli("continue shaker --restitution 0.5 --parameter gamma --from 1.3 --to 1.6 --json --csv " + csv);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"schema_version", "rig", "method", "parameter", "start", "branch", "events", "ends", "inputs",
                          "git_revision"})
    CHECK(j.contains(key));
  REQUIRE(j["events"].size() == 1);
  CHECK(j["events"][0]["type"] == "period-doubling");
  CHECK(std::abs(j["events"][0]["parameter"].get<double>() - std::hypot(std::numbers::pi / 3, 10.0 / 9.0)) < 1e-8);
  // Two branches: period 1 from 1.3 to 1.6, stable below Gamma_2 only; period 2 from Gamma_2.
  int periods[3] = {0, 0, 0};
  for (const auto& p : j["branch"]) {
    const double gamma = p["gamma"].get<double>();
    ++periods[p["period"].get<int>()];
    if (p["period"] == 1) CHECK(p["stable"].get<bool>() == (gamma < 1.5268));
    CHECK(p["multipliers"].size() == 2);
    CHECK(p["impacts_per_period"] == p["period"]);
  }
  CHECK(periods[1] > 5);
  CHECK(periods[2] > 5);
  CHECK(j["ends"].size() == 2);
  // The CSV: the same points below the provenance, the event as a comment.
  const std::string text = hertzdash::test::slurp(csv);
  CHECK(text.rfind("branch,period,gamma,position_m,velocity_mps,multiplier_1_re", 0) == 0);
  CHECK_THAT(text, Catch::Contains("# event: period-doubling at gamma = 1.5268237") && Catch::Contains("# git_revision"));
  std::size_t rows = 0;
  for (std::size_t at = text.find('\n'); at != std::string::npos && at + 1 < text.size(); at = text.find('\n', at + 1))
    rows += text[at + 1] != '#';
  CHECK(rows == j["branch"].size());
}

TEST_CASE("CLI continue: bad input exits 2 naming the option, no orbit at the start exits 3", "[orbit]") {
  for (const auto& [args, named] : {std::pair{"--parameter impacts --from 1 --to 2", "--parameter"},
                                    {"--parameter gamma --to 2", "--from"},
                                    {"--parameter gamma --from 1.3 --to 1.3", "--to"},
                                    {"--parameter restitution --from 0.5 --to 1.5", "--restitution"},
                                    {"--from 1.3 --to 1.4", "--parameter"},
                                    // The start's inputs: the map starts from its own states.
                                    {"--parameter start-phase --from 0.1 --to 0.6", "--parameter"},
                                    // gamma's default depends on e: continuing in e would move it too.
                                    {"--parameter restitution --from 0.5 --to 0.6", "--amplitude"}}) {
    const auto r = run_cli("continue shaker --restitution 0.5 " + std::string(args));
    INFO(args);
    CHECK(r.exit_code == 2);
    CHECK(r.out.empty());
    CHECK_THAT(r.err, Catch::Contains(named));
  }
  // Gamma = 1.02 < Gamma_1: the rig's own run sticks to the wall (see the orbit's case).
  const auto none = run_cli("continue shaker --restitution 0.5 --parameter gamma --from 1.02 --to 1.2");
  CHECK(none.exit_code == 3);
  CHECK_THAT(none.err, Catch::Contains("no branch followed"));
}

TEST_CASE("CLI lyapunov: a chaotic shaker's exponents, their sum 2 ln e per impact", "[orbit]") {
  // e = 0.95, Gamma = 2.2: chaotic (tests/test_orbit_lyapunov.cpp); the sum per impact is
  // 2 ln 0.95 = -0.10258659 to round-off, the largest exponent positive.
  const auto r = run_cli("lyapunov shaker --restitution 0.95 --gamma 2.2 --periods 10000 --json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"schema_version", "rig", "method", "periods", "impacts", "section_phase", "exponents_per_period",
                          "exponents_per_impact", "sum_per_impact", "expected_sum_per_impact", "half_difference",
                          "converged", "running", "inputs", "git_revision"})
    CHECK(j.contains(key));
  CHECK(j["periods"] == 10000);
  CHECK(std::abs(j["sum_per_impact"].get<double>() - 2 * std::log(0.95)) < 1e-10);
  CHECK(j["exponents_per_impact"][0].get<double>() > 0);
  CHECK(j["converged"] == true);
  // Too few periods for a chaotic run to converge: exit 3, the output standing.
  const auto short_run = run_cli("lyapunov shaker --restitution 0.95 --gamma 2.2 --periods 10");
  CHECK(short_run.exit_code == 3);
  CHECK_THAT(short_run.out, Catch::Contains("exponents per impact"));
  CHECK(run_cli("lyapunov shaker --periods 5").exit_code == 2);
}
