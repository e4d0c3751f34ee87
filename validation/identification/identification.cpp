// Identification on virtual experiments: can `hertzdash fit` recover the nylon modulus and e
// from drop-test traces, with honest error bars, and what would fitting the paper's rigid model
// to the real (elastic) rod have done to the estimates?
//
// No measured trace of the paper exists (it printed its traces only as plots), so every trace
// here is SYNTHETIC: a virtual experiment with known truth (simulation/fit/virtual_measurement.hpp).
// The measurement chain is an assumption, stated once and used throughout: the load cell under
// the hemisphere and the accelerometer on the rod's top face, each sampled at 500 kHz through a
// second-order Butterworth anti-alias filter at 100 kHz, with white noise of 1 % of each
// channel's peak. The truth: the four rods of Table 1 dropped from 20 mm, nylon E = 1.7 GPa
// (inside the 1.2-2.9 GPa the paper leaves open) and e = Table 2's. The fit starts from the
// paper's assumed E = 2.0 GPa and e = 0.9, and fits E, e and the onset time
// (simulation/fit/trace_fit.hpp).
//
//  1. Coverage. The rigid model's traces (the paper's model, so the fitted model is right) with
//     `draws` independent noise draws per rod: how often does the 1-sigma interval contain the
//     truth? Least squares with white noise predicts 68.3 %; the binomial scatter of the
//     observed fraction is sqrt(0.683 * 0.317 / N).
//  2. Model-form bias. The elastic rod on the load cell (model/elastic_drop_test.hpp) makes the
//     traces; the rigid model is fitted to them, as the paper implicitly did: by how much, in
//     units of the statistical error, are E and e off, and does the reduced chi-square notice?
//     The elastic model fitted to the same traces shows what the bias is owed to.
//  3. The figure: the steel rod's elastic trace with both fits and their residuals.
//
// Writes: OUT/identification_draws.csv, OUT/identification_bias.csv, OUT/identification_fit_
// {rigid,elastic}.csv (identification.gp, identification_fit.gp), GENERATED/identification.tex
// (macros \ident...) and GENERATED/identification_table.tex.
#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/csv_writer.hpp"
#include "validation/common/latex_macros.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "validation/common/all_rods.hpp"
#include "validation/common/study_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <tuple>

using namespace hertzdash;

namespace {

constexpr double truth_E_Pa = 1.7e9, start_e = 0.9, height_m = 0.020;
constexpr double inf_aic = std::numeric_limits<double>::infinity();

MeasurementChain load_cell_and_accelerometer() {
  MeasurementChain c;
  c.sample_rate_Hz = 5e5;
  c.anti_alias_cutoff_Hz = 1e5;
  c.noise_fraction = 0.01;
  c.channels = {"force_N", "accel_mps2"};
  return c;
}

// The truth's run, with a fine fixed step: its samples between steps are interpolated with an
// error (pi 2e-7 / 1.2e-3)^2 / 8 = 3e-8 of the peak, far below the noise.
SimulateRun truth_run(const PaperParameters& paper, const std::string& rod, bool elastic, int elements) {
  RunOptions o;
  o.rod = rod;
  o.height_m = height_m;
  o.ball_E_Pa = truth_E_Pa;
  o.integrator = "rk4";
  o.dt_s = 2e-7;
  if (elastic) {
    o.rod_model = "elastic";
    o.rod_elements = elements;
  }
  return run_simulate(o, paper, true);
}

// Where the fit starts, and the model it fits: rigid, or the elastic rod.
RunOptions fit_start(const std::string& rod, bool elastic, int elements) {
  RunOptions o;
  o.rod = rod;
  o.height_m = height_m;
  o.restitution = start_e;
  if (elastic) {
    o.rod_model = "elastic";
    o.rod_elements = elements;
  }
  return o;
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const PaperParameters paper = load_paper_parameters();
  const int draws = args.reduced ? 4 : 50;
  const int elements = args.reduced ? 4 : ElasticRodSetup::default_elements;
  const MeasurementChain chain = load_cell_and_accelerometer();
  const TraceFitSettings settings;  // E, e and the onset time

  Parameters header{{"truth_ball_E_Pa", fmt::format("{}", truth_E_Pa)},
                    {"truth_restitution", "Table 2"},
                    {"height_m", fmt::format("{}", height_m)},
                    {"start_ball_E_Pa", "2e9 (the paper's assumption)"},
                    {"start_restitution", fmt::format("{}", start_e)},
                    {"sample_rate_Hz", fmt::format("{}", chain.sample_rate_Hz)},
                    {"anti_alias_cutoff_Hz", fmt::format("{}", chain.anti_alias_cutoff_Hz)},
                    {"noise_fraction", fmt::format("{}", chain.noise_fraction)},
                    {"channels", "force_N accel_mps2"},
                    {"draws_per_rod", std::to_string(draws)},
                    {"elastic_rod_elements", std::to_string(elements)},
                    {"traces", "SYNTHETIC virtual experiments; no measured trace of the paper exists"}};
  LatexMacros macros("hertzdash identification: fitting E and e to virtual drop-test traces", header);
  CsvWriter draws_csv("hertzdash identification: fits of the rigid model to its own virtual traces (SYNTHETIC), one "
                      "row per rod and noise draw",
                      header,
                      {"rod", "draw", "E_estimate_Pa", "E_standard_error_Pa", "e_truth", "e_estimate",
                       "e_standard_error", "reduced_chi_square"});
  CsvWriter bias_csv("hertzdash identification: fits to the elastic rod's virtual traces (SYNTHETIC): estimates "
                     "from the trace without noise, standard errors and reduced chi-square from one with noise",
                     header,
                     {"rod", "model", "E_estimate_Pa", "E_standard_error_Pa", "e_truth", "e_estimate",
                      "e_standard_error", "reduced_chi_square"});

  // 1. Coverage of the 1-sigma intervals, the fitted model being the true one.
  int inside_E = 0, inside_e = 0, total = 0;
  double rel_se_E = 0, se_e = 0;
  for (const RodData& rod : paper.rods) {
    const SimulateRun truth = truth_run(paper, rod.name, false, elements);
    for (int d = 1; d <= draws; ++d) {
      MeasurementChain c = chain;
      c.seed = static_cast<std::uint64_t>(d);
      const FitResult f = fit_trace(virtual_measurement(truth, rod.name, c), fit_start(rod.name, false, elements), paper,
                                   settings);
      const FittedParameter &E = f.parameter("ball-E"), &e = f.parameter("restitution");
      inside_E += std::abs(E.estimate - truth_E_Pa) <= E.standard_error;
      inside_e += std::abs(e.estimate - rod.restitution) <= e.standard_error;
      rel_se_E += E.standard_error / E.estimate;
      se_e += e.standard_error;
      ++total;
      draws_csv.add_row({rod.name, static_cast<long>(d), E.estimate, E.standard_error, rod.restitution, e.estimate,
                         e.standard_error, f.reduced_chi_square});
    }
  }
  const double coverage_E = double(inside_E) / total, coverage_e = double(inside_e) / total;
  const double binomial = std::sqrt(0.683 * 0.317 / total);
  std::cout << fmt::format("coverage of the 1-sigma intervals over {} fits: E {:.3f}, e {:.3f} (expected 0.683 +- {:.3f})\n",
                           total, coverage_E, coverage_e, binomial);
  macros.add("identFits", total, "{:.0f}");
  macros.add("identDrawsPerRod", draws, "{:.0f}");
  macros.add("identCoverageEPct", 100 * coverage_E, "{:.1f}");
  macros.add("identCoverageRestitutionPct", 100 * coverage_e, "{:.1f}");
  macros.add("identCoverageBinomialPct", 100 * binomial, "{:.1f}");
  macros.add("identRelativeErrorEPct", 100 * rel_se_E / total, "{:.2f}");
  macros.add("identErrorRestitution", se_e / total, "{:.5f}");

  // Which law? Every registered law fitted (E, e, onset) to one noisy trace of the paper's law
  // (steel): the criterion can only tell force laws apart by their shape. The paper's dashpot
  // c x^{1/2} xdot has Kuwabara-Kono's form, so the two tie; the laws of the form x^{3/2} xdot
  // (Hunt-Crossley and its relatives) differ only in how their coefficient follows from e, which
  // the fitted e absorbs, so they tie among themselves.
  {
    MeasurementChain c = chain;
    c.seed = 1;
    const RodData& steel = paper.rod("steel");
    const LawComparison laws = compare_laws(virtual_measurement(truth_run(paper, steel.name, false, elements), steel.name, c),
                                            fit_start(steel.name, false, elements), paper, settings);
    auto aic = [&](const std::string& law) {
      for (const FitResult& f : laws.fits)
        if (f.law == law) return f.aic;
      throw std::logic_error("law not fitted: " + law);
    };
    const double reference = aic("hongo");
    macros.add("identLawsFitted", static_cast<double>(laws.fits.size()), "{:.0f}");
    macros.add("identAicGapKuwabaraKono", aic("kuwabara-kono") - reference, "{:.2f}");
    macros.add("identAicGapHuntCrossley", aic("hunt-crossley") - reference, "{:.0f}");
    macros.add("identAicGapKelvinVoigt", aic("kelvin-voigt") - reference, "{:.0f}");
    macros.add("identAicGapNone", aic("none") - reference, "{:.0f}");
    // The spread of the x^{3/2} xdot family (laws whose coefficient differs, not their form).
    double lo = inf_aic, hi = -inf_aic;
    for (const char* law : {"hunt-crossley", "lankarani-nikravesh", "flores", "gonthier", "hu-guo", "zhiying-qishao"})
      lo = std::min(lo, aic(law)), hi = std::max(hi, aic(law));
    macros.add_text("identAicSpreadHuntCrossleyFamily", latex_scientific(hi - lo));
    std::cout << fmt::format("AIC minus the paper's law's: kuwabara-kono {:.2f}, hunt-crossley {:.0f}, kelvin-voigt {:.0f}, "
                             "none {:.0f}\n",
                             aic("kuwabara-kono") - reference, aic("hunt-crossley") - reference,
                             aic("kelvin-voigt") - reference, aic("none") - reference);
  }

  // 2. The elastic rod's traces, fitted by the rigid model and by the elastic one. The bias is
  // read on the trace without noise (the same filter and sampling), so that it is the model
  // form's alone; a noisy trace (its own seed per rod) gives the statistical error it is
  // measured against and the reduced chi-square a researcher would see.
  std::string table;
  long seed = 100;
  std::size_t residual_count = 0;
  std::vector<double> biases_E, biases_E_sigma, biases_e_sigma, chi2_rigid, chi2_elastic, elastic_biases_E;
  for (const RodData& rod : paper.rods) {
    const SimulateRun truth = truth_run(paper, rod.name, true, elements);
    auto fits_of = [&](double noise_fraction) {
      MeasurementChain c = chain;
      c.noise_fraction = noise_fraction;
      c.seed = static_cast<std::uint64_t>(++seed);
      MeasuredTrace trace = virtual_measurement(truth, rod.name, c);
      trace.path = fmt::format("virtual {} elastic rod, noise {}", rod.name, noise_fraction);
      return std::tuple{trace, fit_trace(trace, fit_start(rod.name, false, elements), paper, settings),
                        fit_trace(trace, fit_start(rod.name, true, elements), paper, settings)};
    };
    const auto [clean_trace, clean_rigid, clean_elastic] = fits_of(0.0);
    const auto [noisy_trace, noisy_rigid, noisy_elastic] = fits_of(chain.noise_fraction);
    for (const auto& [model, clean, noisy] : {std::tuple{"rigid", &clean_rigid, &noisy_rigid},
                                              std::tuple{"elastic", &clean_elastic, &noisy_elastic}}) {
      const FittedParameter &E = clean->parameter("ball-E"), &e = clean->parameter("restitution");
      bias_csv.add_row({rod.name, std::string(model), E.estimate, noisy->parameter("ball-E").standard_error,
                        rod.restitution, e.estimate, noisy->parameter("restitution").standard_error,
                        noisy->reduced_chi_square});
    }
    const double bias_E = clean_rigid.parameter("ball-E").estimate / truth_E_Pa - 1;
    const double bias_e = clean_rigid.parameter("restitution").estimate - rod.restitution;
    const double sigma_E = noisy_rigid.parameter("ball-E").standard_error / truth_E_Pa;
    const double sigma_e = noisy_rigid.parameter("restitution").standard_error;
    const double elastic_bias_E = clean_elastic.parameter("ball-E").estimate / truth_E_Pa - 1;
    const double elastic_bias_e = clean_elastic.parameter("restitution").estimate - rod.restitution;
    biases_E.push_back(100 * bias_E);
    biases_E_sigma.push_back(bias_E / sigma_E);
    biases_e_sigma.push_back(std::abs(bias_e / sigma_e));
    chi2_rigid.push_back(noisy_rigid.reduced_chi_square);
    chi2_elastic.push_back(noisy_elastic.reduced_chi_square);
    residual_count = noisy_elastic.n;
    elastic_biases_E.push_back(std::abs(100 * elastic_bias_E));
    const std::string tag = rod_macro_tag(rod.name);
    macros.add("ident" + tag + "RigidBiasEPct", 100 * bias_E, "{:+.2f}");
    macros.add("ident" + tag + "RigidBiasEInSigma", bias_E / sigma_E, "{:+.1f}");
    macros.add("ident" + tag + "RigidBiasRestitution", bias_e, "{:+.4f}");
    macros.add("ident" + tag + "RigidBiasRestitutionInSigma", bias_e / sigma_e, "{:+.1f}");
    macros.add("ident" + tag + "RigidReducedChiSquare", noisy_rigid.reduced_chi_square, "{:.3g}");
    macros.add("ident" + tag + "ElasticBiasEPct", 100 * elastic_bias_E, "{:+.3f}");
    macros.add("ident" + tag + "ElasticReducedChiSquare", noisy_elastic.reduced_chi_square, "{:.3g}");
    table += fmt::format("{} & {:.3f} & {:+.2f} ({:+.1f}) & {:+.4f} ({:+.1f}) & {:.3g} & {:+.3f} & {:+.5f} & {:.3g} \\\\\n",
                         rod_label(rod.name), rod.restitution, 100 * bias_E, bias_E / sigma_E, bias_e, bias_e / sigma_e,
                         noisy_rigid.reduced_chi_square, 100 * elastic_bias_E, elastic_bias_e,
                         noisy_elastic.reduced_chi_square);
    std::cout << fmt::format("{}: rigid model on the elastic trace: E {:+.2f} % ({:+.1f} sigma), e {:+.4f} ({:+.1f} sigma), "
                             "chi2/dof {:.3g}; elastic model: E {:+.3f} %, e {:+.5f}, chi2/dof {:.3g}\n",
                             rod.name, 100 * bias_E, bias_E / sigma_E, bias_e, bias_e / sigma_e,
                             noisy_rigid.reduced_chi_square, 100 * elastic_bias_E, elastic_bias_e,
                             noisy_elastic.reduced_chi_square);
    if (rod.name == "steel") {
      write_fit_curves(noisy_rigid, noisy_trace, args.out_dir / "identification_fit_rigid.csv");
      write_fit_curves(noisy_elastic, noisy_trace, args.out_dir / "identification_fit_elastic.csv");
    }
  }
  auto [lo_E, hi_E] = std::minmax_element(biases_E.begin(), biases_E.end());
  auto [lo_s, hi_s] = std::minmax_element(biases_E_sigma.begin(), biases_E_sigma.end());
  auto [lo_c, hi_c] = std::minmax_element(chi2_rigid.begin(), chi2_rigid.end());
  macros.add("identRigidBiasEPctMin", *lo_E, "{:+.2f}");
  macros.add("identRigidBiasEPctMax", *hi_E, "{:+.2f}");
  macros.add("identRigidBiasEInSigmaMin", *lo_s, "{:+.1f}");
  macros.add("identRigidBiasEInSigmaMax", *hi_s, "{:+.1f}");
  macros.add("identRigidBiasRestitutionInSigmaMax", *std::max_element(biases_e_sigma.begin(), biases_e_sigma.end()), "{:.1f}");
  macros.add("identRigidReducedChiSquareMin", *lo_c, "{:.3g}");
  macros.add("identRigidReducedChiSquareMax", *hi_c, "{:.3g}");
  auto [lo_ce, hi_ce] = std::minmax_element(chi2_elastic.begin(), chi2_elastic.end());
  macros.add("identElasticReducedChiSquareMin", *lo_ce, "{:.3g}");
  // The reduced chi-square of a correct model scatters by sqrt(2 / n) about 1 (chi^2 with n dof).
  macros.add("identResiduals", static_cast<double>(residual_count), "{:.0f}");
  macros.add("identChiSquareScatter", std::sqrt(2.0 / static_cast<double>(residual_count)), "{:.2f}");
  macros.add("identElasticReducedChiSquareMax", *hi_ce, "{:.3g}");
  macros.add("identElasticBiasEPctMax", *std::max_element(elastic_biases_E.begin(), elastic_biases_E.end()), "{:.3f}");
  macros.add("identSampleRateKHz", chain.sample_rate_Hz / 1e3, "{:.0f}");
  macros.add("identAntiAliasKHz", chain.anti_alias_cutoff_Hz / 1e3, "{:.0f}");
  macros.add("identNoisePct", 100 * chain.noise_fraction, "{:.0f}");
  macros.add("identTruthEGPa", truth_E_Pa / 1e9, "{:.1f}");
  macros.add("identStartEGPa", paper.ball.E_Pa / 1e9, "{:.1f}");
  macros.add("identHeightMm", 1e3 * height_m, "{:.0f}");
  macros.add("identStartRestitution", start_e, "{:.1f}");

  draws_csv.save(args.out_dir / "identification_draws.csv");
  bias_csv.save(args.out_dir / "identification_bias.csv");
  write_file_atomically(args.generated_dir / "identification_table.tex",
                        "% Generated by validation/identification; do not edit.\n"
                        "\\begin{tabular}{lccccccc}\n\\toprule\n"
                        "Rod & true & \\multicolumn{3}{c}{rigid model} & \\multicolumn{3}{c}{elastic rod model} \\\\\n"
                        " & $e$ & $\\Delta E$ (\\%) ($\\sigma$) & $\\Delta e$ ($\\sigma$) & $\\chi^2_\\nu$ & $\\Delta E$ (\\%) & "
                        "$\\Delta e$ & $\\chi^2_\\nu$ \\\\\n\\midrule\n" +
                            table + "\\bottomrule\n\\end{tabular}\n");
  macros.save(args.generated_dir / "identification.tex");
  return 0;
} catch (const std::exception& e) {
  return study_failed(argv[0], e);
}
