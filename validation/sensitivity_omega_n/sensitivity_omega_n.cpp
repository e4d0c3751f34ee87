// Sensitivity of the paper's damping coefficient to its omega_n assumption.
//
// What it reproduces and why. Hongo et al. fix the dashpot of eq. (5),
// c_e = 2 K x^{1/2} zeta / omega_n, with one modelling choice, eqs. (7)-(11): the
// contact is an oscillator whose natural frequency omega_n follows from a peak
// deformation X estimated from the MEAN of the kinetic energies before and after
// impact. Nothing in the paper tests that choice. This study replaces it by the
// alternatives of OmegaNVariant (model/omega_n_variant.hpp):
//   paper, impact-energy, rebound-energy       closed forms, eqs. (9)-(10) with another energy;
//   self-consistent, contact-time              omega_n from the simulated impact itself,
//                                              iterated to a fixed point;
//   as-printed                                 the erratum of eq. (9) taken literally;
// and, independently, zeta by eq. (6) ("paper") or the exact linear-oscillator
// relation ("exact"). For each it simulates the drop test (CVODE, events located)
// and records what a user of the model would read off: the damping coefficient,
// the effective restitution, peak force, maximum deformation and contact time.
//
// Grids: for the steel rod and duralumin rod C, e from 0.1 to 0.99 at h = 20 mm
// (the paper's Figs. 5-6 height) and h from 2 to 100 mm at the rod's Table 2 e.
// --reduced keeps three points of each.
//
// Outputs (validation/sensitivity_omega_n/outputs.txt):
//   sensitivity_omega_n.csv             every run (nan where an iterated variant has no fixed point)
//   omega_n_restitution.csv             e_effective - e_input against e_input (figure)
//   omega_n_height.csv                  e_effective, peak force, contact time against h (figure)
//   omega_n_hysteresis.csv              force-deformation loops at h = 20 mm (figure)
//   ../generated/sensitivity_omega_n.tex        \sens... macros for the paper
//   ../generated/sensitivity_omega_n_table.tex  the h = 20 mm comparison table
#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/csv_writer.hpp"
#include "validation/common/latex_macros.hpp"
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/omega_n_fixed_point.hpp"
#include "hertzdash/simulation/sweep/parallel_sweep.hpp"
#include "validation/common/study_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <string>
#include <vector>

using namespace hertzdash;

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr std::array<ZetaForm, 2> zeta_forms{ZetaForm::paper, ZetaForm::exact};
const std::array<std::string, 2> rods{"steel", "duralumin-c"};
constexpr double paper_height_m = 0.020;

/// One run of the paper's law under one assumption: the columns of sensitivity_omega_n.csv.
struct Row {
  OmegaNVariant variant;
  ZetaForm zeta_form;
  std::string rod;
  double e_input, h_m;
  double omega_n_rad_per_s, c_e_coefficient;  ///< c_e = c_e_coefficient x^{1/2} [N s / m^{3/2}]
  double e_effective, peak_force_N, max_deformation_m, contact_time_s;
  int iterations;
  double contraction;  ///< last observed contraction factor of an iterated variant (0 for closed forms)
  bool ok;         ///< false: the iterated variant found no fixed point (values nan)
  bool separated;  ///< false: the rod came to rest on the ball (e_effective 0, contact time nan)
  std::string failure;  ///< why an iterated variant found no fixed point (empty if ok)
};

/// The study's solver: CVODE (Adams, rtol 1e-8, events located), results to ~1e-7 relative.
const SolverSettings study_solver{};

Row simulate(ImpactSimulator& solver, const PaperParameters& paper, OmegaNVariant variant, ZetaForm zeta,
             const std::string& rod, double e, double h, std::vector<TraceSample>* trace = nullptr) {
  DropTestSetup setup = paper_setup(paper, rod, h);
  setup.restitution = e;
  setup.damping.zeta_form = zeta;
  setup.damping.omega_n = variant;
  const double nan = not_a_number;
  Row row{variant, zeta, rod, e, h, nan, nan, nan, nan, nan, nan, 0, 0.0, false, false, {}};
  const OmegaNFixedPoint r = run_paper_law(solver, setup, {}, trace);
  row.iterations = r.iterations;
  row.contraction = r.contraction;
  row.ok = r.converged;
  if (!r.converged) {
    row.failure = fmt::format("no fixed point for {} zeta={} {} e={} h={}: {}", to_string(variant),
                              to_string(zeta), rod, e, h, r.failure);
    return row;
  }
  const double K = hertz_stiffness(setup);
  row.separated = r.summary.separated;
  row.omega_n_rad_per_s = r.omega_n_rad_per_s;
  row.c_e_coefficient = 2.0 * K * zeta_from_restitution(e, zeta) / r.omega_n_rad_per_s;  // eq. (5)
  row.e_effective = r.summary.e_effective;  // 0 if the rod came to rest on the ball
  row.peak_force_N = r.summary.peak_force_N;
  row.max_deformation_m = r.summary.max_deformation_m;
  row.contact_time_s = r.summary.separated ? r.summary.contact_time_s : nan;
  return row;
}

/// The omega_n [rad/s] at which the paper's law returns the input e (e_effective = e), by
/// bisection on ln omega_n: e_effective grows with omega_n (c_e ~ 1/omega_n). The law is run
/// with a prescribed omega_n through the hook of the iterated variants
/// (DampingSettings::omega_n_rad_per_s), without iterating.
double omega_n_reproducing_e(ImpactSimulator& solver, const PaperParameters& paper, const std::string& rod, double h) {
  DropTestSetup setup = paper_setup(paper, rod, h);
  setup.damping.omega_n = OmegaNVariant::self_consistent;  // only to prescribe omega_n
  const double e = setup.restitution;
  auto e_effective = [&](double w) {
    setup.damping.omega_n_rad_per_s = w;
    return solver.run<HongoPaper>(setup).e_effective;
  };
  const ImpactConditions c{hertz_stiffness(setup), setup.mass_kg, approach_speed(setup), e};
  double hi = paper_law_natural_frequency(c, DampingSettings{}), lo = 0.05 * hi;
  if (!(e_effective(hi) > e && e_effective(lo) < e)) return not_a_number;
  while (hi / lo - 1 > 1e-9) {
    const double mid = std::sqrt(lo * hi);
    (e_effective(mid) > e ? hi : lo) = mid;
  }
  return std::sqrt(lo * hi);
}

// Macro names are letters only: "self-consistent" -> "SelfConsistent".
std::string camel(const std::string& s) {
  std::string out;
  bool up = true;
  for (char c : s) {
    if (c == '-' || c == '_') { up = true; continue; }
    out += up ? static_cast<char>(std::toupper(static_cast<unsigned char>(c))) : c;
    up = false;
  }
  return out;
}
std::string rod_tag(const std::string& rod) { return rod == "steel" ? "Steel" : "DurC"; }

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const PaperParameters paper = load_paper_parameters();
  ImpactSimulator sim(study_solver);

  const std::vector<double> e_grid =
      args.reduced ? std::vector<double>{0.1, 0.5, 0.99}
                   : std::vector<double>{0.1, 0.15, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.85, 0.9, 0.95, 0.99};
  const std::vector<double> h_grid =
      args.reduced ? std::vector<double>{0.002, 0.02, 0.1}
                   : std::vector<double>{0.002, 0.003, 0.005, 0.007, 0.01, 0.015, 0.02, 0.03, 0.05, 0.07, 0.1};

  // ---- 1. Every run: the e sweep at h = 20 mm and the h sweep at the Table 2 e. ----
  //      The runs are independent: listed first, then run on all cores.
  struct Run {
    OmegaNVariant v;
    ZetaForm z;
    std::string rod;
    double e, h;
  };
  std::vector<Run> e_runs, h_runs;
  for (OmegaNVariant v : all_omega_n_variants)
    for (ZetaForm z : zeta_forms)
      for (const std::string& rod : rods) {
        for (double e : e_grid) e_runs.push_back({v, z, rod, e, paper_height_m});
        for (double h : h_grid) h_runs.push_back({v, z, rod, paper.rod(rod).restitution, h});
      }
  auto run_all = [&](const std::vector<Run>& runs, const std::string& label) {
    std::vector<Row> rows(runs.size());
    parallel_sweep(
        runs.size(), study_solver,
        [&](ImpactSimulator& solver, std::size_t i) {
          const Run& r = runs[i];
          rows[i] = simulate(solver, paper, r.v, r.z, r.rod, r.e, r.h);
        },
        {.label = label});
    for (const Row& row : rows)
      if (!row.failure.empty()) std::cerr << "  " << row.failure << "\n";
    return rows;
  };
  const std::vector<Row> e_sweep = run_all(e_runs, "omega_n e sweep"), h_sweep = run_all(h_runs, "omega_n h sweep");

  const Parameters params{{"rods", "steel, duralumin-c (Tables 1-3, data/assumptions.csv)"},
                          {"solver", "cvode adams rtol 1e-8 atol 1e-12, events located"},
                          {"e_sweep_height_m", fmt::format("{}", paper_height_m)},
                          {"h_sweep_restitution", "Table 2 value of each rod"},
                          {"reduced", args.reduced ? "true" : "false"}};
  CsvWriter all("omega_n sensitivity of the paper's law: every run (e sweep at h = 20 mm, then h sweep at the "
                "Table 2 e); nan = the iterated variant has no fixed point (see omega_n_fixed_point.hpp); "
                "e_effective 0 with contact_time_s nan = the rod came to rest on the ball; "
                "c_e_coefficient [N s/m^1.5] = 2 K zeta / omega_n",
                params,
                {"variant", "zeta_form", "rod", "e_input", "h_m", "c_e_coefficient", "e_effective", "peak_force_N",
                 "max_deformation_m", "contact_time_s"});
  for (const auto* sweep : {&e_sweep, &h_sweep})
    for (const Row& r : *sweep)
      all.add_row({to_string(r.variant), to_string(r.zeta_form), r.rod, r.e_input, r.h_m, r.c_e_coefficient,
                   r.e_effective, r.peak_force_N, r.max_deformation_m, r.contact_time_s});
  all.save(args.out_dir / "sensitivity_omega_n.csv");

  // ---- 2. Figure data. ----
  // Restitution: does any variant give back the e it was given? e_effective - e_input.
  CsvWriter restitution("e_effective - e_input against e_input at h = 20 mm (figure omega_n_restitution)", params,
                        {"variant", "zeta_form", "rod", "e_input", "e_deviation"});
  for (const Row& r : e_sweep)
    restitution.add_row({to_string(r.variant), to_string(r.zeta_form), r.rod, r.e_input, r.e_effective - r.e_input});
  restitution.save(args.out_dir / "omega_n_restitution.csv");

  // Height: the results relative to the paper's variant at the same h.
  std::map<std::tuple<std::string, std::string, double>, const Row*> paper_rows;
  for (const Row& r : h_sweep)
    if (r.variant == OmegaNVariant::paper) paper_rows[{to_string(r.zeta_form), r.rod, r.h_m}] = &r;
  CsvWriter height("e_effective, and peak force and contact time relative to the paper variant, against h at the "
                   "Table 2 e (figure omega_n_height)",
                   params,
                   {"variant", "zeta_form", "rod", "h_m", "e_effective", "peak_force_rel_paper",
                    "contact_time_rel_paper"});
  for (const Row& r : h_sweep) {
    const Row& p = *paper_rows.at({to_string(r.zeta_form), r.rod, r.h_m});
    height.add_row({to_string(r.variant), to_string(r.zeta_form), r.rod, r.h_m, r.e_effective,
                    r.peak_force_N / p.peak_force_N - 1.0, r.contact_time_s / p.contact_time_s - 1.0});
  }
  height.save(args.out_dir / "omega_n_height.csv");

  // Hysteresis loops at h = 20 mm, Table 2 e, zeta by eq. (6).
  CsvWriter loops("contact force against deformation at h = 20 mm, Table 2 e, zeta eq. (6) (figure "
                  "omega_n_hysteresis)",
                  params, {"variant", "rod", "x_m", "force_N"});
  for (const std::string& rod : rods)
    for (OmegaNVariant v : all_omega_n_variants) {
      std::vector<TraceSample> trace;
      simulate(sim, paper, v, ZetaForm::paper, rod, paper.rod(rod).restitution, paper_height_m, &trace);
      for (const TraceSample& t : trace) loops.add_row({to_string(v), rod, t.x_m, t.force_N});
    }
  loops.save(args.out_dir / "omega_n_hysteresis.csv");

  // ---- 3. Numbers for the paper. ----
  // (a) At h = 20 mm and the Table 2 e: each variant relative to the paper's.
  LatexMacros tex("omega_n sensitivity of the paper's law (validation/sensitivity_omega_n)", params);
  std::string table;
  for (const std::string& rod : rods) {
    const double e_table = paper.rod(rod).restitution;
    const Row base = simulate(sim, paper, OmegaNVariant::paper, ZetaForm::paper, rod, e_table, paper_height_m);
    const std::string rt = rod_tag(rod);
    tex.add("sens" + rt + "InputE", e_table, "{:.3f}");
    const double w_e = omega_n_reproducing_e(sim, paper, rod, paper_height_m);
    tex.add("sens" + rt + "OmegaNReproducingE", w_e, "{:.0f}");
    tex.add("sens" + rt + "OmegaNReproducingERelPct", 100.0 * (w_e / base.omega_n_rad_per_s - 1.0), "{:+.0f}");
    tex.add("sens" + rt + "CeReproducingERelPct", 100.0 * (base.omega_n_rad_per_s / w_e - 1.0), "{:+.0f}");
    table += fmt::format("\\midrule\n\\multicolumn{{8}}{{l}}{{{} rod, $e = {:.3f}$, $h = 20$\\,mm}}\\\\\n",
                         rod == "steel" ? "Steel" : "Duralumin C", e_table);
    for (OmegaNVariant v : all_omega_n_variants) {
      const Row r = simulate(sim, paper, v, ZetaForm::paper, rod, e_table, paper_height_m);
      const Row x = simulate(sim, paper, v, ZetaForm::exact, rod, e_table, paper_height_m);
      const std::string tag = "sens" + rt + camel(to_string(v));
      tex.add(tag + "OmegaN", r.omega_n_rad_per_s, "{:.0f}");
      tex.add(tag + "Ce", r.c_e_coefficient, "{:.0f}");
      tex.add(tag + "Eeff", r.e_effective, "{:.3f}");
      tex.add(tag + "EeffExact", x.e_effective, "{:.3f}");
      tex.add(tag + "CeRelPct", 100.0 * (r.c_e_coefficient / base.c_e_coefficient - 1.0), "{:+.1f}");
      tex.add(tag + "CeRatio", r.c_e_coefficient / base.c_e_coefficient, "{:.1f}");
      tex.add(tag + "PeakRelPct", 100.0 * (r.peak_force_N / base.peak_force_N - 1.0), "{:+.2f}");
      tex.add(tag + "ContactRelPct", 100.0 * (r.contact_time_s / base.contact_time_s - 1.0), "{:+.2f}");
      tex.add(tag + "XmaxRelPct", 100.0 * (r.max_deformation_m / base.max_deformation_m - 1.0), "{:+.2f}");
      table += fmt::format(
          "\\texttt{{{}}} & {:.0f} & {:.0f} & {:.3f} & {:.3f} & {:.1f} & {:.1f} & {:.3f}\\\\\n", to_string(v),
          r.omega_n_rad_per_s, r.c_e_coefficient, r.e_effective, x.e_effective, r.peak_force_N,
          1e6 * r.max_deformation_m, 1e3 * r.contact_time_s);
    }
  }
  // (a') The four physically motivated variants (all but as-printed) against the paper's, both
  // rods: the largest change of e_effective and the largest relative change of peak force,
  // maximum deformation and contact time.
  {
    double de = 0, rel = 0;
    for (const std::string& rod : rods) {
      const double e_table = paper.rod(rod).restitution;
      const Row base = simulate(sim, paper, OmegaNVariant::paper, ZetaForm::paper, rod, e_table, paper_height_m);
      for (OmegaNVariant v : all_omega_n_variants) {
        if (v == OmegaNVariant::as_printed) continue;
        const Row r = simulate(sim, paper, v, ZetaForm::paper, rod, e_table, paper_height_m);
        de = std::max(de, std::abs(r.e_effective - base.e_effective));
        for (double ratio : {r.peak_force_N / base.peak_force_N, r.max_deformation_m / base.max_deformation_m,
                             r.contact_time_s / base.contact_time_s})
          rel = std::max(rel, std::abs(ratio - 1.0));
      }
    }
    tex.add("sensPhysicalVariantsMaxEeffChange", de, "{:.3f}");
    tex.add("sensPhysicalVariantsMaxResultChangePct", 100.0 * rel, "{:.2f}");
  }
  // (b) Over the e grid at h = 20 mm: the largest |e_effective - e_input| of each variant and
  // zeta form (both rods), and where the iterated variants have a fixed point.
  for (OmegaNVariant v : all_omega_n_variants)
    for (ZetaForm z : zeta_forms) {
      double worst = 0, e_min_fixed = not_a_number, contraction = 0;
      int iterations = 0;
      for (const Row& r : e_sweep) {
        if (r.variant != v || r.zeta_form != z) continue;
        if (r.ok) {
          worst = std::max(worst, std::abs(r.e_effective - r.e_input));
          if (!(r.e_input >= e_min_fixed)) e_min_fixed = r.e_input;
          contraction = std::max(contraction, r.contraction);
          iterations = std::max(iterations, r.iterations);
        }
      }
      const std::string tag = "sens" + camel(to_string(v)) + "Zeta" + camel(to_string(z));
      tex.add(tag + "MaxEDev", worst, "{:.3f}");
      if (is_iterated(v)) {
        tex.add(tag + "MinEFixedPoint", e_min_fixed, "{:.2f}");
        tex.add(tag + "MaxContraction", contraction, "{:.2f}");
        tex.add(tag + "MaxIterations", iterations, "{:.0f}");
      }
    }
  // (b') Where a variant reproduces the input e on the e grid (steel, h = 20 mm, zeta eq. 6):
  // the sign change of e_effective - e, located by linear interpolation; "none" if there is none.
  for (OmegaNVariant v : all_omega_n_variants) {
    std::vector<const Row*> rows;
    for (const Row& r : e_sweep)
      if (r.variant == v && r.zeta_form == ZetaForm::paper && r.rod == "steel" && r.ok) rows.push_back(&r);
    std::string crossing = "none";
    for (std::size_t i = 1; i < rows.size(); ++i) {
      const double d0 = rows[i - 1]->e_effective - rows[i - 1]->e_input, d1 = rows[i]->e_effective - rows[i]->e_input;
      if ((d0 < 0) != (d1 < 0)) {
        const double e0 = rows[i - 1]->e_input, e1 = rows[i]->e_input;
        crossing = fmt::format("{:.2f}", e0 - d0 * (e1 - e0) / (d1 - d0));
        break;
      }
    }
    tex.add_text("sensSteel" + camel(to_string(v)) + "ReproducesEAt", crossing);
  }
  // (b'') The misprint: the largest e of the grid at which the steel rod does not separate.
  {
    double e_rest = not_a_number;
    for (const Row& r : e_sweep)
      if (r.variant == OmegaNVariant::as_printed && r.zeta_form == ZetaForm::paper && r.rod == "steel" && r.ok &&
          !r.separated && !(r.e_input <= e_rest))
        e_rest = r.e_input;
    tex.add("sensSteelAsPrintedNoSeparationMaxE", e_rest, "{:.2f}");
  }
  // (c) The h dependence: spread of e_effective over the h grid for the paper variant.
  for (const std::string& rod : rods) {
    double lo = 1, hi = 0;
    for (const Row& r : h_sweep)
      if (r.rod == rod && r.variant == OmegaNVariant::paper && r.zeta_form == ZetaForm::paper)
        lo = std::min(lo, r.e_effective), hi = std::max(hi, r.e_effective);
    tex.add("sens" + rod_tag(rod) + "PaperEeffSpreadOverH", hi - lo, "{:.1e}");
  }
  tex.add("sensFixedPointRtolExponent", std::log10(OmegaNFixedPointOptions{}.rtol), "{:.0f}");
  tex.add("sensEGridMin", e_grid.front(), "{:.2f}");
  tex.add("sensEGridMax", e_grid.back(), "{:.2f}");
  tex.add("sensHGridMinMm", 1e3 * h_grid.front(), "{:.0f}");
  tex.add("sensHGridMaxMm", 1e3 * h_grid.back(), "{:.0f}");
  tex.save(args.generated_dir / "sensitivity_omega_n.tex");

  std::string provenance = provenance_header("omega_n variants at h = 20 mm, zeta eq. (6) unless stated "
                                            "(validation/sensitivity_omega_n)", params);
  std::replace(provenance.begin(), provenance.end(), '#', '%');  // LaTeX comments
  const std::string header =
      provenance +
      "\\begin{tabular}{lrrrrrrr}\n\\toprule\n"
      "variant & $\\omega_n$ [rad/s] & $c_e/x^{1/2}$ [N\\,s/m$^{3/2}$] & $e_\\mathrm{eff}$ & "
      "$e_\\mathrm{eff}$ (exact $\\zeta$) & $P_\\mathrm{max}$ [N] & $x_\\mathrm{max}$ [$\\mu$m] & $t_c$ [ms]\\\\\n";
  write_file_atomically(args.generated_dir / "sensitivity_omega_n_table.tex",
                        header + table + "\\bottomrule\n\\end{tabular}\n");
  std::cout << fmt::format("sensitivity_omega_n: {} runs written to {}\n", e_sweep.size() + h_sweep.size(),
                           args.out_dir.string());
  return 0;
} catch (const std::exception& e) {
  return study_failed(argv[0], e);
}
