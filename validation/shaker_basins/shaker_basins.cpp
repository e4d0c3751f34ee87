// Where two attractors coexist: the basins of the bouncing ball's period-1 orbit and of the body
// at rest on the table.
//
// At e = 0.8 and Gamma = 0.8 < 1 the table never accelerates downwards faster than g, so a body
// at rest on it stays there; and the period-1 orbit exists above Gamma_1 = pi (1 - e)/(1 + e) =
// 0.349 and is stable below Gamma_2 = 1.067 (tests/test_orbits.cpp). Which one a release reaches
// depends on where it starts: the brute-force diagrams (validation/shaker_bifurcation) show only
// the one their start picks. The grid of starts at the section half a cycle after the orbit's
// impact, position from just above the table's highest point to 20 mm and velocity +-0.5 m/s,
// each classified by the attractor it settles on (simulation/orbits/basins.hpp, `hertzdash
// basins`), and the orbit itself by shooting, which must lie in its own basin.
//
// Writes: OUT/shaker_basins.csv (one row per start: position_m, velocity_mps, attractor 0 period 1,
// 1 at rest, 2 other, -1 inside the table), GENERATED/shaker_basins.tex (macros \shakerBasins...),
// GENERATED/shaker_basins_table.tex (the attractors and their shares); shaker_basins.gp draws the map.
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/model/wall_motion.hpp"
#include "hertzdash/simulation/orbits/basins.hpp"
#include "hertzdash/simulation/orbits/periodic_orbit.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"
#include "validation/common/latex_macros.hpp"
#include "validation/common/steel_rod_setups.hpp"
#include "validation/common/study_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <thread>

using namespace hertzdash;

namespace {

constexpr double e = 0.8, table_gamma = 0.8, frequency_Hz = 20;

ImpactSequenceSpec ball() {
  ShakerOptions o;
  o.wall = {.amplitude_m = shaker_amplitude_m(table_gamma, frequency_Hz, paper_steel_rod(e).gravity_mps2),
            .frequency_Hz = frequency_Hz};
  o.impact_model = ShakerImpactModel::instantaneous;
  return make_shaker_sequence(paper_steel_rod(e), "hongo-paper", {}, o).spec;
}

/// The study's classes: the period-1 orbit, the body at rest, anything else.
int study_class(const BasinAttractor& a) {
  if (a.kind == BasinAttractor::Kind::rest) return 1;
  return a.kind == BasinAttractor::Kind::periodic && a.period == 1 && a.impacts_per_period == 1 ? 0 : 2;
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const Parameters provenance{{"restitution", fmt::format("{}", e)}, {"gamma", fmt::format("{}", table_gamma)},
                              {"frequency_Hz", fmt::format("{}", frequency_Hz)}, {"impact_model", "instantaneous"}};
  // The orbit's impact phase theta*/(2 pi), cos theta* = Gamma_1/Gamma, and its apex half a cycle
  // later: y = A sin theta* + g T^2/8, u = 0.
  const double gamma_1 = std::numbers::pi * (1 - e) / (1 + e), theta = std::acos(gamma_1 / table_gamma);
  const double g = paper_steel_rod(e).gravity_mps2, T = 1 / frequency_Hz;
  const double A = shaker_amplitude_m(table_gamma, frequency_Hz, g);
  const double section_phase = std::fmod(theta / (2 * std::numbers::pi) + 0.5, 1.0);
  const Eigen::Vector2d scale(g * T * T, g * T), apex(A * std::sin(theta) + g * T * T / 8, 0);
  const PeriodicOrbit orbit = find_periodic_orbit(StroboscopicMap(ball(), section_phase, 1), apex, scale);
  if (!orbit.converged) throw std::runtime_error("no period-1 orbit: " + orbit.failure);

  const BasinOptions grid{.section_phase = section_phase, .position_min_m = 1.2 * A, .position_max_m = 0.02,
                          .velocity_min_mps = -0.5, .velocity_max_mps = 0.5, .resolution = args.reduced ? 24 : 96,
                          .threads = std::max(1u, std::thread::hardware_concurrency())};
  const auto start = std::chrono::steady_clock::now();
  const Basins basins = compute_basins(ball, grid);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  CsvWriter csv("hertzdash validation/shaker_basins: the attractor each start at the section reaches (0: the period-1 "
                "orbit, 1: at rest on the table, 2: another, -1: inside the table)",
                provenance, {"position_m", "velocity_mps", "attractor"});
  csv.add_comment(fmt::format("orbit: position {:.9g} m, velocity {:.9g} m/s", orbit.state(0), orbit.state(1)));
  const int n = grid.resolution;
  std::array<long, 3> cells{};
  int orbit_cell_class = -1;
  double nearest = INFINITY;
  for (int row = 0; row < n; ++row)
    for (int col = 0; col < n; ++col) {
      const int a = basins.cell[static_cast<std::size_t>(row * n + col)];
      const int cls = a < 0 ? -1 : study_class(basins.attractors[static_cast<std::size_t>(a)]);
      const double y = cell_centre(grid.position_min_m, grid.position_max_m, col, n);
      const double u = cell_centre(grid.velocity_min_mps, grid.velocity_max_mps, row, n);
      csv.add_row({y, u, static_cast<long>(cls)});
      if (cls >= 0) ++cells[static_cast<std::size_t>(cls)];
      const double distance = std::hypot((y - orbit.state(0)) / scale(0), (u - orbit.state(1)) / scale(1));
      if (distance < nearest) nearest = distance, orbit_cell_class = cls;
    }
  if (orbit_cell_class != 0) throw std::runtime_error("the orbit's own cell is not in its basin");
  if (cells[0] == 0 || cells[1] == 0) throw std::runtime_error("the two attractors do not both have a basin");

  const double total = static_cast<double>(n) * n;
  LatexMacros macros("validation/shaker_basins: the basins of the period-1 orbit and of rest", provenance);
  macros.add("shakerBasinsRestitution", e, "{:.1f}");
  macros.add("shakerBasinsGamma", table_gamma, "{:.1f}");
  macros.add("shakerBasinsResolution", n, "{:.0f}");
  macros.add("shakerBasinsOrbitPercent", 100 * static_cast<double>(cells[0]) / total, "{:.1f}");
  macros.add("shakerBasinsRestPercent", 100 * static_cast<double>(cells[1]) / total, "{:.1f}");
  macros.add("shakerBasinsOtherPercent", 100 * static_cast<double>(cells[2]) / total, "{:.1f}");
  macros.add("shakerBasinsSeconds", seconds, "{:.1f}");
  macros.add("shakerBasinsThreads", grid.threads, "{:.0f}");
  std::string table = "% Generated by validation/shaker_basins; do not edit.\n"
                      "\\begin{tabular}{lr}\n\\toprule\nattractor & starts (\\%) \\\\\n\\midrule\n";
  for (const BasinAttractor& a : basins.attractors)
    table += fmt::format("{} & {:.1f} \\\\\n", a.describe(), 100 * static_cast<double>(a.cells) / total);
  table += fmt::format("inside the table & {:.1f} \\\\\n", 100 * static_cast<double>(basins.inside_wall) / total);
  table += "\\bottomrule\n\\end{tabular}\n";
  return save_study_outputs(args, "shaker_basins", {{"shaker_basins.csv", csv}}, table, macros);
} catch (const std::exception& ex) {
  return study_failed(argv[0], ex);
}
