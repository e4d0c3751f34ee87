// Basins of attraction (simulation/orbits/basins.hpp) of the bouncing ball where two attractors
// coexist, and the command (`hertzdash basins RIG`).
//
// e = 0.8, Gamma = 0.8 < 1: the table never accelerates downwards faster than g, so a body that
// comes to rest on it stays there; and the period-1 orbit exists above Gamma_1 = pi (1 - e)/(1 + e)
// = 0.349, stable below Gamma_2 = sqrt(Gamma_1^2 + (2 (1 + e^2)/(1 + e)^2)^2) = 1.0671
// (tests/test_orbits.cpp derives both), impacting at phase theta*/(2 pi) with
// cos theta* = Gamma_1/Gamma: 0.17813861. A start either settles on the orbit or comes to rest.
#include "cli_runner.hpp"
#include "scratch_dir.hpp"

#include "hertzdash/simulation/orbits/basins.hpp"
#include "hertzdash/simulation/orbits/periodic_orbit.hpp"
#include "hertzdash/simulation/orbits/section_guess.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"
#include "validation/common/steel_rod_setups.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

using namespace hertzdash;

namespace {

constexpr double e = 0.8, gamma = 0.8, f_Hz = 20;

ImpactSequenceSpec ball() {
  const DropTestSetup s = paper_steel_rod(e);
  ShakerOptions o;
  o.wall = {.amplitude_m = shaker_amplitude_m(gamma, f_Hz, s.gravity_mps2), .frequency_Hz = f_Hz};
  o.impact_model = ShakerImpactModel::instantaneous;
  return make_shaker_sequence(s, "hongo-paper", {}, o).spec;
}

double orbit_phase() {
  const double gamma_1 = std::numbers::pi * (1 - e) / (1 + e);
  return std::acos(gamma_1 / gamma) / (2 * std::numbers::pi);
}

BasinOptions grid(unsigned threads) {
  // The section half a cycle after the orbit's impact; positions from just above the table's
  // highest point (A = 0.5 mm) to 20 mm, velocities +-0.5 m/s (the orbit's g T/2 = 0.245 m/s).
  return {.section_phase = std::fmod(orbit_phase() + 0.5, 1.0), .position_min_m = 6e-4, .position_max_m = 0.02,
          .velocity_min_mps = -0.5, .velocity_max_mps = 0.5, .resolution = 12, .threads = threads};
}

}  // namespace

TEST_CASE("basins: the bouncing ball's period-1 orbit and the body at rest share the section, whatever the threads",
          "[orbit]") {
  const Basins one = compute_basins(ball, grid(1)), two = compute_basins(ball, grid(2));
  // Deterministic: the same attractors, numbered alike, cell by cell.
  CHECK(one.cell == two.cell);
  REQUIRE(one.attractors.size() == two.attractors.size());
  // Both attractors, each with a basin of its own; the period-1 orbit at its closed-form phase
  // (the root search places impacts to 1e-13 of a cycle; the kept impacts are 400 past a start
  // whose transient decays like e^n, so to 1e-9 here).
  const auto periodic = std::ranges::find_if(one.attractors, [](const BasinAttractor& a) {
    return a.kind == BasinAttractor::Kind::periodic && a.period == 1 && a.impacts_per_period == 1;
  });
  const auto rest = std::ranges::find_if(one.attractors, [](const BasinAttractor& a) { return a.kind == BasinAttractor::Kind::rest; });
  REQUIRE(periodic != one.attractors.end());
  REQUIRE(rest != one.attractors.end());
  CHECK(periodic->phases.at(0) == Approx(orbit_phase()).margin(1e-9));
  CHECK(periodic->cells > 0);
  CHECK(rest->cells > 0);
  long counted = one.inside_wall;
  for (const BasinAttractor& a : one.attractors) counted += a.cells;
  CHECK(counted == 12 * 12);
}

TEST_CASE("basins shared among processes: each runs its rows, process 0 numbers the grid as one process does",
          "[orbit]") {
  // Three processes in one: the ranks' gathers are played here (rank 1 and 2 hand their text to
  // process 0's gather, which returns all three in rank order; tests/basins_mpi.sh runs mpirun).
  // Their texts carry each phase in its shortest exact decimal, so process 0 sees the same outcomes
  // as if it had run every row: the same cells, attractors and phases, to the bit.
  const Basins alone = compute_basins(ball, grid(2));
  std::vector<std::string> texts(3);
  for (int rank : {1, 2}) {
    BasinOptions o = grid(1);
    o.rank = rank, o.ranks = 3;
    o.gather = [&texts, rank](const std::string& mine) {
      texts[static_cast<std::size_t>(rank)] = mine;
      return std::vector<std::string>{};
    };
    CHECK(compute_basins(ball, o).elsewhere);
  }
  BasinOptions o = grid(2);
  o.rank = 0, o.ranks = 3;
  o.gather = [&texts](const std::string& mine) {
    texts[0] = mine;
    return texts;
  };
  const Basins shared = compute_basins(ball, o);
  CHECK_FALSE(shared.elsewhere);
  CHECK(shared.cell == alone.cell);
  CHECK(shared.inside_wall == alone.inside_wall);
  REQUIRE(shared.attractors.size() == alone.attractors.size());
  for (std::size_t k = 0; k < alone.attractors.size(); ++k) {
    CHECK(shared.attractors[k].phases == alone.attractors[k].phases);
    CHECK(shared.attractors[k].cells == alone.attractors[k].cells);
  }
  // 12 rows over 3 processes: 4 each; rank 1's text has 4 x 12 lines.
  CHECK(std::count(texts[1].begin(), texts[1].end(), '\n') == 4 * 12);
}

TEST_CASE("basins: the orbit Newton finds lies in its own basin", "[orbit]") {
  // Shooting from the apex of the closed form (half a cycle after the impact: y = A sin theta* +
  // g T^2/8, u = 0), then a 2 x 2 grid of starts within 1e-3 of the scales around the orbit: a
  // stable orbit attracts its neighbourhood, so all four reach the period-1 attractor.
  const BasinOptions g0 = grid(1);
  const ImpactSequenceSpec spec = ball();
  const double g = 9.80665, T = 1 / f_Hz, A = spec.prescribed->position_m(0.25 / f_Hz);
  const double theta = 2 * std::numbers::pi * orbit_phase();
  const Eigen::Vector2d scale(g * T * T, g * T), apex(A * std::sin(theta) + g * T * T / 8, 0);
  const PeriodicOrbit o = find_periodic_orbit(StroboscopicMap(spec, g0.section_phase, 1), apex, scale);
  REQUIRE(o.converged);
  BasinOptions near = g0;
  near.resolution = 2;
  near.position_min_m = o.state(0) - 1e-3 * scale(0), near.position_max_m = o.state(0) + 1e-3 * scale(0);
  near.velocity_min_mps = o.state(1) - 1e-3 * scale(1), near.velocity_max_mps = o.state(1) + 1e-3 * scale(1);
  const Basins b = compute_basins(ball, near);
  REQUIRE(b.attractors.size() == 1);
  CHECK(b.attractors[0].kind == BasinAttractor::Kind::periodic);
  CHECK(b.attractors[0].period == 1);
  CHECK(b.attractors[0].phases.at(0) == Approx(orbit_phase()).margin(1e-9));
  CHECK(b.attractors[0].cells == 4);
}

TEST_CASE("CLI basins: the grid as JSON and CSV, bad ranges exit 2 naming the option", "[orbit]") {
  using hertzdash::test::run_cli;
  const hertzdash::test::ScratchDir dir;
  const std::string csv = (dir.path / "basins.csv").string();
  const auto r = run_cli("basins shaker --restitution 0.8 --gamma 0.8 --resolution 8 --position-min 6e-4 "
                         "--position-max 0.02 --velocity-min -0.5 --velocity-max 0.5 --threads 2 --json --csv " + csv);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  for (const char* key : {"schema_version", "rig", "method", "section_phase", "position_m", "velocity_mps", "resolution",
                          "attractors", "inside_wall", "cell", "inputs", "git_revision"})
    CHECK(j.contains(key));
  CHECK(j["cell"].size() == 8);
  CHECK(j["position_m"].size() == 8);
  long cells = j["inside_wall"].get<long>();
  for (const auto& a : j["attractors"]) cells += a["cells"].get<long>();
  CHECK(cells == 64);
  std::ifstream in(csv);
  std::string line;
  long rows = 0;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') ++rows;
  CHECK(rows == 1 + 64);  // the header and one row per start
  const auto bad = run_cli("basins shaker --position-min 0.02 --position-max 0.01 --velocity-min -1 --velocity-max 1");
  CHECK(bad.exit_code == 2);
  CHECK(bad.err.find("position-max") != std::string::npos);
  const auto half = run_cli("basins shaker --position-min 0.01");
  CHECK(half.exit_code == 2);
  CHECK(half.err.find("position-max") != std::string::npos);
}

TEST_CASE("CLI basins: the impact damper's slice, the cells next to its orbit reaching it", "[orbit]") {
  // The default damper's orbit (`orbit walls --rig damper`: period 1, 3 impacts, its complex pairs
  // of modulus 0.89 and 0.50) from the rig's own run; the basins' grid is centred on the same
  // run's state at the section with the primary started where that run has it, its half-widths half
  // the gap and the body's speed there, so the four cells around the centre (1/8 of those from it)
  // start near a stable orbit and reach it: period 1 and the orbit's three impact phases, to the
  // grid's phase tolerance 1e-4.
  using hertzdash::test::run_cli;
  const auto o = run_cli("orbit walls --rig damper --json");
  REQUIRE(o.exit_code == 0);
  const nlohmann::json orbit = nlohmann::json::parse(o.out);
  std::vector<double> phases = orbit["impact_phase"].get<std::vector<double>>();
  std::ranges::sort(phases);
  const auto r = run_cli("basins walls --rig damper --resolution 8 --threads 2 --json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const nlohmann::json j = nlohmann::json::parse(r.out);
  CHECK(j["section_phase"].get<double>() == Approx(orbit["section_phase"].get<double>()).margin(1e-12));
  CHECK(j["inputs"]["box_position_m"].get<double>() ==
        Approx(orbit["section_state"]["box_position_m"].get<double>()).margin(1e-9));
  for (const int row : {3, 4})
    for (const int col : {3, 4}) {
      const int index = j["cell"][row][col].get<int>();
      REQUIRE(index >= 0);  // not inside a wall
      const nlohmann::json& a = j["attractors"][static_cast<std::size_t>(index)];
      CHECK(a["kind"] == "periodic");
      CHECK(a["period"] == 1);
      const std::vector<double> reached = a["impact_phase"].get<std::vector<double>>();
      REQUIRE(reached.size() == 3);
      for (std::size_t k = 0; k < 3; ++k) CHECK(reached[k] == Approx(phases[k]).margin(1e-4));
    }
}
