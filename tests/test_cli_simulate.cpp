// `hertzdash simulate`: the JSON summary carries every promised field and the
// inputs actually used; the trace is the contact phase in the measured-trace format, provenance below the column names;
// the README's example prints what the README says it prints.
#include "cli_runner.hpp"
#include "scratch_dir.hpp"
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/provenance.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using hertzdash::test::run_cli;

namespace {

/// `hertzdash simulate ARGS --json --trace FILE`: its JSON and the trace file read back (the file
/// in a scratch directory, removed after).
struct SimulatedTrace {
  nlohmann::json j;
  hertzdash::CsvTable t;
};
SimulatedTrace simulate_with_trace(const std::string& args) {
  const hertzdash::test::ScratchDir dir;
  const std::string path = (dir.path / "trace.csv").string();
  const auto r = run_cli("simulate " + args + " --json --trace " + path);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return {nlohmann::json::parse(r.out), hertzdash::CsvTable::read(path)};
}

}  // namespace

TEST_CASE("CLI simulate --json: fields, units and inputs", "[cli]") {
  const auto r = run_cli("simulate --rod steel --height 0.02 --integrator cvode --json");
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::ordered_json::parse(r.out);
  // The keys of docs/json-output.md, schema version 1, in its order.
  std::vector<std::string> keys;
  for (const auto& [key, value] : j.items()) keys.push_back(key);
  CHECK(keys == std::vector<std::string>{"schema_version", "e_effective", "peak_force_N", "max_deformation_m",
                                         "peak_contact_pressure_Pa", "yield_onset_pressure_Pa", "exceeds_yield_onset",
                                         "hertz_profile_error", "exceeds_small_deformation", "contact_time_s",
                                         "impact_velocity_mps", "rebound_velocity_mps", "separated", "K_N_per_m_1_5",
                                         "law_coefficients", "steps", "rhs_evaluations", "events", "integrator_used",
                                         "warnings", "inputs", "git_revision"});
  CHECK(j["schema_version"].get<int>() == 2);
  const auto& law = j["law_coefficients"];
  CHECK(law.contains("zeta"));
  CHECK(law.contains("omega_n_rad_per_s"));
  // e_effective is rebound over approach speed; v0 = sqrt(2 g h) for a free fall.
  CHECK(j["e_effective"].get<double>() ==
        Approx(j["rebound_velocity_mps"].get<double>() / j["impact_velocity_mps"].get<double>()).epsilon(1e-15));
  CHECK(j["impact_velocity_mps"].get<double>() == Approx(std::sqrt(2 * 9.80665 * 0.02)).epsilon(1e-8));
  // Table 2: steel e = 0.795 -> eq. (6) zeta = ln(1/0.795)/pi.
  CHECK(law["zeta"].get<double>() == Approx(std::log(1 / 0.795) / M_PI).epsilon(1e-14));
  const auto& in = j["inputs"];
  CHECK(in["mass_kg"].get<double>() == 0.778);
  CHECK(in["restitution"].get<double>() == 0.795);
  CHECK(in["height_m"].get<double>() == 0.02);
  CHECK(in["integrator"].get<std::string>() == "cvode");
  CHECK(in["damping"].get<std::string>() == "hongo");
}

TEST_CASE("CLI simulate --json names the integrator that ran, and stderr says why it fell back", "[cli]") {
  // The integrator table's fall-backs: gbs8-regularized integrates the contact in u = x^{1/2},
  // which has no event for the tension clamp, so with --no-tension dopri5 runs in the
  // physical variables; gbs8 needs a law declaring force_of_root, which tsuji-dem (x^{1/4}
  // dashpot) does not, so dopri5-regularized runs. A run that fell back must be the very
  // run of the integrator it names: the same result and the same work, to the last bit.
  struct Case {
    std::string options, used, same_as;
  };
  for (const Case& c : {Case{"--integrator gbs8-regularized --no-tension", "dopri5", "--integrator dopri5 --no-tension"},
                        Case{"--integrator gbs8-regularized --damping tsuji-dem", "dopri5-regularized",
                             "--integrator dopri5-regularized --damping tsuji-dem"},
                        Case{"--integrator cvode-regularized --no-tension", "cvode", "--integrator cvode --no-tension"},
                        Case{"--integrator gbs8-regularized", "gbs8-regularized", ""}}) {
    INFO(c.options);
    const auto r = run_cli("simulate --json " + c.options);
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["integrator_used"].get<std::string>() == c.used);
    if (c.same_as.empty()) {
      CHECK(j["inputs"]["integrator"].get<std::string>() == c.used);
      CHECK(r.err.find("fell back") == std::string::npos);
      continue;
    }
    CHECK(r.err.find("fell back to " + c.used + ":") != std::string::npos);
    const auto same = nlohmann::json::parse(run_cli("simulate --json " + c.same_as).out);
    CHECK(same["integrator_used"].get<std::string>() == c.used);
    CHECK(j["e_effective"].get<double>() == same["e_effective"].get<double>());
    CHECK(j["peak_force_N"].get<double>() == same["peak_force_N"].get<double>());
    CHECK(j["rhs_evaluations"].get<long>() == same["rhs_evaluations"].get<long>());
  }
}

TEST_CASE("CLI restitution names the integrator that ran", "[cli]") {
  // The same table fall-back as simulate: the tension clamp sends gbs8-regularized to dopri5.
  const auto r = run_cli("restitution --json --integrator gbs8-regularized --no-tension");
  REQUIRE(r.exit_code == 0);
  CHECK(nlohmann::json::parse(r.out)["integrator_used"].get<std::string>() == "dopri5");
  CHECK(r.err.find("fell back to dopri5:") != std::string::npos);
  CHECK(nlohmann::json::parse(r.out)["warnings"][0]["code"] == "integrator_fallback");
  // Without the fall-back nothing is said (the yield check off: the 20 mm contact exceeds the
  // yield onset, a warning restitution reports like simulate).
  const auto plain = run_cli("restitution --json --integrator gbs8-regularized --ball-yield-stress inf");
  REQUIRE(plain.exit_code == 0);
  CHECK(nlohmann::json::parse(plain.out)["integrator_used"].get<std::string>() == "gbs8-regularized");
  CHECK(plain.err.empty());
}

TEST_CASE("CLI simulate --trace: contact phase under a provenance header", "[cli]") {
  const auto [j, t] = simulate_with_trace("");
  // The measured-trace format (data/measurements/README.md), then the model's own columns.
  CHECK(t.columns() == std::vector<std::string>{"t_s", "force_N", "accel_mps2", "velocity_mps", "displacement_m",
                                                "x_m", "xdot_mps", "contact_force_N", "rod_accel_mps2"});
  // The rigid model's instruments: the cell reads the contact force, the accelerometer the rod.
  for (std::size_t i = 0; i < t.rows(); ++i) {
    CHECK(t.number(i, "force_N") == t.number(i, "contact_force_N"));
    CHECK(t.number(i, "accel_mps2") == t.number(i, "rod_accel_mps2"));
  }
  bool has_revision = false, has_mass = false;
  for (const auto& c : t.comments()) {
    has_revision |= c.text.rfind("git_revision: ", 0) == 0;
    has_mass |= c.text == "mass_kg: 0.778";
  }
  CHECK(has_revision);
  CHECK(has_mass);
  CHECK(t.comment_field("rod") == std::string("steel"));
  CHECK(t.comment_field("height_m") == std::string("0.02"));
  CHECK(t.comment_field("synthetic") == std::string("true"));
  REQUIRE(t.rows() > 10);
  // Starts at onset (t = 0, x = 0, approach speed), ends at separation (x = 0, rebound).
  CHECK(t.number(0, "t_s") == 0);
  CHECK(std::abs(t.number(0, "x_m")) < 1e-12);
  CHECK(t.number(0, "xdot_mps") == Approx(j["impact_velocity_mps"].get<double>()));
  const std::size_t last = t.rows() - 1;
  CHECK(std::abs(t.number(last, "x_m")) < 1e-12);
  CHECK(-t.number(last, "xdot_mps") == Approx(j["rebound_velocity_mps"].get<double>()));
  CHECK(t.number(last, "t_s") == Approx(j["contact_time_s"].get<double>()));
  // The peak-force event puts a sample on the maximum; eq. (1): accel = g - F/m; the rigid rod
  // moves with the deformation on a fixed hemisphere: displacement since onset = x, velocity = x'.
  double peak = 0;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    peak = std::max(peak, t.number(i, "force_N"));
    CHECK(t.number(i, "accel_mps2") == Approx(9.80665 - t.number(i, "force_N") / 0.778).margin(1e-9));
    CHECK(t.number(i, "displacement_m") == Approx(t.number(i, "x_m")).margin(1e-15));
    CHECK(t.number(i, "velocity_mps") == t.number(i, "xdot_mps"));
  }
  CHECK(peak == Approx(j["peak_force_N"].get<double>()).epsilon(1e-15));
}

TEST_CASE("CLI --version names the version and the git revision it was built from", "[cli]") {
  const auto r = run_cli("--version");
  CHECK(r.exit_code == 0);
  CHECK(r.out == std::string("hertzdash ") + hertzdash::version() + " (git " + hertzdash::git_revision() + ")\n");
}

TEST_CASE("CLI simulate --rod-model elastic: the instruments, the energy account, the stability note", "[cli][elastic]") {
  const auto [j, t] = simulate_with_trace("--rod-model elastic");
  const auto& e = j["elastic_rod"];
  // The account closes: in = rigid-body out + vibration + cell + both dissipations + error,
  // with the error at the integrator's level (rtol 1e-8 of the energy in, with margin).
  const double in = e["energy_in_J"].get<double>();
  CHECK(std::abs(e["energy_balance_error_J"].get<double>()) < 1e-7 * in);
  CHECK(e["energy_rod_vibration_J"].get<double>() > 0);
  CHECK(e["energy_cell_J"].get<double>() > 0);
  CHECK(j["inputs"]["rod_model"] == "elastic");
  CHECK(j["inputs"]["accelerometer"] == "top");
  // On the load cell, the cell's force is not the contact force (the hemisphere's inertia and
  // the cell's dashpot lie between), and the top face's accelerometer is not the centre of mass.
  double cell_gap = 0, accel_gap = 0;
  for (std::size_t i = 0; i < t.rows(); ++i) {
    cell_gap = std::max(cell_gap, std::abs(t.number(i, "force_N") - t.number(i, "contact_force_N")));
    accel_gap = std::max(accel_gap, std::abs(t.number(i, "accel_mps2") - t.number(i, "rod_accel_mps2")));
  }
  CHECK(cell_gap > 1e-3 * j["peak_force_N"].get<double>());
  CHECK(accel_gap > 0.05 * j["peak_force_N"].get<double>() / 0.778);  // > 5 % of the peak deceleration

  // rk4 at --dt 1e-5 would be unstable on the rod's fastest mode: the run takes the limit and says so.
  const auto rk4 = run_cli("simulate --rod-model elastic --integrator rk4 --dt 1e-5 --json");
  REQUIRE(rk4.exit_code == 0);
  const auto k = nlohmann::json::parse(rk4.out)["elastic_rod"];
  CHECK(k["step_used_s"].get<double>() == k["stable_step_s"].get<double>());
  CHECK(k["step_used_s"].get<double>() < 1e-5);
  CHECK(rk4.err.find("limits rk4 to steps of") != std::string::npos);
  // A regularised path falls back to its physical counterpart, with the reason.
  const auto gbs = run_cli("simulate --rod-model elastic --integrator gbs8-regularized --json");
  REQUIRE(gbs.exit_code == 0);
  CHECK(nlohmann::json::parse(gbs.out)["integrator_used"] == "dopri5");
  CHECK(gbs.err.find("--rod-model elastic") != std::string::npos);
}

TEST_CASE("CLI simulate: a pair changed on top of a preset keeps the preset's e with a note, and the inputs name the preset",
          "[cli]") {
  // Table 2's e was measured for each rod on the hemisphere. A run that gives the pair a mass of
  // its own but no --restitution still uses the steel rod's 0.795: said, not silent.
  auto codes = [](const nlohmann::json& j) {
    std::vector<std::string> c;
    for (const auto& w : j["warnings"]) c.push_back(w["code"]);
    return c;
  };
  const auto custom = run_cli("simulate --mass 1.0 --json");
  REQUIRE(custom.exit_code == 0);
  const auto j = nlohmann::json::parse(custom.out);
  CHECK(j["inputs"]["rod"] == "steel");
  CHECK(j["inputs"]["restitution"] == 0.795);
  const auto c = codes(j);
  CHECK(std::find(c.begin(), c.end(), "preset_restitution") != c.end());
  CHECK_THAT(custom.err, Catch::Contains("hertzdash: note: the input e = 0.795 is the steel rod's, measured for that "
                                         "rod on the hemisphere (Table 2); the run changed the pair"));
  CHECK_THAT(custom.err, Catch::Contains("give --restitution for it"));
  // With its own e, found by a calibration for this pair, with a law that reads none, or with the
  // preset as it is: no note.
  for (const char* args : {"restitution --mass 1.0 --target-restitution 0.7", "bounce --mass 1.0 --bounces 3 "
                                                                               "--target-interval-restitution 0.7"}) {
    INFO(args);
    const auto r = run_cli(std::string(args) + " --json");
    REQUIRE(r.exit_code == 0);
    CHECK_THAT(r.out, !Catch::Contains("preset_restitution"));
  }
  for (const char* args : {"--mass 1.0 --restitution 0.8", "--mass 1.0 --damping none", "--rod duralumin-a"}) {
    INFO(args);
    const auto r = run_cli(std::string("simulate --json ") + args);
    REQUIRE(r.exit_code == 0);
    const auto k = codes(nlohmann::json::parse(r.out));
    CHECK(std::find(k.begin(), k.end(), "preset_restitution") == k.end());
  }
}
