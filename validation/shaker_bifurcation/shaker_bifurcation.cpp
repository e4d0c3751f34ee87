// The impact system the model was built for: where does a finite contact time change the
// bouncing ball's bifurcation diagram?
//
// A body on a wall vibrating as s(t) = A sin(2 pi f t), Gamma = A (2 pi f)^2 / g
// (simulation/shaker/shaker.hpp, docs/shaker.md). The textbook analysis treats each impact as
// instantaneous, relative rebound speed = e times the relative impact speed; its period-1 orbit
// has cos theta* = pi (1 - e)/(Gamma (1 + e)) and loses stability by period doubling at
//   Gamma_2(e)^2 = (pi (1 - e)/(1 + e))^2 + (2 (1 + e^2)/(1 + e)^2)^2
// (Holmes, J. Sound Vib. 84 (1982) 173; Luck and Mehta, Phys. Rev. E 48 (1993) 3988; derived in
// tests/test_shaker.cpp). The paper's contact (hongo) and the viscoelastic law (kuwabara-kono,
// calibrated at the period-1 orbit's impact speed g T/(1 + e)) take a time t_c per impact during
// which the wall keeps moving. This study asks:
//  1. The bifurcation diagrams (impact phase against Gamma) of the map and of both soft contacts,
//     for a stiff pair (the paper's steel rod on a steel hemisphere, t_c/T below 1 %) and for the
//     paper's soft pair (the steel rod on the nylon hemisphere, t_c/T a few %). Each soft law is
//     drawn beside the map with e = that law's own e_effective on its period-1 orbit (not the
//     input e: the paper's law's e_effective differs from its input e, and gravity and the wall's
//     acceleration during the contact change the rebound).
//  2. The period-doubling threshold of each soft contact against Gamma_2 of its own e_effective:
//     for the stiff pair with both moduli stiffened 1, 10 and 100 times (t_c ~ E^{-2/5}), the
//     difference must shrink as O(t_c/T), a factor 10^{-2/5} = 0.40 per decade; for the nylon
//     pair, by how much the threshold moves, against t_c/T.
// Threshold of a soft contact: the first Gamma of a scan (step dG = 0.01) with period 2 brackets
// it within dG; past a flip bifurcation the period-2 orbit's phase split d obeys
// d^2 = c (Gamma - Gamma_2) + O((Gamma - Gamma_2)^2), so the line through d^2 at two Gammas above
// (G_c + dG/2, G_c + 2 dG) crosses zero at Gamma_2 up to O(dG^2) (tests/test_shaker.cpp uses
// the same construction and finds the map's closed form within 2e-4).
//
// Writes: OUT/shaker_bifurcation_steel.csv, OUT/shaker_bifurcation_nylon.csv (model, law, gamma and the
// kept impacts; shaker_bifurcation.gp), GENERATED/shaker_bifurcation_table.tex (the thresholds)
// and GENERATED/shaker_bifurcation.tex (macros \shaker...).
#include "hertzdash/io/csv_writer.hpp"
#include "validation/common/latex_macros.hpp"
#include "hertzdash/model/wall_motion.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"
#include "hertzdash/simulation/sweep/parallel_sweep.hpp"
#include "validation/common/study_args.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <ctime>
#include <iostream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

using namespace hertzdash;

namespace {

constexpr double input_e = 0.5;      // every law's input restitution
constexpr double frequency_Hz = 20;  // T = 0.05 s
constexpr double gamma_from = 1.2, gamma_to = 2.0, gamma_step = 0.01;
const char* const viscoelastic = "kuwabara-kono";

double gamma_1(double e) { return std::numbers::pi * (1 - e) / (1 + e); }
double gamma_2(double e) { return std::hypot(gamma_1(e), 2 * (1 + e * e) / ((1 + e) * (1 + e))); }
/// The threshold of the map whose rebound R(W) depends on the impact speed W: e = R/W on the
/// orbit, eps = dR/dW there. The linearisation of tests/test_shaker.cpp with du_{n+1} taking
/// eps instead of e where it differentiates the rebound: J = [[1, T/W], [(1 + eps) a,
/// (1 + eps) a T/W + eps e]], W = g T/(1 + e), det = eps e, trace = 1 + eps e + (1 + eps)(1 + e) a/g;
/// 1 + trace + det = 0 gives Gamma sin theta* = 2 (1 + eps e)/((1 + eps)(1 + e)), so
/// Gamma_2(e, eps)^2 = (pi (1 - e)/(1 + e))^2 + (2 (1 + eps e)/((1 + eps)(1 + e)))^2 (eps = e:
/// gamma_2(e)). A restitution falling with the speed (eps < e) raises the threshold.
double gamma_2(double e, double eps) {
  return std::hypot(gamma_1(e), 2 * (1 + eps * e) / ((1 + eps) * (1 + e)));
}

SolverSettings solver() {
  SolverSettings s;
  s.integrator = IntegratorKind::gbs8_regularized;
  s.rtol = 1e-8;
  s.atol = 1e-8;  // of the regularised scales X^{1/2}, v0, t_H
  return s;
}

/// The paper's steel rod (mass, 20 mm set-up) on a hemisphere of `ball` material; the rod's own
/// modulus and the ball's times `stiffening` for the steel pair; the viscoelastic law calibrated
/// at the map's period-1 impact speed g T/(1 + e).
DropTestSetup pair(const PaperParameters& paper, bool steel, double stiffening) {
  DropTestSetup s = paper_setup(paper, "steel", 0.02);
  s.restitution = input_e;
  if (steel) {
    s.ball = {2.0e11 * stiffening, 0.3};
    s.rod = {2.0e11 * stiffening, 0.3};
    s.ball_yield_stress_Pa = INFINITY;
  }
  s.damping.reference_velocity_mps = s.gravity_mps2 / frequency_Hz / (1 + input_e);
  return s;
}

/// One run to make: set-up, law ("" for the instantaneous map), gamma and counts.
struct Job {
  DropTestSetup setup;
  std::string law;
  double gamma;
  int transient, kept;
  ShakerRun run;
};

ShakerRun run(const Job& j) {
  ShakerOptions o;
  o.wall = {.amplitude_m = shaker_amplitude_m(j.gamma, frequency_Hz, j.setup.gravity_mps2), .frequency_Hz = frequency_Hz};
  o.transient = j.transient;
  o.impacts = j.kept;
  o.impact_model = j.law.empty() ? ShakerImpactModel::instantaneous : ShakerImpactModel::soft;
  return run_shaker(j.setup, j.law.empty() ? "hongo" : j.law, solver(), o);
}

void run_all(std::vector<Job>& jobs, const char* label) {
  parallel_for_chunks(
      jobs.size(), [] { return 0; }, [&](int, std::size_t i) { jobs[i].run = run(jobs[i]); },
      {.label = label, .progress = false});
}

double phase_split(const ShakerRun& r) {
  const double d = std::abs(r.impacts.at(1).phase - r.impacts.at(0).phase);
  return std::min(d, 1 - d);
}

/// A family (pair, stiffening, law) and its threshold.
struct Family {
  std::string pair_label, law;
  bool steel;
  double stiffening;
  std::vector<std::size_t> scan;  ///< jobs of its period scan, ascending gamma
  double G_c = NAN;               ///< first scanned gamma with period 2
  double e_eff = NAN, contact_over_T = NAN, soft_G2 = NAN;
  double differential_e = NAN;  ///< dR/dW on the period-2 orbit just above the threshold
};

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const PaperParameters paper = load_paper_parameters();
  const std::clock_t cpu_start = std::clock();
  const int values = args.reduced ? 11 : static_cast<int>(std::lround((gamma_to - gamma_from) / gamma_step)) + 1;
  const double step = (gamma_to - gamma_from) / (values - 1);
  const int transient = args.reduced ? 400 : 1500, kept = args.reduced ? 8 : 32;
  const int threshold_transient = args.reduced ? 1500 : 6000;
  const double T = 1 / frequency_Hz;

  // 1. The diagrams of both soft laws on both pairs (their scans double as the thresholds' first
  //    bracket), and the stiffened steel pairs' scans around Gamma_2 of the input e's neighbourhood.
  std::vector<Job> jobs;
  std::vector<Family> families;
  auto add_scan = [&](Family f, double from, int count, double dG) {
    for (int k = 0; k < count; ++k) {
      f.scan.push_back(jobs.size());
      jobs.push_back({pair(paper, f.steel, f.stiffening), f.law, from + dG * k, transient, kept, {}});
    }
    families.push_back(f);
  };
  for (const bool steel : {true, false})
    for (const std::string law : {"hongo", viscoelastic})
      add_scan({steel ? "steel on steel" : "steel on nylon", law, steel, 1.0, {}}, gamma_from, values, step);
  run_all(jobs, "shaker diagrams");

  // 2. Bracket (the first scanned gamma of period 2), e_effective just below, and the two
  //    extrapolation runs above. The stiffened steel pairs are scanned around the bracket of the
  //    unstiffened one (+-5 steps).
  auto bracket = [&](Family& f) {
    for (std::size_t k = 1; k < f.scan.size(); ++k)
      if (jobs[f.scan[k]].run.pattern.period == 2) {  // the one before: period 1 (or not settled, --reduced)
        f.G_c = jobs[f.scan[k]].gamma;
        const ShakerRun& below = jobs[f.scan[k - 1]].run;
        f.e_eff = below.e_effective;
        f.contact_over_T = below.impacts.back().contact_time_s / T;
        break;
      }
    if (std::isnan(f.G_c)) throw std::runtime_error("no period doubling in the scan of " + f.pair_label + ", " + f.law);
  };
  for (std::size_t fi = 0; fi < 4; ++fi) bracket(families[fi]);
  const std::size_t diagram_jobs = jobs.size();
  const int around = args.reduced ? 2 : 5;
  for (const std::size_t fi : {0, 1})
    for (const double k : {10.0, 100.0})
      add_scan({"steel on steel", families[fi].law, true, k, {}}, families[fi].G_c - around * step, 2 * around + 1, step);
  {
    std::vector<Job> stiffened(jobs.begin() + static_cast<std::ptrdiff_t>(diagram_jobs), jobs.end());
    run_all(stiffened, "shaker stiffened scans");
    std::move(stiffened.begin(), stiffened.end(), jobs.begin() + static_cast<std::ptrdiff_t>(diagram_jobs));
  }
  for (std::size_t fi = 4; fi < families.size(); ++fi) bracket(families[fi]);
  std::vector<Job> extra;
  for (const Family& f : families) {
    for (const double g : {f.G_c + gamma_step / 2, f.G_c + 2 * gamma_step})  // reduced: a wider bracket
      extra.push_back({pair(paper, f.steel, f.stiffening), f.law, g, threshold_transient, 8, {}});
  }
  run_all(extra, "shaker thresholds");
  for (std::size_t i = 0; i < families.size(); ++i) {
    const Job &a = extra[2 * i], &b = extra[2 * i + 1];
    if (a.run.pattern.period != 2 || b.run.pattern.period != 2)
      throw std::runtime_error("the runs above the threshold of " + families[i].pair_label + ", " + families[i].law +
                               " are not of period 2");
    const double da2 = std::pow(phase_split(a.run), 2), db2 = std::pow(phase_split(b.run), 2);
    families[i].soft_G2 = a.gamma - da2 * (b.gamma - a.gamma) / (db2 - da2);
    const ShakerImpact &i0 = a.run.impacts.at(0), &i1 = a.run.impacts.at(1);
    families[i].differential_e =
        (i0.rebound_speed_mps - i1.rebound_speed_mps) / (i0.impact_speed_mps - i1.impact_speed_mps);
  }

  // 3. The map's diagram beside each soft law's on each pair, with that law's e_effective there
  //    (families 0 to 3).
  std::vector<Job> maps;
  for (const std::size_t fi : {0, 1, 2, 3})
    for (int k = 0; k < values; ++k) {
      DropTestSetup s = pair(paper, families[fi].steel, 1.0);  // the map reads e and g only
      s.restitution = families[fi].e_eff;
      maps.push_back({s, "", gamma_from + step * k, transient, kept, {}});
    }
  run_all(maps, "shaker maps");

  Parameters header{{"restitution_input", fmt::format("{}", input_e)},
                    {"frequency_Hz", fmt::format("{}", frequency_Hz)},
                    {"gamma", fmt::format("{} to {} in {} values", gamma_from, gamma_to, values)},
                    {"transient", std::to_string(transient)},
                    {"kept", std::to_string(kept)},
                    {"integrator", "gbs8-regularized, rtol = atol = 1e-8"},
                    {"rod", "the paper's steel rod (mass, flat end)"},
                    {"steel_pair", "hemisphere and rod E = 200 GPa, nu = 0.3"},
                    {"nylon_pair", "the paper's nylon hemisphere"},
                    {"viscoelastic_reference_velocity", "g T / (1 + e), the map's period-1 impact speed"}};
  for (const bool steel : {true, false}) {
    const std::size_t fi = steel ? 0 : 2;
    Parameters h = header;
    for (const std::size_t f : {fi, fi + 1})
      h.emplace_back("map_restitution_" + families[f].law,
                     fmt::format("{} (that law's e_effective on this pair)", families[f].e_eff));
    CsvWriter csv(fmt::format("hertzdash shaker_bifurcation: impact phase and speed against gamma, {}: each soft "
                              "contact (model = its law) and the instantaneous map with its e_effective (model = "
                              "instantaneous, law = that law)",
                              families[fi].pair_label),
                  h, {"model", "law", "gamma", "impact_phase", "impact_speed_mps", "contact_time_s", "period"});
    auto rows = [&](const std::string& model, const std::string& law, const Job& j) {
      for (const ShakerImpact& i : j.run.impacts)
        csv.add_row({model, law, j.gamma, i.phase, i.impact_speed_mps, i.contact_time_s,
                     static_cast<long>(j.run.pattern.period)});
    };
    for (const std::size_t f : {fi, fi + 1}) {
      for (int k = 0; k < values; ++k) rows("instantaneous", families[f].law, maps[f * values + k]);
      for (const std::size_t j : families[f].scan) rows(families[f].law, families[f].law, jobs[j]);
    }
    csv.save(args.out_dir / (steel ? "shaker_bifurcation_steel.csv" : "shaker_bifurcation_nylon.csv"));
  }

  LatexMacros macros("hertzdash shaker_bifurcation: bifurcation diagrams of the bouncing body, instantaneous map "
                     "against soft contacts",
                     header);
  macros.add("shakerInputRestitution", input_e, "{:.1f}");
  macros.add("shakerFrequencyHz", frequency_Hz, "{:.0f}");
  macros.add("shakerGammaFrom", gamma_from, "{:.1f}");
  macros.add("shakerGammaTo", gamma_to, "{:.1f}");
  macros.add("shakerGammaValues", values, "{:.0f}");
  macros.add("shakerGammaStep", step, "{:.2f}");
  macros.add("shakerTransient", transient, "{:.0f}");
  macros.add("shakerKept", kept, "{:.0f}");
  macros.add("shakerThresholdTransient", threshold_transient, "{:.0f}");
  macros.add("shakerGammaTwoHalf", gamma_2(input_e), "{:.4f}");
  std::string table = "% Generated by validation/shaker_bifurcation; do not edit.\n"
          "\\resizebox{\\linewidth}{!}{%  ten columns: scaled to the line width\n"
          "\\begin{tabular}{llcccccrcr}\n\\toprule\n"
          "Pair & Law & $t_c/T$ (\\%) & $\\eeff$ & $\\varepsilon$ & $\\Gamma_2$, soft & "
          "$\\Gamma_2(\\eeff)$ & shift (\\%) & $\\Gamma_2(\\eeff, \\varepsilon)$ & shift (\\%) \\\\\n\\midrule\n";
  // Macro tags: Steel|Nylon, Hongo|Viscoelastic, and Ten|Hundred for the stiffened steel pairs.
  double last_shift = NAN;
  for (const std::size_t fi : {0, 4, 5, 1, 6, 7, 2, 3}) {  // the stiffened steel rows below the first
    const Family& f = families[fi];
    const double map_G2 = gamma_2(f.e_eff), shift = f.soft_G2 / map_G2 - 1;
    const double speed_G2 = gamma_2(f.e_eff, f.differential_e), speed_shift = f.soft_G2 / speed_G2 - 1;
    std::string tag = std::string(f.steel ? "Steel" : "Nylon") + (f.law == "hongo" ? "Hongo" : "Viscoelastic") +
                      (f.stiffening == 10 ? "Ten" : f.stiffening == 100 ? "Hundred" : "");
    macros.add("shaker" + tag + "ContactPercent", 100 * f.contact_over_T, "{:.2f}");
    macros.add("shaker" + tag + "Eeff", f.e_eff, "{:.4f}");
    macros.add("shaker" + tag + "SoftThreshold", f.soft_G2, "{:.4f}");
    macros.add("shaker" + tag + "MapThreshold", map_G2, "{:.4f}");
    macros.add("shaker" + tag + "ShiftPercent", 100 * shift, "{:+.2f}");
    macros.add("shaker" + tag + "ShiftPerContact", shift / f.contact_over_T, "{:+.2f}");
    macros.add("shaker" + tag + "DifferentialE", f.differential_e, "{:.3f}");
    macros.add("shaker" + tag + "SpeedThreshold", speed_G2, "{:.4f}");
    macros.add("shaker" + tag + "SpeedShiftPercent", 100 * speed_shift, "{:+.2f}");
    if (f.steel) {  // the shift's ratio to the 10 times softer pair's
      if (f.stiffening > 1) macros.add("shaker" + tag + "ShiftRatio", shift / last_shift, "{:.2f}");
      last_shift = shift;
    }
    table += fmt::format("{} & {} & {:.2f} & {:.4f} & {:.3f} & {:.4f} & {:.4f} & ${:+.2f}$ & {:.4f} & ${:+.2f}$ \\\\\n",
                         f.steel ? fmt::format("steel, $E\\times{:g}$", f.stiffening) : "nylon", f.law,
                         100 * f.contact_over_T, f.e_eff, f.differential_e, f.soft_G2,
                         map_G2, 100 * shift, speed_G2, 100 * speed_shift);
    std::cout << fmt::format("{:15} {:14} x{:<4g} t_c/T {:.4f}  e_eff {:.5f}  eps {:.4f}  Gamma_2 soft {:.5f}  map {:.5f} "
                             "({:+.3f} %)  map(e, eps) {:.5f} ({:+.3f} %)\n",
                             f.pair_label, f.law, f.stiffening, f.contact_over_T, f.e_eff, f.differential_e, f.soft_G2,
                             map_G2, 100 * shift, speed_G2, 100 * speed_shift);
  }
  table += "\\bottomrule\n\\end{tabular}}\n";
  macros.add("shakerStiffeningRatio", std::pow(10.0, -0.4), "{:.2f}");
  const double cpu_s = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  std::cout << fmt::format("shaker_bifurcation: {:.1f} s of CPU\n", cpu_s);
  return save_study_outputs(args, "shaker_bifurcation", {}, table, macros);
} catch (const std::exception& e) {
  return study_failed(argv[0], e);
}
