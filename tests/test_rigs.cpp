// The rig table (simulation/rigs/rig.hpp) and what every front end makes of it: each registered
// rig is a command whose --help lists every declared input, its run fills one scalar per result
// field and one cell per table column, and its JSON holds every field the run has under its name;
// a case file runs a rig over a grid (simulation/sweep/sweep_case.hpp), checked against the rig
// when read.
#include "cli_runner.hpp"
#include "scratch_dir.hpp"
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/reports/rig_report.hpp"
#include "hertzdash/simulation/rigs/rig_work_bound.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

using hertzdash::test::run_cli;
namespace test = hertzdash::test;

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

TEST_CASE("a case file with rig = \"shaker\" sweeps gamma: a row per point, the impacts in a second file", "[rigs][sweep]") {
  // The instantaneous map at e = 0.5 (tests/test_shaker.cpp): period 1 below its period doubling
  // Gamma_2 = sqrt((pi/3)^2 + (10/9)^2) = 1.5268, period 2 above; every rebound e times the impact
  // speed, so e_effective is 0.5 at every point. 1.40 and 1.65 lie 8 % either side of Gamma_2,
  // where 2000 transient impacts settle the orbit (the slower eigenvalue is far from -1 there).
  const hertzdash::test::ScratchDir dir;
  std::ofstream(dir.path / "case.toml") << "[base]\nrig = \"shaker\"\nimpact-model = \"instantaneous\"\n"
                                           "restitution = 0.5\ntransient = 2000\nimpacts = 4\n"
                                           "[grid]\ngamma = [1.40, 1.65]\n";
  std::string rows[2], impacts[2];
  for (int threads : {1, 2}) {
    const std::string out = (dir.path / ("t" + std::to_string(threads) + ".csv")).string();
    const auto r = run_cli("sweep " + (dir.path / "case.toml").string() + " --quiet --threads " +
                           std::to_string(threads) + " --out " + out);
    INFO(r.err);
    REQUIRE(r.exit_code == 0);
    rows[threads - 1] = test::slurp(out);
    rows[threads - 1].erase(rows[threads - 1].find("# timing:"), rows[threads - 1].find('\n', rows[threads - 1].find("# timing:")));
    impacts[threads - 1] = test::slurp(dir.path / ("t" + std::to_string(threads) + ".impacts.csv"));
  }
  CHECK(rows[0] == rows[1]);  // the runs do not depend on the threads that ran them
  CHECK(impacts[0] == impacts[1]);
  const hertzdash::CsvTable t = hertzdash::CsvTable::read(dir.path / "t1.csv");
  REQUIRE(t.rows() == 2);
  CHECK(t.number(0, "gamma") == 1.40);
  CHECK(t.number(0, "period") == 1);
  CHECK(t.number(1, "period") == 2);
  for (std::size_t row = 0; row < 2; ++row) CHECK(t.number(row, "e_effective") == Approx(0.5).epsilon(1e-12));
  const hertzdash::CsvTable i = hertzdash::CsvTable::read(dir.path / "t1.impacts.csv");
  CHECK(i.columns() == std::vector<std::string>{"run", "gamma", "n", "impact_time_s", "impact_phase", "impact_speed_mps",
                                                "rebound_speed_mps", "contact_time_s", "peak_force_N"});
  CHECK(i.rows() == 2 * 4);
}

TEST_CASE("a rig's case file is checked against the rig when read: exit 2 naming the key and line, no file", "[rigs][sweep]") {
  // Each case gives what its rig refuses: an option it does not read, an input of the other walls
  // variant (in [base], or by a [grid] value of `rig`), gamma with amplitude, a draw out of range.
  const test::ScratchDir dir;
  const std::pair<const char*, const char*> cases[] = {
      {"[base]\nrig = \"oscillator\"\nheight = 0.1\n", "invalid base.height (" /* line 3 */},
      {"[base]\nrig = \"walls\"\nforce-amplitude = 5\n", "invalid base.force-amplitude ("},
      {"[base]\nrig = \"walls\"\nforce-amplitude = 5\n[grid]\nrig = [\"damper\", \"box\"]\n", "invalid base.force-amplitude ("},
      {"[base]\nrig = \"shaker\"\namplitude = 0.001\n[grid]\ngamma = [1.0, 2.0]\n", "invalid grid.gamma ("},
      {"[base]\nrig = \"oscillator\"\n[sample]\ncount = 8\nstiffness = { distribution = \"normal\", mean = 0, sd = 1 }\n",
       "invalid sample.stiffness ("},
  };
  for (const auto& [text, message] : cases) {
    INFO(text);
    std::ofstream(dir.path / "case.toml") << text;
    const auto r = run_cli("sweep " + (dir.path / "case.toml").string() + " --quiet");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(message) != std::string::npos);
    CHECK(r.err.find("case.toml line ") != std::string::npos);
    CHECK_FALSE(std::filesystem::exists(dir.path / "case.csv"));
    CHECK_FALSE(std::filesystem::exists(dir.path / "case.impacts.csv"));
  }
}

TEST_CASE("a rig's case file: an unknown key lists the rig's inputs, [output] columns only its numbers", "[rigs][sweep]") {
  const test::ScratchDir dir;
  std::ofstream(dir.path / "case.toml") << "[base]\nrig = \"shaker\"\nbogus = 1\n";
  auto r = run_cli("sweep " + (dir.path / "case.toml").string() + " --quiet");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("an input of the rig shaker: frequency, amplitude, gamma") != std::string::npos);
  std::ofstream(dir.path / "case.toml") << "[base]\nrig = \"shaker\"\n[output]\ncolumns = [\"impact_model\"]\n";
  r = run_cli("sweep " + (dir.path / "case.toml").string() + " --quiet");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("invalid output.columns (") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir.path / "case.csv"));
}

TEST_CASE("a rig's case file writes a dotted result under its flat name and the damper's energy balances", "[rigs][sweep]") {
  // The damper's energy account with instantaneous impacts (simulation/shaker/two_walls.hpp):
  // W - D - L = E(end) - E(0), each term to round-off of W; the CSV's 10 significant digits make
  // the balance hold to ~1e-9 of the largest term.
  const test::ScratchDir dir;
  std::ofstream(dir.path / "case.toml")
      << "[base]\nrig = \"walls\"\nimpact-model = \"instantaneous\"\ngravity = 0\nrestitution = 0.6\n"
         "primary-damping-ratio = 0.05\nimpacts = 4\ntransient = 400\n[grid]\nrig = [\"damper\"]\n"
         "[output]\ncolumns = [\"energy_J_initial\", \"energy_J_final\", \"energy_J_drive_work\", "
         "\"energy_J_damping_dissipation\", \"energy_J_impact_loss\"]\n";
  const auto r = run_cli("sweep " + (dir.path / "case.toml").string() + " --quiet");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const hertzdash::CsvTable t = hertzdash::CsvTable::read(dir.path / "case.csv");
  REQUIRE(t.rows() == 1);
  const double W = t.number(0, "energy_J_drive_work"), D = t.number(0, "energy_J_damping_dissipation"),
               L = t.number(0, "energy_J_impact_loss");
  CHECK(W > 0);
  CHECK(W - D - L == Approx(t.number(0, "energy_J_final") - t.number(0, "energy_J_initial")).margin(1e-8 * W));
}

TEST_CASE("a rig records the options it reads and every own input, by column name", "[rigs]") {
  // run_options_not_read are refused, so not recorded; the own inputs at their defaults.
  const std::pair<const char*, std::vector<std::string>> absent[] = {
      {"oscillator", {"height_m", "impact_velocity_mps", "gravity_mps2"}},
      {"walls", {"height_m", "impact_velocity_mps"}},
      {"shaker", {"impact_velocity_mps"}},
  };
  for (const auto& [rig, keys] : absent) {
    INFO(rig);
    const auto r = run_cli(std::string(rig) + " --impact-model instantaneous --impacts 2 --transient 10 --json");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.out);
    for (const std::string& k : keys) CHECK_FALSE(j["inputs"].contains(k));
    for (const char* k : {"impacts", "transient", "impact_model"}) CHECK(j["inputs"].contains(k));
    CHECK(j["inputs"]["impact_model"] == "instantaneous");
  }
  const auto j = nlohmann::json::parse(run_cli("oscillator --impacts 2 --json").out);
  CHECK(j["inputs"]["stiffness_N_per_m"] == 1e4);  // the declared default
  CHECK(j["inputs"]["stop_distance_m"] == 0.002);
}

TEST_CASE("a rig's refusal names its command as `hertzdash RIG`, not as an option", "[rigs]") {
  auto r = run_cli("shaker --rod-model elastic");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("rigid for `hertzdash shaker`") != std::string::npos);
  r = run_cli("oscillator --height 0.1");
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("not given for `hertzdash oscillator`") != std::string::npos);
  CHECK(r.err.find("--oscillator") == std::string::npos);
}

TEST_CASE("a rig's work bound: N (c + L/S) from its time scales, the refusal naming the input given", "[rigs]") {
  using hertzdash::RigTimeScale;
  // W = N (c + L/S), c = rig_work_per_impact = 500, limit max_rig_work = 5e8 (rig_work_bound.hpp).
  // S = 1e-3 s and L = 1 s: 1,500 per impact, so 333,333 impacts fit and 400,000 (6e8) do not.
  const auto scales = [](bool short_given, bool long_given) {
    return std::vector<RigTimeScale>{{.what = "short", .seconds = 1e-3, .key = "frequency", .value = 1e3, .given = short_given},
                                     {.what = "long", .seconds = 1.0, .key = "gap", .value = 5, .given = long_given}};
  };
  CHECK_NOTHROW(hertzdash::require_bounded_rig_work(scales(true, true), 300000, 33333, true));
  const auto blamed = [&](bool short_given, bool long_given, bool impacts_given) {
    try {
      hertzdash::require_bounded_rig_work(scales(short_given, long_given), 390000, 10000, impacts_given);
    } catch (const hertzdash::InvalidParameter& e) {
      CHECK(e.valid_range.find("6e+08 steps") != std::string::npos);
      return e.key;
    }
    return std::string("nothing");
  };
  CHECK(blamed(true, true, true) == "frequency");   // the shortest resolved scale, given
  CHECK(blamed(false, true, true) == "gap");        // else the longest, given
  CHECK(blamed(false, false, true) == "impacts");   // else the count of impacts
  CHECK(blamed(false, false, false) == "frequency");
  // A duration the run does not resolve (a contact) is no S: 1e-9 s against 1 s costs nothing.
  const std::vector<RigTimeScale> contact{{.what = "drive", .seconds = 1.0, .key = "frequency", .value = 1},
                                          {.what = "contact", .seconds = 1e-9, .key = "mass", .value = 1, .resolved = false}};
  CHECK_NOTHROW(hertzdash::require_bounded_rig_work(contact, 100, 1000, false));
}

TEST_CASE("rigs whose time scales cannot be resolved are refused before they run, naming what was given", "[rigs]") {
  // The reproducers of issue 45: each hung for over a minute, or exited 1, or ran in silence.
  const std::pair<std::string, std::string> cases[] = {
      {"walls --rig damper --frequency 1e9", "--frequency"},
      {"walls --rig damper --frequency 1e9 --impact-model instantaneous", "--frequency"},
      {"walls --rig damper --primary-stiffness 1e20", "--primary-stiffness"},
      {"walls --rig damper --primary-stiffness 1e-25", "--primary-stiffness"},
      {"walls --rig damper --primary-stiffness 1e30", "--primary-stiffness"},
      {"walls --rig box --gap 1e-300", "--gap"},
      {"walls --rig damper --impact-model instantaneous --primary-mass 1e-20", "--primary-mass"},
      {"shaker --gamma 1e9", "--gamma"},
      {"shaker --frequency 1e9", "--frequency"},
      {"shaker --impacts 10000000 --transient 0", "--impacts"},
      {"oscillator --stiffness 1e25", "--stiffness"},
      // The wall's amplitude A = gamma g / (2 pi f)^2 under- or overflows: the frequency is named.
      {"shaker --impact-model instantaneous --frequency 1e300", "--frequency"},
      {"shaker --impact-model instantaneous --frequency 1e-300", "--frequency"},
      {"walls --frequency 1e-300", "--frequency"}};
  for (const auto& [args, option] : cases) {
    const auto r = run_cli(args);
    INFO(args << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("invalid " + option + " =") != std::string::npos);
    CHECK(r.out.empty());
  }
  // `shaker --sweep ''` ran one shaker: a rig sweeps through a case file, and the option is none.
  const auto sweep = run_cli("shaker --sweep ''");
  CHECK(sweep.exit_code == 2);
  CHECK(sweep.err.find("unknown option --sweep") != std::string::npos);
  CHECK(sweep.out.empty());
}

// Issue 46: `shaker --help` listed --impact-velocity, --air-density, --rod-model and rk4, each
// refused when given, and ran past 60 lines. A rig's help lists what its runs read; the options
// it never reads are still refused with their reason, not as unknown.
TEST_CASE("a rig's help lists what it reads, and what it never reads is refused with its reason", "[rigs]") {
  for (const hertzdash::Rig& rig : hertzdash::rigs()) {
    INFO(rig.name);
    const auto help = run_cli(std::string(rig.name) + " --help");
    REQUIRE(help.exit_code == 0);
    CHECK(std::count(help.out.begin(), help.out.end(), '\n') <= 60);
    // The impact-sequence rigs run soft contacts in regularising variables; a single-impact rig
    // (`spheres`) reads the speed, the clamp and every integrator's options as `simulate` does.
    std::vector<std::string> never{"--air-density", "--rod-model", "--accelerometer", "--rod-elements"};
    if (rig.regularized_contacts) never.insert(never.end(), {"--impact-velocity ", "--dt ", "--no-tension", "--max-step"});
    for (const std::string& option : never) CHECK(help.out.find(option) == std::string::npos);
    const auto given = run_cli(std::string(rig.name) + " --air-density 1.2");
    CHECK(given.exit_code == 2);
    CHECK(given.err.find("invalid --air-density = 1.2: must be") != std::string::npos);
  }
  // The shaker's help said --gravity "0 allowed" and its refusal of 0 named --impact-velocity,
  // an option the shaker does not take: both are the shaker's own now.
  const auto help = run_cli("shaker --help");
  CHECK(help.out.find("0 allowed") == std::string::npos);
  const auto zero = run_cli("shaker --gravity 0");
  CHECK(zero.exit_code == 2);
  CHECK(zero.err.find("invalid --gravity = 0: must be > 0 for the shaker") != std::string::npos);
  CHECK(zero.err.find("impact-velocity") == std::string::npos);
}
