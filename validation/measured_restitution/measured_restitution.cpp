// Against measurements no one here made: every damping law fitted to Gugan's measured
// restitution of a croquet ball on a wooden mallet face (data/external/gugan-croquet/).
//
// The paper's central modelling claim is a coefficient of restitution that does not depend on
// the impact speed, so that one drop test calibrates the dashpot for every impact. Gugan
// measured e of a croquet ball (Jaques Eclipse) bouncing on a clamped wooden face at ten speeds
// from 0.5 to 6 m/s (his Table I). This study asks what those data say about that claim:
//  1. The set-up. The ball is the model's sphere and falling body (mass m, radius R, from
//     ball.csv), the clamped face the rigid flat of the contact phase `hertzdash restitution`
//     runs (no gravity). Only the effective modulus E* enters the Hertz stiffness
//     K = (4/3) E* R^{1/2}, and neither modulus is given. E* is derived from Gugan's contact
//     time T at speed U (contact_time_wood_face.csv, its first row) with Hertz's undamped
//     contact time (K. L. Johnson, Contact Mechanics, CUP 1985, sec. 11.4; model/hertz.hpp):
//       T = (4/5) B(2/5, 1/2) X / U,  X = (5 m U^2 / (4 K))^{2/5}   =>
//       X = U T / ((4/5) B(2/5, 1/2)),  K = 5 m U^2 / (4 X^{5/2}),  E* = 3 K / (4 R^{1/2});
//     equivalently T = 2.87 (m^2 / (R E*^2 U))^{1/5}, the constant being
//     (4/5) B(2/5, 1/2) (15/16)^{2/5} = 2.868 (computed here, not typed). E* is put in the ball,
//     E_ball = E* (1 - nu^2) with the assumed nu of ball.csv (it enters no result).
//     Why derived and not fitted: e(U) of every law depends on E* only together with the law's
//     own parameter (the calibrated laws' e not at all; kuwabara-kono's through
//     A (K/m)^{2/5} U^{1/5}), so the table cannot determine both. Part 4 shows it.
//  2. Every registered law fitted to the table with fit_restitution_table, as
//     `hertzdash fit --restitution-table FILE --compare-laws --cross-validate` does
//     (simulation/fit/restitution_fit.hpp): its own parameter (the input e, or the viscoelastic
//     time constant A of kuwabara-kono), one common sigma estimated from the residuals (the
//     table has no e_sd), AIC = n ln(RSS/n) + 2(k+1), BIC, leave-one-speed-out cross-validation.
//     The law with the least AIC fits best; the one with the least cross-validated RMS
//     prediction error predicts best. A law whose fitted e is the same at every speed of the
//     table is speed-independent, as `fit`'s verdict says it (constant_e, fit_verdict.hpp: its
//     range below 1e-3; the laws calibrated at each impact's own speed vary by ~1e-10 here).
//  3. Each law's fitted e on a dense grid of speeds (0.3-7 m/s) for the figure, and the
//     viscoelastic law's residuals: their sign changes along the speed axis (about (n - 1)/2 for
//     random scatter, few for a systematic misfit).
//  4. kuwabara-kono fitted with A and E_ball together: the fit's identifiability.
//  5. The model's own contact time at Gugan's contact-time speeds, for the best law (and, on
//     stdout, the paper's), against the measured and Hertz's: the damped contact is not Hertz's
//     undamped one.
//
// What to expect: Gugan's e falls with the speed; every law whose coefficient is calibrated from
// e at each impact (all but kuwabara-kono) gives one e at every speed (Appendix damping_laws),
// the table's mean; kuwabara-kono's e falls as U^{1/5}.
//
// Writes: OUT/measured_restitution_curves.csv and OUT/measured_restitution_points.csv
// (measured_restitution.gp), OUT/measured_restitution_laws.csv (the per-law fit table),
// GENERATED/measured_restitution.tex (macros \measured...) and
// GENERATED/measured_restitution_table.tex.
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/csv_writer.hpp"
#include "validation/common/latex_macros.hpp"
#include "hertzdash/io/restitution_table.hpp"
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/fit/restitution_fit.hpp"
#include "hertzdash/simulation/run/calibrate_restitution.hpp"
#include "hertzdash/simulation/reports/fit_verdict.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"
#include "validation/common/study_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <stdexcept>

using namespace hertzdash;

namespace {

constexpr const char* viscoelastic = "kuwabara-kono";
constexpr double dense_min_mps = 0.3, dense_max_mps = 7.0;

/// A value of a `parameter,value,unit,provenance` table (ball.csv).
double table_value(const CsvTable& t, const std::string& name) {
  return t.number(t.find_row("parameter", name), "value");
}

/// The effective modulus E* [Pa] of a sphere (mass m [kg], radius R [m]) whose undamped Hertz
/// impact at speed U [m/s] lasts T [s] (see the opening comment, part 1).
double effective_modulus_from_contact_time(double m, double R, double U, double T) {
  const double X = U * T / undamped_hertz_contact_time_factor();
  const double K = 5 * m * U * U / (4 * std::pow(X, 2.5));
  return 3 * K / (4 * std::sqrt(R));
}

/// The contact phase of one impact at `speed` with the fitted options of a law: the set-up the
/// fit's model runs (restitution_fit.hpp, "Model").
DropTestSetup contact_at(const RunOptions& fitted, const PaperParameters& paper, double speed) {
  RunOptions o = fitted;
  o.impact_velocity_mps = speed;
  return contact_phase_setup(resolve_setup(o, paper));
}

/// A fit's points in order of increasing speed (the table's order for equal speeds).
std::vector<FitPoint> in_order_of_speed(std::vector<FitPoint> points) {
  std::stable_sort(points.begin(), points.end(), [](const FitPoint& a, const FitPoint& b) {
    return a.x < b.x;
  });
  return points;
}

std::string law_tt(const std::string& law) { return "\\texttt{" + latex_escaped(law) + "}"; }

/// A fitted parameter in the table: the input e, a time constant in microseconds, a damping rate.
std::string parameter_cell(const FittedParameter& p) {
  if (p.name == "viscous-time-constant")
    return fmt::format("$A = {:.2f} \\pm {:.2f}$\\,$\\mu$s", 1e6 * p.estimate, 1e6 * p.standard_error);
  if (p.name == "damping-rate")
    return fmt::format("$\\gamma = {:.0f} \\pm {:.0f}$\\,s$^{{-1}}$", p.estimate, p.standard_error);
  if (p.name == "restitution") return fmt::format("$e = {:.4f} \\pm {:.4f}$", p.estimate, p.standard_error);
  return fmt::format("{} $= {:.4g} \\pm {:.2g}$", latex_escaped(p.name), p.estimate, p.standard_error);
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const PaperParameters paper = load_paper_parameters();
  const std::filesystem::path data = default_data_dir() / "external" / "gugan-croquet";
  const RestitutionTable table = read_restitution_table(data / "restitution_wood_face.csv");
  const CsvTable ball = CsvTable::read(data / "ball.csv");
  const CsvTable contact = CsvTable::read(data / "contact_time_wood_face.csv");
  contact.require_columns({"impact_speed_m_per_s", "contact_time_s"});
  contact.require_rows();

  // 1. The set-up and E* from the contact time.
  const double m = table_value(ball, "ball_mass_kg"), R = table_value(ball, "ball_radius_m"),
               nu = table_value(ball, "ball_nu");
  const double U_T = contact.number(0, "impact_speed_m_per_s"), T = contact.number(0, "contact_time_s");
  const double E_star = effective_modulus_from_contact_time(m, R, U_T, T);
  const double E_ball = E_star * (1 - nu * nu);
  // Hertz's constant in Johnson's form, T = c (m^2 / (R E*^2 U))^{1/5}: c = (4/5) B(2/5, 1/2) (15/16)^{2/5}.
  const double johnson_constant = undamped_hertz_contact_time_factor() * std::pow(15.0 / 16.0, 0.4);
  if (std::abs(johnson_constant * std::pow(m * m / (R * E_star * E_star * U_T), 0.2) / T - 1) > 1e-12)
    throw std::logic_error("E* does not reproduce the contact time it was derived from");

  RunOptions base;
  base.mass_kg = m;
  base.ball_radius_m = R;
  base.ball_E_Pa = E_ball;
  base.ball_nu = nu;
  base.ball_yield_stress_Pa = std::numeric_limits<double>::infinity();  // unknown: no yield check

  Parameters header{{"table", "data/external/gugan-croquet/restitution_wood_face.csv"},
                    {"table_source", table.source},
                    {"ball_mass_kg", fmt::format("{}", m)},
                    {"ball_radius_m", fmt::format("{}", R)},
                    {"effective_modulus_Pa", fmt::format("{:.6g}", E_star)},
                    {"effective_modulus_source",
                     fmt::format("Hertz's undamped contact time {} s at {} m/s (contact_time_wood_face.csv)", T, U_T)},
                    {"ball_E_Pa", fmt::format("{:.6g}", E_ball)},
                    {"ball_nu", fmt::format("{} (assumed, ball.csv)", nu)},
                    {"flat", "rigid (the clamped mallet face)"},
                    {"fit", "fit_restitution_table, each law's own parameter, one common sigma, leave-one-speed-out "
                            "cross-validation (hertzdash fit --restitution-table --compare-laws --cross-validate)"}};
  LatexMacros macros("hertzdash measured_restitution: every law fitted to Gugan's croquet ball on a wooden face", header);

  // 2. Every law fitted, with cross-validation.
  FitSettings settings;
  settings.cross_validate = true;
  const LawComparison comparison = compare_laws_on_restitution(table, base, paper, settings);
  if (comparison.fits.empty() || comparison.fits.front().failed) throw std::runtime_error("no law could be fitted");
  for (const FitResult& f : comparison.fits)
    if (!f.cross_validation || !f.cross_validation->failure.empty())
      throw std::runtime_error("the cross-validation of " + f.law + " failed");
  const FitResult& best = comparison.fits.front();  // least AIC
  const FitResult* best_cv = &best;
  const FitResult *hongo = nullptr, *kk_fit = nullptr;
  for (const FitResult& f : comparison.fits) {
    if (f.cross_validation->rms_prediction_error < best_cv->cross_validation->rms_prediction_error) best_cv = &f;
    if (f.law == HongoPaper::info.name) hongo = &f;
    if (f.law == viscoelastic) kk_fit = &f;
  }
  if (!hongo || !kk_fit || kk_fit->failed) throw std::runtime_error("the paper's or the viscoelastic law was not fitted");
  auto speed_independent = [](const FitResult& f) { return constant_e(f.e_effective); };
  int constant_laws = 0, not_converged_constant = 0;
  std::vector<std::string> not_converged;
  for (const FitResult& f : comparison.fits) {
    constant_laws += speed_independent(f);
    if (!f.converged) not_converged.push_back(f.law), not_converged_constant += speed_independent(f);
  }

  // The laws' table, and their CSV.
  CsvWriter laws_csv("hertzdash measured_restitution: every law fitted to Gugan's croquet table, best AIC first",
                     header,
                     {"law", "aic", "delta_aic", "bic", "sigma", "parameter", "estimate", "standard_error",
                      "e_effective_min", "e_effective_max", "cv_rms_prediction_error", "cv_ratio_to_sigma", "converged",
                      "identifiable"});
  std::string tex = "% Generated by validation/measured_restitution; do not edit.\n"
                    "\\begin{tabular}{@{}lllrrl@{}}\n\\toprule\n"
                    "Law & fitted parameter & $e$ over the speeds & $\\Delta$AIC & $\\sigma$ & CV RMS error \\\\\n"
                    "\\midrule\n";
  for (const FitResult& f : comparison.fits) {
    const CrossValidation& cv = *f.cross_validation;
    for (const FittedParameter& p : f.parameters)
      laws_csv.add_row({f.law, f.aic, f.aic - best.aic, f.bic, f.sigma, p.name, p.estimate, p.standard_error, f.e_effective.min,
                        f.e_effective.max, cv.rms_prediction_error, cv.ratio, static_cast<long>(f.converged),
                        static_cast<long>(f.identifiable)});
    std::string cells;
    for (const FittedParameter& p : f.parameters) cells += (cells.empty() ? "" : ", ") + parameter_cell(p);
    const std::string range = speed_independent(f) ? fmt::format("{:.4f}", f.e_effective.min)
                                                    : fmt::format("{:.4f}--{:.4f}", f.e_effective.max, f.e_effective.min);
    tex += fmt::format("{}{} & {} & {} & {:.1f} & {:.4f} & {:.4f} \\\\\n", law_tt(f.law), f.converged ? "" : "$^*$",
                       cells, range, f.aic - best.aic, f.sigma, cv.rms_prediction_error);
  }
  for (const auto& [law, why] : comparison.failures)
    tex += fmt::format("{} & \\multicolumn{{5}}{{l}}{{not fitted: {}}} \\\\\n", law_tt(law),
                       law == "none" ? "undamped, nothing to fit" : latex_escaped(why));
  tex += "\\bottomrule\n\\end{tabular}\n";

  // 3. The fitted curves on a dense grid, the points and the viscoelastic law's residual signs.
  ImpactSimulator simulator([] {
    SolverSettings s;  // the fit's own model solver (restitution_fit.hpp, "Model")
    s.integrator = IntegratorKind::gbs8_regularized;
    s.rtol = s.atol = 1e-12;
    return s;
  }());
  CsvWriter curves("hertzdash measured_restitution: each law's fitted e_effective against the impact speed (contact "
                   "phase, rigid face)",
                   header, {"law", "impact_speed_mps", "e_effective"});
  CsvWriter points("hertzdash measured_restitution: Gugan's measured e and each law's fitted e at the table's speeds, "
                   "in order of speed",
                   header, {"law", "impact_speed_mps", "e_measured", "e_model", "residual"});
  const int grid = args.reduced ? 6 : 60;
  for (const FitResult& f : comparison.fits) {
    for (int i = 0; i < grid; ++i) {
      const double v = dense_min_mps * std::pow(dense_max_mps / dense_min_mps, i / static_cast<double>(grid - 1));
      const ImpactSummary r = simulator.run(contact_at(f.fitted_options, paper, v), f.law);
      curves.add_row({f.law, v, r.separated ? r.e_effective : NAN});
    }
    for (const FitPoint& p : in_order_of_speed(f.points))
      points.add_row({f.law, p.x, p.measured, p.model, p.residual});
  }
  const std::vector<FitPoint> by_speed = in_order_of_speed(kk_fit->points);
  int sign_changes = 0;
  for (std::size_t i = 1; i < by_speed.size(); ++i)
    sign_changes += (by_speed[i].residual > 0) != (by_speed[i - 1].residual > 0);

  // 4. kuwabara-kono with A and E_ball together.
  RunOptions kk = base;
  kk.damping = viscoelastic;
  FitSettings joint_settings;
  joint_settings.parameters = parse_fit_parameters("viscous-time-constant,ball-E");
  const FitResult joint = fit_restitution_table(table, kk, paper, joint_settings);
  const double joint_correlation = std::abs(joint.correlation.at(0).at(1));

  // 5. The model's contact times at the measured ones' speeds.
  std::string contact_text;
  for (std::size_t i = 0; i < contact.rows(); ++i) {
    const std::string tag = i == 0 ? "Slow" : i == 1 ? "Fast" : "";  // the file's two rows
    if (tag.empty()) continue;
    const double U = contact.number(i, "impact_speed_m_per_s"), T_measured = contact.number(i, "contact_time_s");
    const double T_best = simulator.run(contact_at(best.fitted_options, paper, U), best.law).contact_time_s;
    const double T_hongo = simulator.run(contact_at(hongo->fitted_options, paper, U), hongo->law).contact_time_s;
    const double T_hertz = undamped_hertz_impact(4.0 / 3.0 * E_star * std::sqrt(R), m, U).contact_time_s;
    macros.add("measuredContactSpeed" + tag, U, "{:.2f}");
    macros.add("measuredContactTimeMs" + tag, 1e3 * T_measured, "{:.2f}");
    macros.add("measuredBestContactTimeMs" + tag, 1e3 * T_best, "{:.2f}");
    macros.add("measuredHertzContactTimeMs" + tag, 1e3 * T_hertz, "{:.2f}");
    contact_text += fmt::format("  U = {:.2f} m/s: T measured {:.3f} ms, Hertz {:.3f} ms, {} {:.3f} ms, hongo {:.3f} ms\n", U,
                                1e3 * T_measured, 1e3 * T_hertz, best.law, 1e3 * T_best, 1e3 * T_hongo);
  }

  // The macros.
  const auto [e_lo, e_hi] = std::minmax_element(table.e.begin(), table.e.end());
  const auto [v_lo, v_hi] = std::minmax_element(table.impact_speed_mps.begin(), table.impact_speed_mps.end());
  const int law_count = static_cast<int>(comparison.fits.size() + comparison.failures.size());
  macros.add("measuredRows", static_cast<double>(table.rows()), "{:.0f}");
  macros.add_text("measuredRowsWords", number_in_words(static_cast<int>(table.rows())));
  macros.add("measuredSpeedMin", *v_lo, "{:.2f}");
  macros.add("measuredSpeedMax", *v_hi, "{:.2f}");
  macros.add("measuredEMax", *e_hi, "{:.3f}");
  macros.add("measuredEMin", *e_lo, "{:.3f}");
  macros.add("measuredEDrop", *e_hi - *e_lo, "{:.3f}");
  macros.add("measuredBallMassKg", m, "{:.4f}");
  macros.add("measuredBallRadiusMm", 1e3 * R, "{:.0f}");
  macros.add("measuredBallNu", nu, "{:.2f}");
  macros.add("measuredJohnsonConstant", johnson_constant, "{:.3f}");
  macros.add("measuredEStarGPa", E_star / 1e9, "{:.3f}");
  macros.add("measuredBallEGPa", E_ball / 1e9, "{:.3f}");
  macros.add_text("measuredLawCountWords", number_in_words(law_count));
  macros.add_text("measuredFittedLawCountWords", number_in_words(static_cast<int>(comparison.fits.size())));
  macros.add_text("measuredConstantLawCountWords",
                  count_of_total_in_words(constant_laws, static_cast<int>(comparison.fits.size())));
  macros.add_text("measuredBestAicLaw", law_tt(best.law));
  macros.add_text("measuredBestCvLaw", law_tt(best_cv->law));
  macros.add("measuredBestSigma", best.sigma, "{:.4f}");
  macros.add("measuredDropOverBestSigma", (*e_hi - *e_lo) / best.sigma, "{:.0f}");
  macros.add("measuredBestCvRms", best_cv->cross_validation->rms_prediction_error, "{:.4f}");
  macros.add("measuredViscoelasticCvRatio", kk_fit->cross_validation->ratio, "{:.2f}");
  macros.add("measuredViscoelasticEHigh", kk_fit->e_effective.max, "{:.3f}");
  macros.add("measuredViscoelasticELow", kk_fit->e_effective.min, "{:.3f}");
  macros.add_text("measuredViscoelasticSignChangesPhrase", sign_changes == 1   ? "once"
                                                           : sign_changes == 2 ? "twice"
                                                                               : number_in_words(sign_changes) + " times");
  macros.add("measuredRandomSignChanges", 0.5 * static_cast<double>(table.rows() - 1), "{:.1f}");
  const FittedParameter& A = kk_fit->parameter("viscous-time-constant");
  macros.add("measuredViscoelasticTimeConstantMicrosecond", 1e6 * A.estimate, "{:.1f}");
  macros.add("measuredViscoelasticTimeConstantErrorMicrosecond", 1e6 * A.standard_error, "{:.1f}");
  macros.add("measuredHongoE", hongo->e_effective.min, "{:.4f}");
  macros.add("measuredHongoInputE", hongo->parameter("restitution").estimate, "{:.4f}");
  macros.add("measuredHongoSigma", hongo->sigma, "{:.4f}");
  macros.add("measuredHongoDeltaAic", hongo->aic - best.aic, "{:.1f}");
  macros.add("measuredHongoCvRms", hongo->cross_validation->rms_prediction_error, "{:.4f}");
  macros.add("measuredHongoCvOverBest",
             hongo->cross_validation->rms_prediction_error / best_cv->cross_validation->rms_prediction_error, "{:.1f}");
  macros.add("measuredHongoSigmaOverViscoelastic", hongo->sigma / kk_fit->sigma, "{:.1f}");
  macros.add("measuredJointIdentifiable", joint.identifiable ? 1 : 0, "{:.0f}");
  macros.add("measuredJointCorrelation", joint_correlation, "{:.4f}");
  {
    std::string clause = "every fit converged";
    if (!not_converged.empty()) {
      std::string names;
      for (std::size_t i = 0; i < not_converged.size(); ++i)
        names += (i == 0 ? "" : i + 1 == not_converged.size() ? " and " : ", ") + law_tt(not_converged[i]);
      clause = fmt::format("$^*$\\,{} stopped where no step lowered the cost within its resolution{}", names,
                           not_converged_constant == static_cast<int>(not_converged.size())
                               ? ", at the same constant as the other speed-independent laws"
                               : "");
    }
    macros.add_text("measuredConvergenceClause", clause);
  }

  std::cout << fmt::format("E* = {:.4g} Pa from T = {} s at {} m/s (Johnson's constant {:.4f}); E_ball = {:.4g} Pa\n",
                           E_star, T, U_T, johnson_constant, E_ball);
  for (const FitResult& f : comparison.fits)
    std::cout << fmt::format("{:20} AIC {:9.3f}  dAIC {:6.2f}  sigma {:.5f}  e {:.4f}-{:.4f}  cv_rms {:.5f}{}\n", f.law,
                             f.aic, f.aic - best.aic, f.sigma, f.e_effective.min, f.e_effective.max, f.cross_validation->rms_prediction_error,
                             f.converged ? "" : "  (not converged: " + f.stop_reason + ")");
  std::cout << fmt::format("best by AIC {}, by cross-validation {}; residual sign changes of {}: {}\n", best.law,
                           best_cv->law, viscoelastic, sign_changes)
            << fmt::format("kuwabara-kono with A and ball-E: identifiable {}, |correlation| {:.6f}\n", joint.identifiable,
                           joint_correlation)
            << contact_text;

  return save_study_outputs(args, "measured_restitution",
                            {{"measured_restitution_curves.csv", curves}, {"measured_restitution_points.csv", points},
                             {"measured_restitution_laws.csv", laws_csv}},
                            tex, macros);
} catch (const std::exception& e) {
  return study_failed(argv[0], e);
}
