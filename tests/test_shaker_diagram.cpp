// The shaker's bifurcation diagram, a case file of `hertzdash sweep` with rig = "shaker"
// (simulation/sweep/sweep_case.hpp, docs/shaker.md): the instantaneous bouncing-ball map across
// its period-doubling threshold, identical with one and two threads; an amplitude or frequency
// axis, with gamma = A (2 pi f)^2 / g in the rows.
#include "cli_runner.hpp"
#include "scratch_dir.hpp"

#include "hertzdash/io/csv_table.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using hertzdash::test::run_cli;
using hertzdash::test::slurp;
using hertzdash::test::ScratchDir;

namespace {

// The exact map's period-doubling threshold for e = 0.5 (derived in tests/test_shaker.cpp):
// Gamma_2 = sqrt((pi (1-e)/(1+e))^2 + (2 (1+e^2)/(1+e)^2)^2) = sqrt((pi/3)^2 + (10/9)^2) = 1.526824.
const double gamma_2 = std::hypot(std::numbers::pi / 3, 10.0 / 9.0);

// Distinct values among phases on the circle [0, 1), two being the same within 1e-6 (the period
// detection's tolerance, docs/shaker.md).
int distinct_phases(std::vector<double> phases) {
  std::sort(phases.begin(), phases.end());
  int distinct = 1;
  for (std::size_t k = 1; k < phases.size(); ++k) distinct += phases[k] - phases[k - 1] > 1e-6 ? 1 : 0;
  if (distinct > 1 && phases.front() + 1 - phases.back() <= 1e-6) --distinct;  // the two ends of the circle
  return distinct;
}

// The file without its timing line (which names the thread count).
std::string without_timing(const std::string& text) {
  std::istringstream in(text);
  std::string out;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("# timing:", 0) != 0) out += line + "\n";
  return out;
}

// `hertzdash sweep CASE --out NAME.csv ARGS` in `dir`, the case the shaker's instantaneous map
// at e = 0.5 with `rest` (its kept impacts and a [grid] table): NAME.csv and NAME.impacts.csv.
void sweep_shaker(const ScratchDir& dir, const std::string& name, const std::string& rest, const std::string& args = "") {
  const auto case_file =
      dir.write("case.toml", "[base]\nrig = \"shaker\"\nimpact-model = \"instantaneous\"\nrestitution = 0.5\n" + rest);
  const auto r = run_cli("sweep " + case_file.string() + " --quiet --out " + (dir.path / (name + ".csv")).string() +
                         " " + args);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
}

}  // namespace

TEST_CASE("CLI sweep: the shaker's diagram has one impact phase per gamma below the period doubling and two above",
          "[shaker][sweep]") {
  // The instantaneous map at e = 0.5 swept over gamma 1.30 ... 1.60 in steps of 0.01 (31 values).
  // Below Gamma_2 = 1.526824 the period-1 orbit is stable: every kept impact of a value has the
  // same phase. Above it the orbit doubles (a flip bifurcation): two phases alternate, split by
  // O(sqrt(gamma - Gamma_2)) of a cycle. 20000 transient impacts settle every value outside 1 % of
  // Gamma_2 (tests/test_shaker.cpp: 1 % below, the slower eigenvalue is -0.935, and 0.935^20000 is
  // nothing; farther from the threshold the orbit attracts faster); values within 1 % of Gamma_2,
  // where the eigenvalue approaches -1 and settling slows without bound, are not asserted. Above,
  // the values stay below 1.60 = 1.048 Gamma_2: the period-2 orbit's own doubling (no closed form;
  // the diagram shows it near 1.67, 9 % above Gamma_2) is well beyond.
  const ScratchDir dir;
  const std::string grid = "transient = 20000\nimpacts = 16\n[grid]\ngamma = { from = 1.30, to = 1.60, count = 31 }\n";
  sweep_shaker(dir, "one", grid, "--threads 1");
  sweep_shaker(dir, "two", grid, "--threads 2");
  // Each value's run is independent of the others and of the thread that ran it, and the rows are
  // written in value order: the files are the same byte for byte but for the timing line.
  CHECK(without_timing(slurp(dir.path / "one.csv")) == without_timing(slurp(dir.path / "two.csv")));
  CHECK(without_timing(slurp(dir.path / "one.impacts.csv")) == without_timing(slurp(dir.path / "two.impacts.csv")));

  const hertzdash::CsvTable runs = hertzdash::CsvTable::read(dir.path / "one.csv");
  const hertzdash::CsvTable impacts = hertzdash::CsvTable::read(dir.path / "one.impacts.csv");
  REQUIRE(runs.rows() == 31);
  REQUIRE(impacts.rows() == 31 * 16);
  CHECK(impacts.comment_field("git_revision").has_value());
  std::map<int, std::vector<double>> phases;
  for (std::size_t row = 0; row < impacts.rows(); ++row) {
    phases[static_cast<int>(impacts.number(row, "run"))].push_back(impacts.number(row, "impact_phase"));
    CHECK(impacts.number(row, "contact_time_s") == 0);
  }
  int below = 0, above = 0;
  for (std::size_t run = 0; run < runs.rows(); ++run) {
    const double g = runs.number(run, "gamma");
    const int period = static_cast<int>(runs.number(run, "period"));
    CHECK(g == Approx(1.30 + 0.01 * static_cast<double>(run)).epsilon(1e-12));  // from + (to - from) i/(n-1)
    INFO("gamma " << g);
    if (g < 0.99 * gamma_2) {
      CHECK(distinct_phases(phases.at(static_cast<int>(run))) == 1);
      CHECK(period == 1);
      ++below;
    } else if (g > 1.01 * gamma_2) {
      CHECK(distinct_phases(phases.at(static_cast<int>(run))) == 2);
      CHECK(period == 2);
      ++above;
    }
  }
  CHECK(below == 22);  // 1.30 ... 1.51 (0.99 Gamma_2 = 1.5116)
  CHECK(above == 6);   // 1.55 ... 1.60 (1.01 Gamma_2 = 1.5421)
}

TEST_CASE("CLI sweep: a shaker's amplitude or frequency axis gives gamma = A (2 pi f)^2 / g in its rows",
          "[shaker][sweep]") {
  // Gamma = A w^2 / g, w = 2 pi f, g = 9.80665 m/s^2 (the paper's gravity): sweeping A at f = 20 Hz
  // gives gamma proportional to A (1.13 to 1.61: every value bounces, Gamma > 1); sweeping f at
  // gamma 1.3 keeps gamma fixed (the amplitude follows, A = gamma g / w^2). Both to the CSV's
  // shortest round-trip printing.
  const ScratchDir dir;
  const std::string kept = "transient = 200\nimpacts = 4\n";
  sweep_shaker(dir, "a", kept + "[grid]\namplitude = { from = 7e-4, to = 1e-3, count = 3 }\n");
  sweep_shaker(dir, "f", kept + "gamma = 1.3\n[grid]\nfrequency = { from = 10, to = 30, count = 3 }\n");
  const hertzdash::CsvTable ta = hertzdash::CsvTable::read(dir.path / "a.csv");
  const hertzdash::CsvTable tf = hertzdash::CsvTable::read(dir.path / "f.csv");
  REQUIRE(ta.rows() == 3);
  REQUIRE(tf.rows() == 3);
  const double w = 2 * std::numbers::pi * 20, g = 9.80665;
  for (std::size_t row = 0; row < 3; ++row) {
    const double A = ta.number(row, "amplitude_m"), i = static_cast<double>(row);
    CHECK(A == Approx(7e-4 + 1.5e-4 * i).epsilon(1e-12));
    CHECK(ta.number(row, "gamma") == Approx(A * w * w / g).epsilon(1e-12));
    CHECK(tf.number(row, "frequency_Hz") == Approx(10 + 10 * i).epsilon(1e-12));
    CHECK(tf.number(row, "gamma") == Approx(1.3).epsilon(1e-12));
  }
}
