// The paper's results under its joint input uncertainty: bands of Figs. 5 and 6, and which
// input the uncertainty of each result comes from (Sobol indices), beside the linearisation.
//
// What it reproduces and why. The paper leaves inputs unstated (the nylon modulus within a
// catalogue range 1.2-2.9 GPa, every Poisson ratio) and gives others as single measurements
// (e, whose one repeat, rod A at 0.828 and 0.834, shows a scatter; the masses and the drop
// height to the printed digits). The other studies vary them one at a time (paper_figures: the
// nylon modulus band; elasticities: derivatives at one point). Here they are drawn jointly,
// each from the distribution data/assumptions.csv states with its reason
// (simulation/uncertain_inputs.hpp), independent of each other:
//   nylon E, nylon nu, the rod's nu, e (Table 2 + deviation), R, h, m (Table 1 + deviation),
//   the rod's E (Table 3 x (1 + deviation)).
// For every rod at the paper's h = 20 mm the paper's model (law "hongo") runs on the rows of a
// Saltelli design (simulation/sobol_indices.hpp: N rows each of A, B and the d matrices
// A_B^(i); Sobol points, so N (d + 2) runs, each started at contact onset with v0 = sqrt(2 g h))
// and gives
//   - the 5 %, 50 % and 95 % quantiles of e_effective, peak force and contact time over the
//     2N joint draws of A and B,
//   - first-order and total Sobol indices of each with 95 % bootstrap intervals,
//   - beside them the variance share the linearisation predicts, el_i^2 CV_i^2 / sum_k
//     el_k^2 CV_k^2, from the CVODES elasticities of validation/elasticities at the assumed
//     values (the rod's nu and E act only through K, so theirs are the nylon modulus's scaled by
//     d ln K / d ln p; eq. 3), with CV_i = sd_i / value_i of each input's distribution;
//   - for the steel rod (Fig. 5) and duralumin rod C (Fig. 6) the pointwise 5-50-95 % band of
//     the force, displacement, acceleration and velocity histories over the first N_band rows
//     of A and B, and the loops (panel c) of the runs at the 5th, 50th and 95th percentile of
//     peak force (a loop has no pointwise band: its points belong to different instants).
// What to expect: peak force and contact time follow the Hertz scalings (K^{2/5}, K^{-2/5}),
// so the nylon modulus, the widest input, carries most of their variance and the Sobol indices
// match the linear shares; e_effective depends on e alone to within gravity's small work
// (validation/elasticities), so S_e ~ 1 for it. S_i ~ ST_i throughout would say the inputs
// barely interact.
//
// Sample sizes: --reduced (the pipeline test) N = 64; `make figures` N = 4096 (a few seconds);
// `make uncertainty` (--full) N = 65536 (2.6 million impacts, over a minute on 2 cores). The
// band runs: 2 x 16, 2 x 512, 2 x 2048.
// Writes: OUT/uncertainty_inputs.csv, OUT/uncertainty_outputs.csv, OUT/uncertainty_sobol.csv,
// OUT/uncertainty_fig5.csv, OUT/uncertainty_fig6.csv (drawn by the .gp scripts here),
// GENERATED/uncertainty.tex (macros \uq...), GENERATED/uncertainty_inputs_table.tex,
// GENERATED/uncertainty_sobol_table.tex.
#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/io/latex_macros.hpp"
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/simulation/impact_history.hpp"
#include "hertzdash/simulation/paper_law_elasticities.hpp"
#include "hertzdash/simulation/paper_parameters.hpp"
#include "hertzdash/simulation/parallel_sweep.hpp"
#include "hertzdash/simulation/sample_quantile.hpp"
#include "hertzdash/simulation/sobol_indices.hpp"
#include "validation/common/all_rods.hpp"
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

// The varied inputs, in design order. `rod_nu` is steel_nu or duralumin_nu by rod.
struct InputSlot {
  const char* parameter;  ///< row of data/assumptions.csv
  const char* symbol;     ///< LaTeX
  const char* tag;        ///< macro name part
};
constexpr std::array<InputSlot, 8> slots{{{"nylon_E_Pa", "$E_s$ (nylon)", "NylonE"},
                                          {"nylon_nu", "$\\nu_s$ (nylon)", "NylonNu"},
                                          {"rod_nu", "$\\nu_w$ (rod)", "RodNu"},
                                          {"restitution_deviation", "$e$", "Restitution"},
                                          {"ball_radius_m", "$R$", "Radius"},
                                          {"drop_height_m", "$h$", "Height"},
                                          {"mass_deviation_kg", "$m$", "Mass"},
                                          {"rod_E_relative_deviation", "$E_w$ (rod)", "RodE"}}};
constexpr std::size_t d = slots.size();

const UncertainInput& slot_input(const PaperParameters& paper, const std::string& rod, std::size_t k) {
  const std::string p = slots[k].parameter;
  if (p != "rod_nu") return paper.uncertain_input(p);
  return paper.uncertain_input(rod.rfind("steel", 0) == 0 ? "steel_nu" : "duralumin_nu");
}

// The outputs whose uncertainty is reported.
struct OutputSpec {
  const char* name;   ///< CSV column
  const char* tag;    ///< macro name part
};
constexpr std::array<OutputSpec, 3> outputs{{{"e_effective", "Eeff"}, {"peak_force_N", "Peak"}, {"contact_time_s", "Contact"}}};
double output_value(const ImpactSummary& s, std::size_t o) {
  return o == 0 ? s.e_effective : o == 1 ? s.peak_force_N : s.contact_time_s;
}

// A rod's e about which the study draws: Table 2, or the mean of rod A's two printed values.
double restitution_centre(const RodData& rod) {
  return std::isnan(rod.restitution_second) ? rod.restitution : 0.5 * (rod.restitution + rod.restitution_second);
}

// The paper's drop from h started at contact onset with v0 = sqrt(2 g h): the free fall is exact,
// and a run with a bounded step (the band's traces) need not step through it.
DropTestSetup from_onset(DropTestSetup s) {
  s.impact_velocity_mps = std::sqrt(2 * s.gravity_mps2 * s.height_m);
  validate(s);
  return s;
}

// The set-up of one draw x (design order) for a rod.
DropTestSetup drawn_setup(const PaperParameters& paper, const RodData& rod, const std::array<double, d>& x) {
  DropTestSetup s = paper_setup(paper, rod.name, x[5]);
  s.ball.E_Pa = x[0];
  s.ball.nu = x[1];
  s.rod.nu = x[2];
  s.restitution = restitution_centre(rod) + x[3];
  s.ball_radius_m = x[4];
  s.mass_kg = rod.mass_kg + x[6];
  s.rod.E_Pa = rod.E_Pa * (1 + x[7]);
  return from_onset(s);
}

// Mean and standard deviation of a distribution from its quantile function: the midpoint rule
// in u on 2^16 points (error O(2^-32) for the smooth quantiles here; the tails of a truncated
// normal are bounded).
std::pair<double, double> distribution_moments(const InputDistribution& dist) {
  constexpr int n = 1 << 16;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < n; ++i) {
    const double x = dist.quantile((i + 0.5) / n);
    sum += x, sum2 += x * x;
  }
  const double mean = sum / n;
  return {mean, std::sqrt(std::max(0.0, sum2 / n - mean * mean))};
}

// Elasticity of output o to design slot k at the assumed set-up `s`, and the slot's CV relative
// to the assumed value of the physical parameter it moves.
struct Linearised {
  std::array<std::array<double, d>, outputs.size()> elasticity;
  std::array<double, d> cv;
};
Linearised linearise(const PaperParameters& paper, const RodData& rod, const DropTestSetup& s) {
  const PaperLawElasticities el = paper_law_elasticities(s);
  const std::array<const Elasticities*, 3> by_output{&el.e_effective_el, &el.peak_force_el, &el.contact_time_el};
  // d ln K / d ln p (eq. 3, C the compliance sum): E_s c_s/C, nu_w 2 nu_w^2/(E_w C), E_w c_w/C;
  // the rod's nu and E reach the contact only through K, as E_s does.
  const double c_s = (1 - s.ball.nu * s.ball.nu) / s.ball.E_Pa, c_w = (1 - s.rod.nu * s.rod.nu) / s.rod.E_Pa;
  const double via_K_nu_w = (2 * s.rod.nu * s.rod.nu / s.rod.E_Pa) / c_s, via_K_E_w = c_w / c_s;
  Linearised lin{};
  for (std::size_t o = 0; o < outputs.size(); ++o) {
    const Elasticities& e = *by_output[o];
    lin.elasticity[o] = {e[p_ball_E], e[p_ball_nu], e[p_ball_E] * via_K_nu_w, e[p_restitution],
                         e[p_radius], e[p_height],  e[p_mass],               e[p_ball_E] * via_K_E_w};
  }
  // The assumed value of each slot's parameter (deviations: of the tabled value they move).
  const std::array<double, d> value{s.ball.E_Pa, s.ball.nu, s.rod.nu, s.restitution, s.ball_radius_m,
                                    s.height_m,  s.mass_kg, 1.0};
  for (std::size_t k = 0; k < d; ++k) lin.cv[k] = distribution_moments(slot_input(paper, rod.name, k).distribution).second / value[k];
  return lin;
}

// Text for LaTeX: the special characters escaped (latex_escaped), "+-" as a plus-minus sign,
// | in math (OT1 text has none).
std::string latex_text(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.compare(i, 2, "+-") == 0) {
      out += "$\\pm$";
      ++i;
    } else if (s[i] == '|') {
      out += "$|$";
    } else {
      out += latex_escaped(std::string_view(s).substr(i, 1));
    }
  }
  return out;
}

// A number for LaTeX math: 1.2e+09 -> 1.2\times 10^{9}.
std::string latex_number(double v) {
  const std::string s = fmt::format("{:g}", v);
  const auto e = s.find('e');
  if (e == std::string::npos) return s;
  return s.substr(0, e) + "\\times 10^{" + std::to_string(std::stoi(s.substr(e + 1))) + "}";
}

// A distribution in the article's short form: U(min, max), N(mean, sd), LN(median, sd of ln X),
// with "on [lower, upper]" for a truncation.
std::string latex_distribution(const InputDistribution& dist) {
  switch (dist.kind) {
    case DistributionKind::uniform: return fmt::format("$\\mathcal{{U}}({}, {})$", latex_number(dist.p1), latex_number(dist.p2));
    case DistributionKind::normal: {
      std::string s = fmt::format("$\\mathcal{{N}}({}, {})$", latex_number(dist.p1), latex_number(dist.p2));
      if (std::isfinite(dist.lower) || std::isfinite(dist.upper)) s += fmt::format(" on $[{}, {}]$", latex_number(dist.lower), latex_number(dist.upper));
      return s;
    }
    case DistributionKind::lognormal: {
      std::string s = fmt::format("$\\ln\\mathcal{{N}}({}, {})$", latex_number(std::exp(dist.p1)), latex_number(dist.p2));
      if (dist.lower > 0 || std::isfinite(dist.upper)) s += fmt::format(" on $[{}, {}]$", latex_number(dist.lower), latex_number(dist.upper));
      return s;
    }
  }
  return describe(dist);
}

struct Sizes {
  std::size_t n, n_band, grid, replicates;
};

// The five panels of one figure: pointwise quantiles of the histories, the paper's model at
// the assumed values, and the loops of three representative runs.
void write_band_figure(const std::string& name, const RodData& rod, const PaperParameters& paper,
                       const std::vector<std::array<double, d>>& draws, const std::vector<double>& peak_force,
                       const Sizes& sizes, const Parameters& header_base, const StudyArgs& args, LatexMacros& tex,
                       const std::string& tag) {
  // The band runs: the first n_band rows of A and of B (Sobol prefixes, balanced for powers of 2).
  std::vector<std::size_t> rows;
  for (std::size_t j = 0; j < sizes.n_band; ++j) rows.push_back(j);
  for (std::size_t j = 0; j < sizes.n_band; ++j) rows.push_back(sizes.n + j);
  const DropTestSetup nominal = from_onset(paper_setup(paper, rod.name, paper.uncertain_input("drop_height_m").value));
  const double tc_ref = undamped_hertz_impact(hertz_stiffness(nominal), nominal.mass_kg, approach_speed(nominal)).contact_time_s;
  SolverSettings solver;  // CVODE; bounded step: linear interpolation error ~ (1/400)^2 of the peak
  solver.max_step_s = tc_ref / 400.0;
  validate(solver);

  ImpactSimulator sim(solver);
  std::vector<TraceSample> trace;
  const ImpactSummary model = sim.run<HongoPaper>(nominal, &trace);
  const ImpactHistory model_history(std::move(trace), nominal.gravity_mps2);

  std::vector<ImpactHistory> histories(rows.size(), model_history);
  std::vector<double> contact(rows.size());
  parallel_sweep(rows.size(), solver, [&](ImpactSimulator& s, std::size_t r) {
    const DropTestSetup setup = drawn_setup(paper, rod, draws[rows[r]]);
    std::vector<TraceSample> t;
    const ImpactSummary summary = s.run<HongoPaper>(setup, &t);
    if (!summary.separated) throw std::runtime_error("uncertainty: a band run did not separate");
    histories[r] = ImpactHistory(std::move(t), setup.gravity_mps2);
    contact[r] = summary.contact_time_s;
  }, {.chunk = 8, .label = name + " band"});

  // The representative loops: the band runs nearest the 5th, 50th, 95th percentile of peak force.
  std::vector<double> band_peak(rows.size());
  for (std::size_t r = 0; r < rows.size(); ++r) band_peak[r] = peak_force[rows[r]];
  std::array<std::size_t, 3> loop{};
  const std::array<double, 3> loop_p{0.05, 0.50, 0.95};
  for (std::size_t q = 0; q < 3; ++q) {
    const double target = sample_quantile(band_peak, loop_p[q]);
    loop[q] = static_cast<std::size_t>(std::min_element(band_peak.begin(), band_peak.end(), [&](double a, double b) {
                                         return std::abs(a - target) < std::abs(b - target);
                                       }) - band_peak.begin());
  }

  const double longest = std::max(model.contact_time_s, *std::max_element(contact.begin(), contact.end()));
  const double t_begin = -0.05 * longest, t_end = 1.20 * longest;
  Parameters header = header_base;
  header.emplace_back("rod", rod.name);
  header.emplace_back("band", fmt::format("pointwise 5/50/95 % quantiles (Hyndman-Fan 7) over {} joint draws (the first "
                                          "{} rows of A and of B)", rows.size(), sizes.n_band));
  header.emplace_back("band_runs", std::to_string(rows.size()));
  header.emplace_back("model", "the paper's model at the assumed values of data/assumptions.csv");
  header.emplace_back("loops", "the band runs nearest the 5th, 50th, 95th percentile of peak force");
  header.emplace_back("time_origin", "contact onset of each run");
  header.emplace_back("solver", fmt::format("cvode rtol {} atol {} max_step_s {}", solver.rtol, solver.atol, solver.max_step_s));
  std::vector<std::string> columns{"t_s"};
  const std::array<std::string, 4> q_names{"force", "displacement", "accel", "velocity"};
  const std::array<std::string, 4> q_units{"N", "m", "mps2", "mps"};
  for (std::size_t q = 0; q < 4; ++q)
    for (const char* which : {"q05", "q50", "q95", "model"}) columns.push_back(q_names[q] + "_" + which + "_" + q_units[q]);
  for (const char* which : {"p05", "p50", "p95"})
    for (std::size_t q = 0; q < 2; ++q) columns.push_back("loop_" + std::string(which) + "_" + q_names[q] + "_" + q_units[q]);
  CsvWriter csv(fmt::format("hertzdash uncertainty: the band of {} of Hongo et al. ({} rod, h = 20 mm) under the joint "
                            "input uncertainty of data/assumptions.csv. displacement = rod displacement since contact "
                            "onset (= deformation x), velocity and acceleration downward positive, force compressive "
                            "positive",
                            name == "uncertainty_fig5" ? "Fig. 5" : "Fig. 6", rod.name),
                header, columns);
  std::vector<double> values(rows.size());
  for (std::size_t k = 0; k < sizes.grid; ++k) {
    const double t = t_begin + (t_end - t_begin) * static_cast<double>(k) / static_cast<double>(sizes.grid - 1);
    std::vector<CsvWriter::Cell> row{t};
    std::vector<ImpactState> states(rows.size());
    for (std::size_t r = 0; r < rows.size(); ++r) states[r] = histories[r].at(t);
    const ImpactState m = model_history.at(t);
    const std::array<double ImpactState::*, 4> field{&ImpactState::force_N, &ImpactState::displacement_m,
                                                     &ImpactState::accel_mps2, &ImpactState::velocity_mps};
    for (std::size_t q = 0; q < 4; ++q) {
      for (std::size_t r = 0; r < rows.size(); ++r) values[r] = states[r].*field[q];
      for (double p : {0.05, 0.50, 0.95}) row.emplace_back(sample_quantile(values, p));
      row.emplace_back(m.*field[q]);
    }
    for (std::size_t l : loop) {
      const ImpactState s = states[l];
      // The loop only while in contact (x >= 0); NaN elsewhere, which gnuplot leaves out.
      row.emplace_back(s.displacement_m >= 0 ? s.force_N : NAN);
      row.emplace_back(s.displacement_m >= 0 ? s.displacement_m : NAN);
    }
    csv.add_row(row);
  }
  csv.save(args.out_dir / (name + ".csv"));
  tex.add("uq" + tag + "BandRuns", static_cast<double>(rows.size()), "{:.0f}");
  tex.add("uq" + tag + "LoopPeakLowN", band_peak[loop[0]], "{:.0f}");
  tex.add("uq" + tag + "LoopPeakHighN", band_peak[loop[2]], "{:.0f}");
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const PaperParameters paper = load_paper_parameters();
  const Sizes sizes = args.reduced ? Sizes{64, 16, 121, 200}
                      : args.full  ? Sizes{65536, 2048, 401, 1000}
                                   : Sizes{4096, 512, 301, 1000};
  const double height_m = paper.uncertain_input("drop_height_m").value;
  SolverSettings solver;  // the fast path of the sweeps; rtol 1e-10 puts its error far below every effect sampled
  solver.integrator = IntegratorKind::gbs8_regularized;
  solver.rtol = 1e-10;
  validate(solver);
  const SobolOptions sobol_options{.replicates = sizes.replicates, .confidence = 0.95, .seed = 17};

  Parameters header = all_rods_parameters(paper, solver, height_m, {"ball_E_Pa", "ball_nu", "ball_radius_m", "height_m"});
  header.emplace_back("design", fmt::format("Saltelli: N = {} rows of A and B and A_B^(i) from a {}-dimensional Sobol "
                                            "sequence (sample_design.hpp), d = {} inputs, N (d + 2) = {} runs per rod",
                                            sizes.n, 2 * d, d, sizes.n * (d + 2)));
  header.emplace_back("inputs", "independent, distributions of data/assumptions.csv (see uncertainty_inputs.csv)");
  header.emplace_back("restitution_centre", "Table 2 e; rod A: the mean of its two printed values");
  header.emplace_back("sobol", fmt::format("first order Saltelli 2010, total Jansen 1999, 95 % percentile bootstrap "
                                           "intervals over {} resamples of the N rows, seed {}",
                                           sobol_options.replicates, sobol_options.seed));
  LatexMacros tex("hertzdash uncertainty: the paper's results under joint input uncertainty (validation/uncertainty)",
                  {{"N", std::to_string(sizes.n)}, {"reduced", args.reduced ? "true" : "false"},
                   {"full", args.full ? "true" : "false"}});
  tex.add("uqN", static_cast<double>(sizes.n), "{:.0f}");
  tex.add("uqInputs", static_cast<double>(d), "{:.0f}");
  tex.add("uqRunsPerRod", static_cast<double>(sizes.n * (d + 2)), "{:.0f}");
  tex.add("uqReplicates", static_cast<double>(sizes.replicates), "{:.0f}");
  tex.add("uqHeightMm", 1e3 * height_m, "{:.0f}");
  tex.add("uqRodARestitution", paper.rod("duralumin-a").restitution, "{:.3f}");
  tex.add("uqRodARestitutionSecond", paper.rod("duralumin-a").restitution_second, "{:.3f}");
  tex.add("uqRestitutionSd", paper.uncertain_input("restitution_deviation").distribution.p2, "{:.4f}");
  tex.add("uqNylonRangeRatio", paper.ball.E_max_Pa / paper.ball.E_min_Pa, "{:.1f}");

  // The inputs as stated, for the reader and the article.
  CsvWriter inputs_csv("hertzdash uncertainty: the distributions of the jointly drawn inputs (data/assumptions.csv)",
                       header, {"parameter", "unit", "assumed_value", "distribution", "mean", "sd", "reason"});
  std::string inputs_table = "{\\footnotesize\\begin{tabularx}{\\textwidth}{@{}llX@{}}\n\\toprule\n"
                             "input [unit] & distribution & why\\\\\n\\midrule\n";
  for (const UncertainInput& in : paper.uncertain_inputs) {
    const auto [mean, sd] = distribution_moments(in.distribution);
    inputs_csv.add_row({in.parameter, in.unit, in.value, describe(in.distribution), mean, sd, in.reason});
    inputs_table += fmt::format("\\texttt{{{}}} [{}] & {} & {}\\\\\n", latex_text(in.parameter), latex_text(in.unit),
                                latex_distribution(in.distribution), latex_text(in.reason));
  }
  inputs_table += "\\bottomrule\n\\end{tabularx}}\n";

  CsvWriter outputs_csv("hertzdash uncertainty: e_effective, peak force and contact time per rod under the joint input "
                        "uncertainty: quantiles over the 2N draws of A and B, and the spread the linearisation predicts",
                        header,
                        {"rod", "output", "assumed_value", "mean", "sd", "q05", "q50", "q95", "sample_cv", "linear_cv"});
  CsvWriter sobol_csv("hertzdash uncertainty: first-order (S) and total (ST) Sobol indices with 95 % bootstrap "
                      "intervals, and the first-order variance share of the linearisation el^2 CV^2 / sum",
                      header,
                      {"rod", "output", "input", "S", "S_lower", "S_upper", "ST", "ST_lower", "ST_upper", "elasticity",
                       "input_cv", "linear_share"});
  std::string sobol_table;
  // Over all rods, outputs and inputs: the largest |ST - linear share|, the shares outside their S's
  // interval, the widest interval.
  double largest_gap = 0, widest_interval = 0;
  double minor_total = 0;  // the largest S_T of the rod's nu and E, R and m
  double through_K_gap = 0;  // the largest |S_T / share - 1| of the rod's nu and E (peak force, contact time)
  int shares_outside = 0, indices = 0;

  const std::vector<double> unit = saltelli_unit_points(SampleMethod::sobol, sizes.n, d, 0);
  const std::size_t runs = sizes.n * (d + 2);
  for (const RodData& rod : paper.rods) {
    const std::string rod_tag = rod_macro_tag(rod.name);
    std::vector<std::array<double, d>> draws(runs);
    for (std::size_t r = 0; r < runs; ++r)
      for (std::size_t k = 0; k < d; ++k) draws[r][k] = slot_input(paper, rod.name, k).distribution.quantile(unit[r * d + k]);
    std::array<std::vector<double>, outputs.size()> y;
    for (auto& v : y) v.resize(runs);
    parallel_sweep(runs, solver, [&](ImpactSimulator& sim, std::size_t r) {
      const DropTestSetup s = drawn_setup(paper, rod, draws[r]);
      const ImpactSummary summary = sim.run<HongoPaper>(s);
      if (!summary.separated) throw std::runtime_error("uncertainty: a run of rod " + rod.name + " did not separate");
      for (std::size_t o = 0; o < outputs.size(); ++o) y[o][r] = output_value(summary, o);
    }, {.label = "uncertainty " + rod.name});

    const DropTestSetup tabled = paper_setup(paper, rod.name, height_m);  // free fall from h, for the elasticities
    validate(tabled);
    const DropTestSetup assumed = from_onset(tabled);
    const ImpactSummary at_assumed = ImpactSimulator(solver).run<HongoPaper>(assumed);
    const Linearised lin = linearise(paper, rod, tabled);
    std::array<std::string, d> table_rows;  // the article's table (steel rod): S, ST, linear share per output
    for (std::size_t o = 0; o < outputs.size(); ++o) {
      const std::vector<double> joint(y[o].begin(), y[o].begin() + static_cast<std::ptrdiff_t>(2 * sizes.n));
      const SobolIndices si = sobol_indices(y[o], sizes.n, d, sobol_options);
      double linear_var = 0;
      for (std::size_t k = 0; k < d; ++k) linear_var += std::pow(lin.elasticity[o][k] * lin.cv[k], 2);
      const double sd = std::sqrt(si.variance);
      const std::array<double, 3> q{sample_quantile(joint, 0.05), sample_quantile(joint, 0.50), sample_quantile(joint, 0.95)};
      outputs_csv.add_row({rod.name, std::string(outputs[o].name), output_value(at_assumed, o), si.mean, sd, q[0], q[1], q[2],
                           sd / si.mean, std::sqrt(linear_var)});
      const std::string t = "uq" + rod_tag + outputs[o].tag;
      const double scale = o == 0 ? 1.0 : o == 1 ? 1.0 : 1e3;  // contact time in ms
      const char* spec = o == 0 ? "{:.3f}" : o == 1 ? "{:.0f}" : "{:.3f}";
      tex.add(t + "Qfive", scale * q[0], spec);
      tex.add(t + "Qfifty", scale * q[1], spec);
      tex.add(t + "Qninetyfive", scale * q[2], spec);
      tex.add(t + "SampleCvPct", 100 * sd / si.mean, "{:.1f}");
      tex.add(t + "LinearCvPct", 100 * std::sqrt(linear_var), "{:.1f}");
      double sum_first = 0, sum_total = 0;
      for (std::size_t k = 0; k < d; ++k) {
        const double share = std::pow(lin.elasticity[o][k] * lin.cv[k], 2) / linear_var;
        const IndexEstimate& S = si.first[k];
        const IndexEstimate& ST = si.total[k];
        sum_first += S.value;
        sum_total += ST.value;
        sobol_csv.add_row({rod.name, std::string(outputs[o].name), slot_input(paper, rod.name, k).parameter, S.value, S.lower, S.upper,
                           ST.value, ST.lower, ST.upper, lin.elasticity[o][k], lin.cv[k], share});
        largest_gap = std::max(largest_gap, std::abs(ST.value - share));
        shares_outside += share < S.lower || share > S.upper;
        const std::string tag = slots[k].tag;
        if (tag == "RodNu" || tag == "RodE" || tag == "Radius" || tag == "Mass") minor_total = std::max(minor_total, ST.value);
        if ((tag == "RodNu" || tag == "RodE") && o > 0) through_K_gap = std::max(through_K_gap, std::abs(ST.value / share - 1));
        ++indices;
        widest_interval = std::max({widest_interval, S.upper - S.lower, ST.upper - ST.lower});
        tex.add(t + "S" + slots[k].tag, S.value, "{:.2f}");
        tex.add(t + "SHalfWidth" + slots[k].tag, 0.5 * (S.upper - S.lower), "{:.3f}");
        tex.add(t + "ST" + slots[k].tag, ST.value, "{:.4f}");
        tex.add(t + "Lin" + slots[k].tag, share, "{:.4f}");
        table_rows[k] += fmt::format(" & ${:.3f}$ & ${:.4f}$ & ${:.4f}$", S.value, ST.value, share);
      }
      tex.add(t + "SumFirst", sum_first, "{:.3f}");
      tex.add(t + "SumTotal", sum_total, "{:.3f}");
    }
    if (rod.name == "steel" || rod.name == "duralumin-c") {
      // The band figure needs the draws and peak forces of A and B; the runs are repeated with a trace.
      const bool five = rod.name == "steel";
      write_band_figure(five ? "uncertainty_fig5" : "uncertainty_fig6", rod, paper, draws, y[1], sizes, header, args,
                        tex, five ? "Five" : "Six");
    }
    if (rod.name == "steel") {
      sobol_table = "\\begin{tabular}{lrrrrrrrrr}\n\\toprule\n"
                    "& \\multicolumn{3}{c}{$e_\\mathrm{eff}$} & \\multicolumn{3}{c}{$P_\\mathrm{max}$} & "
                    "\\multicolumn{3}{c}{$t_c$}\\\\\n\\cmidrule(lr){2-4}\\cmidrule(lr){5-7}\\cmidrule(lr){8-10}\n"
                    "input & $S_i$ & $S_{Ti}$ & lin. & $S_i$ & $S_{Ti}$ & lin. & $S_i$ & $S_{Ti}$ & lin.\\\\\n\\midrule\n";
      for (std::size_t k = 0; k < d; ++k) sobol_table += slots[k].symbol + table_rows[k] + "\\\\\n";
      sobol_table += "\\bottomrule\n\\end{tabular}\n";
    }
    std::cout << fmt::format("uncertainty: {} done ({} runs)\n", rod.name, runs);
  }
  tex.add_text("uqLargestTotalLinearGap", latex_scientific(largest_gap));
  tex.add("uqSharesOutsideFirstInterval", shares_outside, "{:.0f}");
  tex.add("uqIndexCount", indices, "{:.0f}");
  tex.add_text("uqMinorLargestTotal", latex_scientific(minor_total));
  tex.add("uqRodThroughKShareGapPct", 100 * through_K_gap, "{:.0f}");
  tex.add("uqWidestInterval", widest_interval, "{:.3f}");

  inputs_csv.save(args.out_dir / "uncertainty_inputs.csv");
  outputs_csv.save(args.out_dir / "uncertainty_outputs.csv");
  sobol_csv.save(args.out_dir / "uncertainty_sobol.csv");
  tex.save(args.generated_dir / "uncertainty.tex");
  std::string provenance = provenance_header("uncertainty tables (validation/uncertainty)", header);
  std::replace(provenance.begin(), provenance.end(), '#', '%');
  write_file_atomically(args.generated_dir / "uncertainty_inputs_table.tex", provenance + inputs_table);
  write_file_atomically(args.generated_dir / "uncertainty_sobol_table.tex", provenance + sobol_table);
  std::cout << "uncertainty: written to " << args.out_dir.string() << " and " << args.generated_dir.string() << "\n";
  return 0;
} catch (const std::exception& e) {
  return study_failed(argv[0], e);
}
