// Chung & Ooi's DEM benchmark tests 1, 2 and 3: the suite against curves published by others.
//
// Everywhere else the suite is checked against its own closed forms. Chung and Ooi (2011)
// proposed benchmark tests for discrete element codes, each with an analytical solution, and
// printed the solutions as curves; the Kratos DEM test suite distributes those curves digitised
// (data/external/chung-ooi-2011/README.md). Tests 1 and 2 are undamped Hertz impacts: two
// identical glass spheres meeting at 20 m/s, and an aluminium alloy sphere striking a rigid flat
// at 0.2 m/s. Along the line of centres each is the drop test's rigid-rod model with the
// benchmark's effective mass, effective radius and E*, no gravity
// (validation/common/chung_ooi_benchmark.hpp maps the benchmark's bodies onto the set-up's names:
// the moving "rod" carries m*, the "hemisphere" the sphere's radius R* and elastic constants, and
// the "rod's flat end" those of what the sphere strikes). We run it with the undamped law "none".
//
// Part 1, the closed forms (model/hertz.hpp). Energy gives the largest overlap
// x_max = (15 m* v^2 / (16 E* sqrt(R*)))^{2/5}, the peak force (4/3) E* sqrt(R*) x_max^{3/2} and
// the contact time (4/5) B(2/5, 1/2) x_max / v; Chung & Ooi write the last as
// 2.87 (m*^2 / (R* E*^2 v))^{1/5}, whose constant is the exact 2.868 rounded up. Expected: the
// simulation meets the closed forms to its tolerance (CVODE at rtol 1e-10: about 1e-9), far inside
// the 0.2-2 % by which the DEM codes Chung & Ooi compared are reported to miss them.
//
// Part 2, the digitised curves. Each digitised point against the closed-form Hertz curve: force
// against overlap F = (4/3) E* sqrt(R*) x^{3/2} (the files hold the loading branch), force
// against time K x(t)^{3/2} with x(t) from model/undamped_hertz_trajectory.hpp (the simulated
// curve drawn in the figure is this one to the accuracy of Part 1). Deviations in % of full
// scale, taken as the closed-form peak of each axis (x_max or t_c, F_max; the paper's axes reach
// at least that far, so this is the stricter reading of the README's "~1 % of full scale"):
// the vertical deviation at the digitised abscissa, and the distance to the curve in both
// columns at once, which is what a digitisation error in both columns moves
// (validation/common/chung_ooi_benchmark.hpp). Also the peak force, the largest overlap and the contact
// time read off the curves against ours.
//
// Part 3, test 3: restitution from 0 to 1. Chung & Ooi's test 3 drops an alumina sphere
// (R = 2.5 mm) onto a rigid flat at 3.9 m/s with input e = 0, 0.2, ..., 1 and asks the rebound
// speed over 3.9 m/s to be that e; the Kratos test accepts |e_eff - e| <= 1e-3. Here every
// registered law, tension allowed and clamped, is run at input e = 0.05, 0.06, ..., 1 (reduced:
// 0.05, 0.10, ..., 1) and at 0.01 and 0.001: the suite refuses e = 0 (valid range (0, 1]), so
// "what happens as e approaches 0" is read at 0.001, the smallest input the calibration
// (simulation/run/calibrate_restitution.hpp) searches. The verdict per law and tension rule is
// the largest |e_eff - e| over test 3's points 0.2, ..., 1 against the 1e-3.
// Expected: a law whose coefficients invert its own e_eff exactly passes (with tension allowed,
// kelvin-voigt by the linear oscillator's closed form and tsuji-dem by the change of variable
// that makes it one; kuwabara-kono and lee-herrmann, calibrated at the impact speed, either way);
// the laws built on approximations (e close to 1, fitted formulas) miss by far more than 1e-3
// at e = 0.2; at e = 1 every law is undamped Hertz.
// Every law builds its coefficients from (e, v0, K, m) alone, so e_eff depends on e alone
// (validation/damping_laws): the map is also computed in the paper's steel contact phase
// (h = 20 mm), where mass, stiffness and speed all differ, and the two must agree to the
// solver's accuracy.
//
// Writes OUT/chung_ooi_force_model.csv (the simulated contacts), OUT/chung_ooi_force_overlap.csv
// and OUT/chung_ooi_force_time.csv (the digitised points with the closed form and their
// deviations), OUT/chung_ooi_restitution.csv (the map), GENERATED/chung_ooi.tex (macros \co...),
// GENERATED/chung_ooi_table.tex, GENERATED/chung_ooi_curves_table.tex and
// GENERATED/chung_ooi_test3_table.tex. Prints the numbers.
#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/csv_writer.hpp"
#include "validation/common/latex_macros.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/undamped_hertz_trajectory.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "validation/common/chung_ooi_benchmark.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/calibrate_restitution.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"
#include "hertzdash/simulation/sweep/parallel_sweep.hpp"
#include "validation/common/study_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

using namespace hertzdash;

namespace {

// data/external/chung-ooi-2011/README.md: digitisation adds ~1 % of full scale in both columns.
constexpr double digitisation_uncertainty_pct = 1.0;
// The agreement the DEM codes compared by Chung & Ooi (2011) reach with the analytical solutions,
// as issue #16 reports it: 0.2 to 2 %.
constexpr double peer_low_pct = 0.2, peer_high_pct = 2.0;
// The contact-time constant as Chung & Ooi print it, 2.87 (m*^2 / (R* E*^2 v))^{1/5}.
constexpr double printed_contact_time_constant = 2.87;

// "test1" -> "TestOne": macro names are letters only.
std::string tag(const std::string& test) { return test == "test1" ? "TestOne" : test == "test2" ? "TestTwo" : "Test"; }

// Test 1 or 2 for tables and labels.
std::string label(const std::string& test) { return "Test " + test.substr(4); }

struct Quantity {
  std::string name;      // for tables
  std::string macro;     // macro stem
  double scale;          // SI -> printed unit
  int decimals;          // printed decimals
  double closed_form, simulated;
  double digitised;      // read off the curves (SI)
};

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  // Tests 1 and 2 have force curves (Parts 1 and 2); test 3 is Part 3.
  const std::vector<ChungOoiTest> tests{chung_ooi_row("test1"), chung_ooi_row("test2")};
  const std::filesystem::path data = chung_ooi_data_dir();

  Parameters common{{"benchmark", "Chung & Ooi 2011 tests 1, 2 and 3 (data/external/chung-ooi-2011)"},
                    {"digitisation_uncertainty_pct_full_scale", fmt::format("{}", digitisation_uncertainty_pct)},
                    {"full_scale", "closed-form x_max or t_c and F_max of each test"}};
  // CVODE at rtol 1e-10, atol 1e-10 of each state component's scale (x_max, v); steps of at
  // most t_c / 400 so that the recorded contact draws a smooth curve.
  auto solver_for = [](const UndampedHertzImpact& exact) {
    SolverSettings solver;
    solver.rtol = 1e-10;
    solver.atol = 1e-10;
    solver.max_step_s = exact.contact_time_s / 400;
    return solver;
  };
  auto closed_form = [](const DropTestSetup& s) {
    return undamped_hertz_impact(hertz_stiffness(s), s.mass_kg, *s.impact_velocity_mps);
  };
  Parameters params = common;
  for (const ChungOoiTest& test : tests) {
    const DropTestSetup s = chung_ooi_setup(test);
    for (const auto& [name, value] : describe_run(s, "none", solver_for(closed_form(s))))
      params.emplace_back(test.name + "." + name, value);
  }
  // Test 3 (Part 3) runs every registered law at CVODE rtol = atol = 1e-10.
  SolverSettings map_solver;
  map_solver.rtol = 1e-10;
  map_solver.atol = 1e-10;
  for (const auto& [name, value] : describe_run(chung_ooi_setup(chung_ooi_row("test3")), "all registered laws", map_solver))
    params.emplace_back("test3." + name, value);
  LatexMacros macros("chung_ooi: Chung & Ooi (2011) benchmark tests 1, 2 and 3", params);
  CsvWriter model_csv("chung_ooi: simulated undamped Hertz contact of Chung & Ooi tests 1 and 2 (law none)", params,
                      {"test", "t_s", "x_m", "force_N"});
  CsvWriter overlap_csv("chung_ooi: digitised force against overlap (Chung & Ooi 2011) and the closed-form Hertz force",
                        common, {"test", "x_m", "force_N", "hertz_force_N", "vertical_pct", "distance_pct"});
  CsvWriter time_csv("chung_ooi: digitised force against time (Chung & Ooi 2011) and the closed-form Hertz force", common,
                     {"test", "t_s", "force_N", "hertz_force_N", "vertical_pct", "distance_pct"});

  std::string table =
      "\\begin{tabular}{llrrcrr}\n\\toprule\n"
      "& & closed & \\multicolumn{2}{c}{simulation} & \\multicolumn{2}{c}{digitised curves} \\\\\n"
      "\\cmidrule(lr){4-5}\\cmidrule(lr){6-7}\n"
      "& & form & value & rel.\\ difference & read & vs closed form \\\\\n\\midrule\n";
  std::string curves_table =
      "\\begin{tabular}{lrrrrrr}\n\\toprule\n"
      "& & \\multicolumn{2}{c}{vertical} & \\multicolumn{2}{c}{distance} & beyond \\\\\n"
      "\\cmidrule(lr){3-4}\\cmidrule(lr){5-6}\n"
      "curve & points & max & RMS & max & RMS & " +
      fmt::format("{:g}", digitisation_uncertainty_pct) + "\\,\\% vertically \\\\\n\\midrule\n";

  double max_relative_error = 0, max_vertical = 0, max_distance = 0, max_peak_departure = 0;
  int points = 0, vertical_over = 0, distance_over = 0;
  for (const ChungOoiTest& test : tests) {
    // ---- Part 1: the simulation against the closed forms ---------------------------------
    const DropTestSetup setup = chung_ooi_setup(test);
    const double K = hertz_stiffness(setup), m = setup.mass_kg, v = test.relative_speed_mps;
    const UndampedHertzImpact exact = closed_form(setup);
    const double E_star = 3 * K / (4 * std::sqrt(test.effective_radius_m));
    std::vector<TraceSample> trace;
    const ImpactSummary s = ImpactSimulator(solver_for(exact)).run(setup, "none", &trace);
    double drawn_departure = 0;  // the drawn curve against the closed form F(t), % of F_max
    for (const TraceSample& p : trace) {
      const double t = p.t_s - s.t_onset_s;
      model_csv.add_row({test.name, t, p.x_m, p.force_N});
      const double x = undamped_hertz_state_at(K, m, v, std::clamp(t, 0.0, exact.contact_time_s)).x_m;
      drawn_departure = std::max(drawn_departure, 100 * std::abs(p.force_N - K * x * std::sqrt(x)) / exact.peak_force_N);
    }
    const double printed_tc =
        printed_contact_time_constant *
        std::pow(m * m / (test.effective_radius_m * E_star * E_star * v), 0.2);

    // ---- Part 2: the digitised curves -----------------------------------------------------
    const std::vector<CurvePoint> by_overlap = read_digitised_curve(data / (test.name + "_force_displacement.dat"));
    const std::vector<CurvePoint> by_time = read_digitised_curve(data / (test.name + "_force_time.dat"));
    auto hertz_force = [&](double x) { return x <= 0 ? 0.0 : K * x * std::sqrt(x); };
    auto hertz_force_at = [&](double t) {
      if (t <= 0 || t >= exact.contact_time_s) return 0.0;
      return hertz_force(undamped_hertz_state_at(K, m, v, t).x_m);
    };
    const CurveDeviation dev_overlap =
        curve_deviation(by_overlap, hertz_force, 0.0, exact.max_deformation_m, exact.max_deformation_m,
                        exact.peak_force_N, digitisation_uncertainty_pct);
    const CurveDeviation dev_time = curve_deviation(by_time, hertz_force_at, 0.0, exact.contact_time_s,
                                                    exact.contact_time_s, exact.peak_force_N, digitisation_uncertainty_pct);
    for (std::size_t i = 0; i < by_overlap.size(); ++i)
      overlap_csv.add_row({test.name, by_overlap[i].abscissa, by_overlap[i].force_N, hertz_force(by_overlap[i].abscissa),
                           dev_overlap.vertical_pct[i], dev_overlap.distance_pct[i]});
    for (std::size_t i = 0; i < by_time.size(); ++i)
      time_csv.add_row({test.name, by_time[i].abscissa, by_time[i].force_N, hertz_force_at(by_time[i].abscissa),
                        dev_time.vertical_pct[i], dev_time.distance_pct[i]});

    // What the curves say of the three quantities: the largest digitised force (force-time
    // curve), the largest digitised overlap (its loading branch may stop short of the peak) and
    // the span of the force-time curve, whose first and last points lie on F = 0.
    double digitised_peak = 0, digitised_overlap = 0;
    for (const CurvePoint& p : by_time) digitised_peak = std::max(digitised_peak, p.force_N);
    for (const CurvePoint& p : by_overlap) digitised_overlap = std::max(digitised_overlap, p.abscissa);
    const double digitised_tc = by_time.back().abscissa - by_time.front().abscissa;

    const std::array<Quantity, 3> quantities{{
        {"peak force (kN)", "PeakForce", 1e-3, 3, exact.peak_force_N, s.peak_force_N, digitised_peak},
        {"largest overlap ($\\mu$m)", "MaxOverlap", 1e6, 2, exact.max_deformation_m, s.max_deformation_m, digitised_overlap},
        {"contact time ($\\mu$s)", "ContactTime", 1e6, 2, exact.contact_time_s, s.contact_time_s, digitised_tc},
    }};
    const std::string T = tag(test.name);
    std::cout << fmt::format("{} ({}), K = {:.6g} N/m^1.5, E* = {:.6g} Pa, {} steps\n", label(test.name),
                             test.description, K, E_star, s.work.steps);
    for (std::size_t q = 0; q < quantities.size(); ++q) {
      const Quantity& Q = quantities[q];
      const double rel = std::abs(Q.simulated / Q.closed_form - 1);
      const double digitised_pct = 100 * (Q.digitised / Q.closed_form - 1);
      max_relative_error = std::max(max_relative_error, rel);
      if (q != 1) max_peak_departure = std::max(max_peak_departure, std::abs(digitised_pct));  // overlap: see caption
      const std::string closed = fmt::format("{:.{}f}", Q.closed_form * Q.scale, Q.decimals);
      const std::string digitised = fmt::format("{:.{}f}", Q.digitised * Q.scale, Q.decimals);
      macros.add_text("co" + T + Q.macro, closed);
      macros.add_text("co" + T + Q.macro + "RelError", latex_scientific(rel));
      macros.add_text("co" + T + Q.macro + "Digitised", digitised);
      macros.add("co" + T + Q.macro + "DigitisedPct", digitised_pct, "{:+.2f}");
      table += fmt::format("{} & {} & {} & {:.{}f} & {} & {} & ${:+.2f}$\\,\\% \\\\\n", q == 0 ? label(test.name) : "",
                           Q.name, closed, Q.simulated * Q.scale, Q.decimals, latex_scientific(rel), digitised,
                           digitised_pct);
      std::cout << fmt::format("  {:16} closed form {:.8g}  simulated {:.8g}  rel. diff {:.2e}  digitised {} ({:+.2f} %)\n",
                               Q.macro, Q.closed_form * Q.scale, Q.simulated * Q.scale, rel, digitised, digitised_pct);
    }
    if (&test != &tests.back()) table += "\\addlinespace\n";
    std::cout << fmt::format("  contact time with the printed constant 2.87: {:.5g} us; drawn curve within {:.2g} % of F_max\n",
                             printed_tc * 1e6, drawn_departure);
    macros.add("co" + T + "PrintedContactTime", printed_tc * 1e6, "{:.4g}");
    macros.add_text("co" + T + "DrawnDeparturePct", latex_scientific(drawn_departure));
    macros.add("co" + T + "EStarGPa", E_star * 1e-9, "{:.4g}");
    macros.add("co" + T + "EGPa", test.sphere.E_Pa * 1e-9, "{:.4g}");
    macros.add("co" + T + "Nu", test.sphere.nu, "{:.2f}");
    macros.add("co" + T + "Density", test.density_kgpm3, "{:.0f}");
    macros.add("co" + T + "RadiusMM", test.radius_m * 1e3, "{:.4g}");
    macros.add("co" + T + "EffectiveRadiusMM", test.effective_radius_m * 1e3, "{:.4g}");
    macros.add("co" + T + "EffectiveMassKg", test.effective_mass_kg, "{:.4g}");
    macros.add("co" + T + "Speed", v, "{:.3g}");
    macros.add("co" + T + "Steps", static_cast<double>(s.work.steps), "{:.0f}");

    for (const auto& [curve, dev] : {std::pair{"overlap", &dev_overlap}, std::pair{"time", &dev_time}}) {
      const std::string C = std::string(curve) == "overlap" ? "Overlap" : "Time";
      curves_table += fmt::format("{}, force--{} & {} & {:.2f} & {:.2f} & {:.2f} & {:.2f} & {} \\\\\n", label(test.name),
                                  curve, dev->points, dev->max_vertical_pct, dev->rms_vertical_pct, dev->max_distance_pct,
                                  dev->rms_distance_pct, dev->vertical_over);
      macros.add("co" + T + C + "MaxVerticalPct", dev->max_vertical_pct, "{:.2f}");
      macros.add("co" + T + C + "MaxDistancePct", dev->max_distance_pct, "{:.2f}");
      macros.add("co" + T + C + "VerticalOver", dev->vertical_over, "{:.0f}");
      std::cout << fmt::format("  force-{:8} {:2} points: vertical max {:.2f} % RMS {:.2f} %, distance max {:.2f} % RMS {:.2f} %"
                               " (% of full scale); {} beyond {} % vertically, {} by distance\n",
                               curve, dev->points, dev->max_vertical_pct, dev->rms_vertical_pct, dev->max_distance_pct,
                               dev->rms_distance_pct, dev->vertical_over, digitisation_uncertainty_pct, dev->distance_over);
      max_vertical = std::max(max_vertical, dev->max_vertical_pct);
      max_distance = std::max(max_distance, dev->max_distance_pct);
      points += dev->points;
      vertical_over += dev->vertical_over;
      distance_over += dev->distance_over;
    }
  }
  table += "\\bottomrule\n\\end{tabular}\n";
  curves_table += "\\bottomrule\n\\end{tabular}\n";
  macros.add_text("coMaxRelError", latex_scientific(max_relative_error));
  macros.add("coDigitisationUncertaintyPct", digitisation_uncertainty_pct, "{:g}");
  macros.add("coPeerLowPct", peer_low_pct, "{:g}");
  macros.add("coPeerHighPct", peer_high_pct, "{:g}");
  macros.add("coPrintedContactTimeConstant", printed_contact_time_constant, "{:.2f}");
  macros.add("coExactContactTimeConstant", 0.8 * std::pow(15.0 / 16, 0.4) * std::tgamma(0.4) * std::tgamma(0.5) /
                                                  std::tgamma(0.9), "{:.4f}");
  macros.add("coMaxVerticalPct", max_vertical, "{:.2f}");
  macros.add("coMaxDistancePct", max_distance, "{:.2f}");
  macros.add("coPointCount", points, "{:.0f}");
  macros.add("coVerticalOver", vertical_over, "{:.0f}");
  macros.add("coDistanceOver", distance_over, "{:.0f}");
  macros.add("coMaxPeakDeparturePct", max_peak_departure, "{:.2f}");
  model_csv.save(args.out_dir / "chung_ooi_force_model.csv");
  overlap_csv.save(args.out_dir / "chung_ooi_force_overlap.csv");
  time_csv.save(args.out_dir / "chung_ooi_force_time.csv");

  // ---- Part 3: test 3, restitution from 0 to 1 ----------------------------------------------
  // Every law, tension allowed and clamped, in test 3's set-up and in the paper's steel contact
  // phase (h = 20 mm), at CVODE rtol 1e-10 and atol 1e-10 of each state component's scale.
  const ChungOoiTest test3 = chung_ooi_row("test3");
  const std::array<DropTestSetup, 2> map_setups{
      chung_ooi_setup(test3), contact_phase_setup(paper_setup(load_paper_parameters(), "steel", 0.02))};
  // Kratos's delta in Chung_Ooi_test_3.py; its points 0.2, ..., 1 (and 0, which the suite refuses).
  constexpr double test3_tolerance = 1e-3;
  constexpr std::array<int, 5> test3_points_percent{20, 40, 60, 80, 100};
  const int stride = args.reduced ? 5 : 1;  // in hundredths
  std::vector<double> e_grid{calibration_e_min, 0.01};
  std::vector<std::size_t> test3_index;  // of test 3's points in e_grid
  for (int percent = 5; percent <= 100; percent += stride) {
    if (std::find(test3_points_percent.begin(), test3_points_percent.end(), percent) != test3_points_percent.end())
      test3_index.push_back(e_grid.size());
    e_grid.push_back(percent / 100.0);
  }
  const std::vector<LawInfo> laws = registered_laws();
  const std::size_t n_e = e_grid.size();
  // Index i = ((law * 2 + clamped) * n_e + k) * 2 + set-up.
  std::vector<double> e_eff(laws.size() * 2 * n_e * 2);
  parallel_sweep(
      e_eff.size(), map_solver,
      [&](ImpactSimulator& sim, std::size_t i) {
        DropTestSetup s = map_setups[i % 2];
        s.restitution = e_grid[i / 2 % n_e];
        s.no_tension = i / (2 * n_e) % 2 == 1;
        e_eff[i] = sim.run(s, laws[i / (4 * n_e)].name).e_effective;
      },
      {.label = "restitution map"});
  auto effective = [&](std::size_t law, bool clamped, std::size_t k) {
    return e_eff[((law * 2 + (clamped ? 1 : 0)) * n_e + k) * 2];
  };
  Parameters map_params = describe_run(map_setups[0], "all registered laws", map_solver);
  map_params.emplace_back("e_grid", fmt::format("0.001, 0.01 and {} points from 0.05 to 1", n_e - 2));
  map_params.emplace_back("e_effective_paper_setup", "the same law and e in the paper's steel contact phase (h = 20 mm)");
  CsvWriter map_csv("chung_ooi: effective against input restitution of every law, Chung & Ooi test 3", map_params,
                    {"model", "tension", "e_input", "e_effective", "e_effective_paper_setup"});
  double max_map_difference = 0, max_deviation_at_one = 0;
  for (std::size_t i = 0; i < e_eff.size(); i += 2) {
    const std::size_t k = i / 2 % n_e;
    const bool clamped = i / (2 * n_e) % 2 == 1;
    map_csv.add_row({std::string(laws[i / (4 * n_e)].name), std::string(clamped ? "clamped" : "allowed"), e_grid[k],
                     e_eff[i], e_eff[i + 1]});
    max_map_difference = std::max(max_map_difference, std::abs(e_eff[i] - e_eff[i + 1]));
    if (k + 1 == n_e) max_deviation_at_one = std::max(max_deviation_at_one, std::abs(e_eff[i] - 1));
  }
  map_csv.save(args.out_dir / "chung_ooi_restitution.csv");

  // The verdict: each law's largest |e_eff - e| over test 3's points, and e_eff at e = 0.001.
  std::string test3_table =
      "\\begin{tabular}{lrrrr}\n\\toprule\n"
      "& \\multicolumn{2}{c}{$\\max|\\eeff - e|$ at $e = 0.2, \\dots, 1$} & \\multicolumn{2}{c}{$\\eeff$ at $e = " +
      fmt::format("{:g}", calibration_e_min) +
      "$} \\\\\n\\cmidrule(lr){2-3}\\cmidrule(lr){4-5}\n"
      "law & tension allowed & clamped & allowed & clamped \\\\\n\\midrule\n";
  int passing[2] = {0, 0};
  std::cout << fmt::format("Test 3 (alumina, R = {} mm, {} m/s): largest |e_eff - e| at e = 0.2, ..., 1 against {:g}; "
                           "e_eff at e = {:g}\n",
                           test3.radius_m * 1e3, test3.relative_speed_mps, test3_tolerance, calibration_e_min);
  for (std::size_t law = 0; law < laws.size(); ++law) {
    if (laws[law].name == "none") continue;  // ignores e: not a restitution model
    double worst[2] = {0, 0};
    for (const bool clamped : {false, true})
      for (const std::size_t k : test3_index)
        worst[clamped] = std::max(worst[clamped], std::abs(effective(law, clamped, k) - e_grid[k]));
    auto verdict = [&](double d) {
      return d <= test3_tolerance ? "{\\boldmath " + latex_scientific(d) + "}" : latex_scientific(d);
    };
    // e_eff = 0: the run ended with the sphere at rest on the flat (the tensile dashpot holds it).
    auto near_zero = [&](bool clamped) {
      const double e = effective(law, clamped, 0);
      return e == 0 ? std::string("rests") : fmt::format("{:.3g}", e);
    };
    test3_table += fmt::format("{} & {} & {} & {} & {} \\\\\n", laws[law].name, verdict(worst[0]), verdict(worst[1]),
                               near_zero(false), near_zero(true));
    for (const bool clamped : {false, true}) passing[clamped] += worst[clamped] <= test3_tolerance ? 1 : 0;
    std::cout << fmt::format("  {:20} allowed {:9.2e}{}  clamped {:9.2e}{}   e_eff(0.001) allowed {:.4f} clamped {:.4f}\n",
                             laws[law].name, worst[0], worst[0] <= test3_tolerance ? " pass" : "     ", worst[1],
                             worst[1] <= test3_tolerance ? " pass" : "     ", effective(law, false, 0),
                             effective(law, true, 0));
  }
  test3_table += "\\bottomrule\n\\end{tabular}\n";
  std::cout << fmt::format("Test 3's map against the paper's steel contact: largest difference {:.2g}; largest |e_eff - 1| "
                           "at e = 1: {:.2g}\n",
                           max_map_difference, max_deviation_at_one);
  macros.add("coMapLawCount", static_cast<double>(laws.size()), "{:.0f}");
  macros.add("coMapGridPoints", static_cast<double>(n_e), "{:.0f}");
  macros.add_text("coMapMaxDifference", latex_scientific(max_map_difference));
  macros.add_text("coMapMaxDeviationAtOne", latex_scientific(max_deviation_at_one));
  macros.add_text("coTestThreeTolerance", latex_scientific(test3_tolerance));
  macros.add("coTestThreeEMin", calibration_e_min, "{:g}");
  macros.add("coTestThreePassAllowed", passing[0], "{:.0f}");
  macros.add("coTestThreePassClamped", passing[1], "{:.0f}");
  macros.add("coTestThreeRadiusMM", test3.radius_m * 1e3, "{:.4g}");
  macros.add("coTestThreeSpeed", test3.relative_speed_mps, "{:.3g}");
  macros.add("coTestThreeEGPa", test3.sphere.E_Pa * 1e-9, "{:.4g}");

  macros.save(args.generated_dir / "chung_ooi.tex");
  const std::string header = [&] {
    std::string h = provenance_header("chung_ooi: Chung & Ooi (2011) tests 1, 2 and 3", params);
    std::replace(h.begin(), h.end(), '#', '%');
    return h;
  }();
  write_file_atomically(args.generated_dir / "chung_ooi_table.tex", header + table);
  write_file_atomically(args.generated_dir / "chung_ooi_curves_table.tex", header + curves_table);
  write_file_atomically(args.generated_dir / "chung_ooi_test3_table.tex", header + test3_table);
  return 0;
} catch (const std::exception& e) {
  return study_failed(argv[0], e);
}
