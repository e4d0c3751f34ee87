// Chung and Ooi's tests 5 and 6 with every tangential model, against the curves of both materials
// of each test: where do the models reproduce the benchmark, and where not?
//
// Why: the issue asks for tests 3-8 against their curves with their authors' tolerances. Kratos's
// own check of tests 5 and 6 compares only the gross-sliding points ("Sliding regime for the time
// being"), which follow closed forms every model meets; the branches where the contact sticks for
// part of the impact depend on the tangential model and on the material (its Poisson ratio sets
// the ratio of tangential to normal stiffness), and are what a user choosing a model wants to see.
//
// Runs (validation/common/chung_ooi_tests_5_6.hpp): test 5, a sphere striking a rigid flat at a
// normal speed of 5 m/s and a tangential speed V_st = x mu V_cn (steel and polyethylene, e = 1,
// undamped, mu = 0.3); test 6, a sphere spinning onto it at 0.2 m/s (aluminium alloy and nylon,
// e = 0.5 under tsuji-dem, mu = 0.4). For each curve and model: the run at each digitised
// abscissa (the errors), and on a grid of 40 abscissae (12 reduced) for the figure.
//
// Expected: on the gross-sliding branches (test 5 x >= 7, test 6 x < 1 and tan > 2.1) every model
// within Kratos's tolerance (tests/test_chung_ooi_oblique.cpp asserts it). Found: so; but on the
// sticking branches no model follows the curves. At small x the benchmark's test 5 reverses the
// contact point's tangential velocity (V_st'/V_st about -0.75 at x = 1), while every spring under
// one cone keeps its direction (V_st'/V_st between +0.3 and +0.7): their sticking oscillation over
// one contact (checked against an independent integration of Mindlin's no-slip spring,
// tests/test_oblique_impact.cpp) runs almost a whole period. Maw, Barber and Fawcett's theory
// (cattaneo-mindlin-mdr, Coulomb's law at every point) all but stops the contact point at x = 1
// and reverses it only beyond; it is the closest on test 5 (about 32 % over the steel recoil curve
// against 40 % for the best spring) and the farthest on test 6. Test 6's sticking branches lie
// above the curves by up to about 0.5 in beta (the linear spring least far). The whole-curve
// errors are tens of per cent: the benchmark's sticking branches come from none of these models.
//
// Writes OUT/chung_ooi_oblique.csv (curve, model, x, y), OUT/chung_ooi_oblique_reference.csv
// (curve, x, y), GENERATED/chung_ooi_oblique.tex (macros \chungOoiOblique...) and
// GENERATED/chung_ooi_oblique_table.tex (a row per curve: Kratos's tolerance, every model's
// error on the sliding branch at worst, and each model's error over the whole curve).
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/model/tangential/registry.hpp"
#include "validation/common/chung_ooi_tests_5_6.hpp"
#include "validation/common/latex_macros.hpp"
#include "validation/common/study_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <string_view>
#include <vector>

using namespace hertzdash;

namespace {

/// The curve's name in the CSVs and the figure: its file without ".dat".
std::string curve_name(const ChungOoiOblique& c) {
  const std::string file = c.file;
  return file.substr(0, file.size() - 4);
}

/// The figure's abscissae of curve c: n points spanning the digitised range (logarithmic for beta).
std::vector<double> grid(const ChungOoiOblique& c, const std::vector<std::array<double, 2>>& reference, int n) {
  const double lo = reference.front()[0], hi = reference.back()[0];
  const bool log_axis = c.test == 6 && !c.spin_axis;
  std::vector<double> xs;
  for (int i = 0; i < n; ++i) {
    const double f = static_cast<double>(i) / (n - 1);
    xs.push_back(log_axis ? lo * std::pow(hi / lo, f) : lo + (hi - lo) * f);
  }
  return xs;
}

/// The run's ordinate at x of curve c under `model`.
double value_at(const ChungOoiOblique& c, double x, const std::string& model) {
  const ObliqueImpactSpec s = chung_ooi_oblique_spec(c, x, model);
  const ObliqueImpactResult r = run_oblique_impact(s);
  if (!r.separated) throw std::runtime_error(fmt::format("{} with {} at x = {:g}: the sphere did not separate", c.file, model, x));
  return chung_ooi_oblique_value(c, x, s, r);
}

/// A row label: "5 steel, recoil".
std::string row_label(const ChungOoiOblique& c) {
  std::string material = std::string(c.row).substr(6);
  const char* what = c.test == 5 ? (c.spin_axis ? "spin" : "recoil") : (c.spin_axis ? "tangent" : "$\\beta$");
  return fmt::format("{} {}, {}", c.test, material, what);
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const int n = args.reduced ? 12 : 40;
  CsvWriter curves("hertzdash validation/chung_ooi_oblique: Chung and Ooi's tests 5 (e = 1, mu = 0.3) and 6 (e = 0.5 "
                   "under tsuji-dem, mu = 0.4) with every tangential model",
                   {{"tangential_models", registered_tangential_model_names(" ")}}, {"curve", "model", "x", "y"});
  CsvWriter reference("hertzdash validation/chung_ooi_oblique: the curves of tests 5 and 6 as digitised in Kratos's DEM "
                      "benchmarks (data/external/chung-ooi-2011/README.md)",
                      {}, {"curve", "x", "y", "gross_sliding"});
  std::string table =
      "\\setlength{\\tabcolsep}{3pt}\n\\begin{tabular}{lrr";  // eight columns in the text width
  for (std::size_t m = 0; m < registered_tangential_models.size(); ++m) table += "r";
  table += "}\n\\toprule\ncurve & Kratos & sliding";
  for (const TangentialModelInfo* model : registered_tangential_models) {  // two lines, broken after the first hyphen, for the width
    const std::string_view name = model->name;
    const std::size_t cut = name.find('-') + 1;  // 0 (one line) where there is none
    table += fmt::format(" & \\shortstack{{\\texttt{{{}}}\\\\\\texttt{{{}}}}}", name.substr(0, cut), name.substr(cut));
  }
  table += " \\\\\n\\midrule\n";

  double worst_sliding_ratio = 0, best_whole = INFINITY, worst_whole = 0;
  // Each curve's whole-curve error: the model resolved over the contact area's, and the best of the
  // springs under one cone.
  std::map<std::string, double> resolved_error, spring_best_error;
  for (const ChungOoiOblique& c : chung_ooi_oblique_curves) {
    const auto points = read_two_columns(chung_ooi_data_dir() / c.file);
    for (const auto& [x, y] : points) reference.add_row({curve_name(c), x, y, chung_ooi_oblique_gross_sliding(c, x) ? 1.0 : 0.0});
    double sliding_worst = 0;
    std::string errors;
    for (const TangentialModelInfo* info : registered_tangential_models) {
      const std::string model(info->name);
      // Kratos's relative L1 error over the gross-sliding points and over all.
      KratosL1Error sliding, all;
      for (const auto& [x, y] : points) {
        const double run = value_at(c, x, model);
        all.add(run, y);
        if (chung_ooi_oblique_gross_sliding(c, x)) sliding.add(run, y);
      }
      const double whole = all.value();
      sliding_worst = std::max(sliding_worst, sliding.value());
      best_whole = std::min(best_whole, whole);
      worst_whole = std::max(worst_whole, whole);
      errors += fmt::format(" & {:.0f}\\,\\%", 100 * whole);
      if (info->resolves_contact_area) resolved_error[c.file] = whole;
      else if (!spring_best_error.contains(c.file) || whole < spring_best_error[c.file]) spring_best_error[c.file] = whole;
      for (const double x : grid(c, points, n)) curves.add_row({curve_name(c), model, x, value_at(c, x, model)});
    }
    worst_sliding_ratio = std::max(worst_sliding_ratio, sliding_worst / c.kratos_tolerance);
    table += fmt::format("{} & {:.0f}\\,\\% & {:.1f}\\,\\%{} \\\\\n", row_label(c), 100 * c.kratos_tolerance, 100 * sliding_worst, errors);
  }
  table += "\\bottomrule\n\\end{tabular}\n";

  // The contact point's velocity after over before at test 5's steel point nearest x = 1: the
  // benchmark's and each model's (the header's finding).
  const ChungOoiOblique& recoil = chung_ooi_oblique_curve("test5_steel_rebound_slip.dat");
  const auto steel = read_two_columns(chung_ooi_data_dir() / recoil.file);
  const auto near_one = *std::min_element(steel.begin(), steel.end(), [](const auto& a, const auto& b) {
    return std::abs(a[0] - 1) < std::abs(b[0] - 1);
  });
  double model_lo = INFINITY, model_hi = -INFINITY, resolved_ratio = NAN;
  for (const TangentialModelInfo* info : registered_tangential_models) {
    const double ratio = value_at(recoil, near_one[0], std::string(info->name)) / near_one[0];  // e = 1: V_cn' = V_cn
    if (info->resolves_contact_area) resolved_ratio = ratio;
    else model_lo = std::min(model_lo, ratio), model_hi = std::max(model_hi, ratio);
  }
  const double benchmark_ratio = near_one[1] / near_one[0];
  std::printf("tests 5 and 6: sliding branches within %.2f of Kratos's tolerance at worst; whole curves %.0f to %.0f %%; "
              "at x = %.3g the benchmark's V_st'/V_st is %.3f, the springs' %.3f to %.3f, Coulomb's law at every point %.3f\n",
              worst_sliding_ratio, 100 * best_whole, 100 * worst_whole, near_one[0], benchmark_ratio, model_lo, model_hi,
              resolved_ratio);

  LatexMacros macros("validation/chung_ooi_oblique: Chung and Ooi's tests 5 and 6 with every tangential model", {});
  macros.add("chungOoiObliqueSlidingShare", worst_sliding_ratio, "{:.2f}");
  macros.add("chungOoiObliqueWholeBest", 100 * best_whole, "{:.0f}");
  macros.add("chungOoiObliqueWholeWorst", 100 * worst_whole, "{:.0f}");
  macros.add("chungOoiObliqueRatioX", near_one[0], "{:.2f}");
  macros.add("chungOoiObliqueRatioBenchmark", benchmark_ratio, "{:.2f}");
  macros.add("chungOoiObliqueRatioModelLow", model_lo, "{:.2f}");
  macros.add("chungOoiObliqueRatioModelHigh", model_hi, "{:.2f}");
  macros.add("chungOoiObliqueModels", static_cast<double>(registered_tangential_models.size()), "{:.0f}");
  macros.add("chungOoiObliqueRatioResolved", resolved_ratio, "{:.2f}");
  macros.add("chungOoiObliqueResolvedTestFive", 100 * resolved_error["test5_steel_rebound_slip.dat"], "{:.0f}");
  macros.add("chungOoiObliqueSpringTestFive", 100 * spring_best_error["test5_steel_rebound_slip.dat"], "{:.0f}");
  macros.add("chungOoiObliqueResolvedTestSix", 100 * resolved_error["test6_aluminium_slip_ratio.dat"], "{:.0f}");
  macros.add("chungOoiObliqueSpringTestSix", 100 * spring_best_error["test6_aluminium_slip_ratio.dat"], "{:.0f}");
  return save_study_outputs(args, "chung_ooi_oblique",
                            {{"chung_ooi_oblique.csv", curves}, {"chung_ooi_oblique_reference.csv", reference}}, table, macros);
} catch (const std::exception& ex) {
  return study_failed(argv[0], ex);
}
