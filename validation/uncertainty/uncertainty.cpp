// The paper's results under its joint input uncertainty: bands of Figs. 5 and 6, and which
// input the uncertainty of each result comes from (Sobol indices), beside the linearisation.
//
// What it reproduces and why. The paper leaves inputs unstated (the nylon modulus within a
// catalogue range 1.2-2.9 GPa, every Poisson ratio) and gives others as single measurements
// (e, whose one repeat, rod A at 0.828 and 0.834, shows a scatter; the masses and the drop
// height to the printed digits). The other studies vary them one at a time (paper_figures: the
// nylon modulus band; elasticities: derivatives at one point). Here they are drawn jointly,
// each from the distribution data/assumptions.csv states with its reason
// (simulation/uncertainty/uncertain_inputs.hpp), independent of each other:
//   nylon E, nylon nu, the rod's nu, e (Table 2 + deviation), R, h, m (Table 1 + deviation),
//   the rod's E (Table 3 x (1 + deviation)).
// For every rod at the paper's h = 20 mm the paper's model (law "hongo") runs on the rows of a
// Saltelli design (validation/common/sobol_indices.hpp: N rows each of A, B and the d matrices
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
#include "validation/common/latex_macros.hpp"
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "validation/common/paper_law_elasticities.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_history.hpp"
#include "hertzdash/simulation/sweep/parallel_sweep.hpp"
#include "hertzdash/simulation/uncertainty/sample_quantile.hpp"
#include "validation/common/sobol_indices.hpp"
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

// ---- The study's set-up.

struct Sizes {
  std::size_t n;           ///< rows N of each of A and B
  std::size_t n_band;      ///< band runs from each of A and B
  std::size_t grid;        ///< time points of the band CSV
  std::size_t replicates;  ///< bootstrap resamples of the Sobol intervals
};

// The sample sizes of --reduced (the pipeline test), `make figures` and --full.
Sizes sizes_for(const StudyArgs& args) {
  return args.reduced ? Sizes{64, 16, 121, 200} : args.full ? Sizes{65536, 2048, 401, 1000} : Sizes{4096, 512, 301, 1000};
}

// What every part of the study shares: the sizes, the drop height, the solver of the sweeps,
// the Sobol options and the provenance header of every file.
struct Study {
  Sizes sizes;
  double height_m;
  SolverSettings solver;
  SobolOptions sobol;
  Parameters header;
};

Study set_up_study(const StudyArgs& args, const PaperParameters& paper) {
  Study st{sizes_for(args), paper.uncertain_input("drop_height_m").value, {}, {}, {}};
  // The fast path of the sweeps; rtol 1e-10 puts its error far below every effect sampled.
  st.solver.integrator = IntegratorKind::gbs8_regularized;
  st.solver.rtol = 1e-10;
  validate(st.solver);
  st.sobol = SobolOptions{.replicates = st.sizes.replicates, .confidence = 0.95, .seed = 17};
  const Sizes& sizes = st.sizes;
  st.header = all_rods_parameters(paper, st.solver, st.height_m, {"ball_E_Pa", "ball_nu", "ball_radius_m", "height_m"});
  st.header.emplace_back("design", fmt::format("Saltelli: N = {} rows of A and B and A_B^(i) from a {}-dimensional Sobol "
                                               "sequence (sample_design.hpp), d = {} inputs, N (d + 2) = {} runs per rod",
                                               sizes.n, 2 * d, d, sizes.n * (d + 2)));
  st.header.emplace_back("inputs", "independent, distributions of data/assumptions.csv (see uncertainty_inputs.csv)");
  st.header.emplace_back("restitution_centre", "Table 2 e; rod A: the mean of its two printed values");
  st.header.emplace_back("sobol", fmt::format("first order Saltelli 2010, total Jansen 1999, 95 % percentile bootstrap "
                                              "intervals over {} resamples of the N rows, seed {}",
                                              st.sobol.replicates, st.sobol.seed));
  return st;
}

// The article's macros of the design: sizes, the drop height, the restitution's centre and
// spread, the nylon modulus's range.
LatexMacros design_macros(const Study& st, const StudyArgs& args, const PaperParameters& paper) {
  const Sizes& sizes = st.sizes;
  LatexMacros tex("hertzdash uncertainty: the paper's results under joint input uncertainty (validation/uncertainty)",
                  {{"N", std::to_string(sizes.n)}, {"reduced", args.reduced ? "true" : "false"},
                   {"full", args.full ? "true" : "false"}});
  tex.add("uqN", static_cast<double>(sizes.n), "{:.0f}");
  tex.add("uqInputs", static_cast<double>(d), "{:.0f}");
  tex.add("uqRunsPerRod", static_cast<double>(sizes.n * (d + 2)), "{:.0f}");
  tex.add("uqReplicates", static_cast<double>(sizes.replicates), "{:.0f}");
  tex.add("uqHeightMm", 1e3 * st.height_m, "{:.0f}");
  tex.add("uqRodARestitution", paper.rod("duralumin-a").restitution, "{:.3f}");
  tex.add("uqRodARestitutionSecond", paper.rod("duralumin-a").restitution_second, "{:.3f}");
  tex.add("uqRestitutionSd", paper.uncertain_input("restitution_deviation").distribution.p2, "{:.4f}");
  tex.add("uqNylonRangeRatio", paper.ball.E_max_Pa / paper.ball.E_min_Pa, "{:.1f}");
  return tex;
}

// A LaTeX fragment of GENERATED under the study's provenance header (as comments).
void write_latex_fragment(const StudyArgs& args, const Study& st, const std::string& file, const std::string& body) {
  std::string provenance = provenance_header("uncertainty tables (validation/uncertainty)", st.header);
  std::replace(provenance.begin(), provenance.end(), '#', '%');
  write_file_atomically(args.generated_dir / file, provenance + body);
}

// The inputs as stated, for the reader (OUT/uncertainty_inputs.csv) and the article
// (GENERATED/uncertainty_inputs_table.tex).
void write_inputs(const Study& st, const PaperParameters& paper, const StudyArgs& args) {
  CsvWriter inputs_csv("hertzdash uncertainty: the distributions of the jointly drawn inputs (data/assumptions.csv)",
                       st.header, {"parameter", "unit", "assumed_value", "distribution", "mean", "sd", "reason"});
  std::string inputs_table = "{\\footnotesize\\begin{tabularx}{\\textwidth}{@{}llX@{}}\n\\toprule\n"
                             "input [unit] & distribution & why\\\\\n\\midrule\n";
  for (const UncertainInput& in : paper.uncertain_inputs) {
    const auto [mean, sd] = distribution_moments(in.distribution);
    inputs_csv.add_row({in.parameter, in.unit, in.value, describe(in.distribution), mean, sd, in.reason});
    // The unit goes in brackets, so the name drops a unit suffix it carries ("nylon_E_Pa" -> "nylon_E").
    std::string name = in.parameter;
    if (const std::string suffix = "_" + in.unit; name.size() > suffix.size() && name.ends_with(suffix))
      name.resize(name.size() - suffix.size());
    inputs_table += fmt::format("\\texttt{{{}}} [{}] & {} & {}\\\\\n", latex_text(name), latex_text(in.unit),
                                latex_distribution(in.distribution), latex_text(in.reason));
  }
  inputs_table += "\\bottomrule\n\\end{tabularx}}\n";
  inputs_csv.save(args.out_dir / "uncertainty_inputs.csv");
  write_latex_fragment(args, st, "uncertainty_inputs_table.tex", inputs_table);
}

// ---- The runs.

// One rod's Saltelli design: the draws (design order) and the outputs of every run.
struct RodSample {
  std::vector<std::array<double, d>> draws;
  std::array<std::vector<double>, outputs.size()> y;
};

RodSample run_design(const Study& st, const PaperParameters& paper, const RodData& rod, const std::vector<double>& unit) {
  const std::size_t runs = st.sizes.n * (d + 2);
  RodSample sample{std::vector<std::array<double, d>>(runs), {}};
  for (std::size_t r = 0; r < runs; ++r)
    for (std::size_t k = 0; k < d; ++k) sample.draws[r][k] = slot_input(paper, rod.name, k).distribution.quantile(unit[r * d + k]);
  for (auto& v : sample.y) v.resize(runs);
  parallel_sweep(runs, st.solver, [&](ImpactSimulator& sim, std::size_t r) {
    const DropTestSetup s = drawn_setup(paper, rod, sample.draws[r]);
    const ImpactSummary summary = sim.run<HongoPaper>(s);
    if (!summary.separated) throw std::runtime_error("uncertainty: a run of rod " + rod.name + " did not separate");
    for (std::size_t o = 0; o < outputs.size(); ++o) sample.y[o][r] = output_value(summary, o);
  }, {.label = "uncertainty " + rod.name});
  return sample;
}

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

// ---- What the runs say.

// Over all rods, outputs and inputs.
struct Tallies {
  double largest_gap = 0;      ///< the largest |S_T - linear share|
  double widest_interval = 0;  ///< the widest bootstrap interval of S or S_T
  double minor_total = 0;      ///< the largest S_T of the rod's nu and E, R and m
  double through_K_gap = 0;    ///< the largest |S_T / share - 1| of the rod's nu and E (peak force, contact time)
  int shares_outside = 0;      ///< linear shares outside their S's interval
  int indices = 0;
};

// The study's findings: the outputs' spread and the Sobol indices (CSV), the article's Sobol
// table (steel rod) and the tallies.
struct Findings {
  CsvWriter outputs_csv, sobol_csv;
  std::string sobol_table;
  Tallies tallies;
};

Findings start_findings(const Study& st) {
  return {CsvWriter("hertzdash uncertainty: e_effective, peak force and contact time per rod under the joint input "
                    "uncertainty: quantiles over the 2N draws of A and B, and the spread the linearisation predicts",
                    st.header,
                    {"rod", "output", "assumed_value", "mean", "sd", "q05", "q50", "q95", "sample_cv", "linear_cv"}),
          CsvWriter("hertzdash uncertainty: first-order (S) and total (ST) Sobol indices with 95 % bootstrap "
                    "intervals, and the first-order variance share of the linearisation el^2 CV^2 / sum",
                    st.header,
                    {"rod", "output", "input", "S", "S_lower", "S_upper", "ST", "ST_lower", "ST_upper", "elasticity",
                     "input_cv", "linear_share"}),
          {},
          {}};
}

// Output o of one rod: its quantiles over the 2N joint draws and its spread beside the
// linearisation's; its Sobol indices beside the linear shares, each input's appended to its
// row of the article's table (`table_rows`).
void analyse_output(std::size_t o, const Study& st, const PaperParameters& paper, const RodData& rod,
                    const std::vector<double>& y, const ImpactSummary& at_assumed, const Linearised& lin,
                    Findings& f, LatexMacros& tex, std::array<std::string, d>& table_rows) {
  const std::size_t n = st.sizes.n;
  const std::vector<double> joint(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(2 * n));
  const SobolIndices si = sobol_indices(y, n, d, st.sobol);
  double linear_var = 0;
  for (std::size_t k = 0; k < d; ++k) linear_var += std::pow(lin.elasticity[o][k] * lin.cv[k], 2);
  const double sd = std::sqrt(si.variance);
  const std::array<double, 3> q{sample_quantile(joint, 0.05), sample_quantile(joint, 0.50), sample_quantile(joint, 0.95)};
  f.outputs_csv.add_row({rod.name, std::string(outputs[o].name), output_value(at_assumed, o), si.mean, sd, q[0], q[1], q[2],
                         sd / si.mean, std::sqrt(linear_var)});
  const std::string t = "uq" + rod_macro_tag(rod.name) + outputs[o].tag;
  const double scale = o == 0 ? 1.0 : o == 1 ? 1.0 : 1e3;  // contact time in ms
  const char* spec = o == 0 ? "{:.3f}" : o == 1 ? "{:.0f}" : "{:.3f}";
  tex.add(t + "Qfive", scale * q[0], spec);
  tex.add(t + "Qfifty", scale * q[1], spec);
  tex.add(t + "Qninetyfive", scale * q[2], spec);
  tex.add(t + "SampleCvPct", 100 * sd / si.mean, "{:.1f}");
  tex.add(t + "LinearCvPct", 100 * std::sqrt(linear_var), "{:.1f}");
  double sum_first = 0, sum_total = 0;
  Tallies& tally = f.tallies;
  for (std::size_t k = 0; k < d; ++k) {
    const double share = std::pow(lin.elasticity[o][k] * lin.cv[k], 2) / linear_var;
    const IndexEstimate& S = si.first[k];
    const IndexEstimate& ST = si.total[k];
    sum_first += S.value;
    sum_total += ST.value;
    f.sobol_csv.add_row({rod.name, std::string(outputs[o].name), slot_input(paper, rod.name, k).parameter, S.value, S.lower,
                         S.upper, ST.value, ST.lower, ST.upper, lin.elasticity[o][k], lin.cv[k], share});
    tally.largest_gap = std::max(tally.largest_gap, std::abs(ST.value - share));
    tally.shares_outside += share < S.lower || share > S.upper;
    const std::string tag = slots[k].tag;
    if (tag == "RodNu" || tag == "RodE" || tag == "Radius" || tag == "Mass") tally.minor_total = std::max(tally.minor_total, ST.value);
    if ((tag == "RodNu" || tag == "RodE") && o > 0) tally.through_K_gap = std::max(tally.through_K_gap, std::abs(ST.value / share - 1));
    ++tally.indices;
    tally.widest_interval = std::max({tally.widest_interval, S.upper - S.lower, ST.upper - ST.lower});
    tex.add(t + "S" + slots[k].tag, S.value, "{:.2f}");
    tex.add(t + "SHalfWidth" + slots[k].tag, 0.5 * (S.upper - S.lower), "{:.3f}");
    tex.add(t + "ST" + slots[k].tag, ST.value, "{:.4f}");
    tex.add(t + "Lin" + slots[k].tag, share, "{:.4f}");
    table_rows[k] += fmt::format(" & ${:.3f}$ & ${:.4f}$ & ${:.4f}$", S.value, ST.value, share);
  }
  tex.add(t + "SumFirst", sum_first, "{:.3f}");
  tex.add(t + "SumTotal", sum_total, "{:.3f}");
}

// One rod's sample analysed, output by output, against the linearisation at the assumed
// values; returns the rows of the article's Sobol table (S, S_T, linear share per output).
std::array<std::string, d> analyse_rod(const Study& st, const PaperParameters& paper, const RodData& rod,
                                       const RodSample& sample, Findings& f, LatexMacros& tex) {
  const DropTestSetup tabled = paper_setup(paper, rod.name, st.height_m);  // free fall from h, for the elasticities
  validate(tabled);
  const ImpactSummary at_assumed = ImpactSimulator(st.solver).run<HongoPaper>(from_onset(tabled));
  const Linearised lin = linearise(paper, rod, tabled);
  std::array<std::string, d> table_rows;
  for (std::size_t o = 0; o < outputs.size(); ++o)
    analyse_output(o, st, paper, rod, sample.y[o], at_assumed, lin, f, tex, table_rows);
  return table_rows;
}

// The article's Sobol table (GENERATED/uncertainty_sobol_table.tex) from its rows.
std::string article_sobol_table(const std::array<std::string, d>& table_rows) {
  std::string table = "\\begin{tabular}{lrrrrrrrrr}\n\\toprule\n"
                      "& \\multicolumn{3}{c}{$e_\\mathrm{eff}$} & \\multicolumn{3}{c}{$P_\\mathrm{max}$} & "
                      "\\multicolumn{3}{c}{$t_c$}\\\\\n\\cmidrule(lr){2-4}\\cmidrule(lr){5-7}\\cmidrule(lr){8-10}\n"
                      "input & $S_i$ & $S_{Ti}$ & lin. & $S_i$ & $S_{Ti}$ & lin. & $S_i$ & $S_{Ti}$ & lin.\\\\\n\\midrule\n";
  for (std::size_t k = 0; k < d; ++k) table += slots[k].symbol + table_rows[k] + "\\\\\n";
  return table + "\\bottomrule\n\\end{tabular}\n";
}

void add_tallies(const Tallies& t, LatexMacros& tex) {
  tex.add_text("uqLargestTotalLinearGap", latex_scientific(t.largest_gap));
  tex.add("uqSharesOutsideFirstInterval", t.shares_outside, "{:.0f}");
  tex.add("uqIndexCount", t.indices, "{:.0f}");
  tex.add_text("uqMinorLargestTotal", latex_scientific(t.minor_total));
  tex.add("uqRodThroughKShareGapPct", 100 * t.through_K_gap, "{:.0f}");
  tex.add("uqWidestInterval", t.widest_interval, "{:.3f}");
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const PaperParameters paper = load_paper_parameters();
  const Study st = set_up_study(args, paper);
  LatexMacros tex = design_macros(st, args, paper);
  write_inputs(st, paper, args);

  Findings findings = start_findings(st);
  const std::vector<double> unit = saltelli_unit_points(SampleMethod::sobol, st.sizes.n, d, 0);
  for (const RodData& rod : paper.rods) {
    const RodSample sample = run_design(st, paper, rod, unit);
    const std::array<std::string, d> table_rows = analyse_rod(st, paper, rod, sample, findings, tex);
    // The band figures need the draws and peak forces of A and B; their runs are repeated with a trace.
    if (rod.name == "steel")
      write_band_figure("uncertainty_fig5", rod, paper, sample.draws, sample.y[1], st.sizes, st.header, args, tex, "Five");
    if (rod.name == "duralumin-c")
      write_band_figure("uncertainty_fig6", rod, paper, sample.draws, sample.y[1], st.sizes, st.header, args, tex, "Six");
    if (rod.name == "steel") findings.sobol_table = article_sobol_table(table_rows);
    std::cout << fmt::format("uncertainty: {} done ({} runs)\n", rod.name, sample.draws.size());
  }
  add_tallies(findings.tallies, tex);

  findings.outputs_csv.save(args.out_dir / "uncertainty_outputs.csv");
  findings.sobol_csv.save(args.out_dir / "uncertainty_sobol.csv");
  tex.save(args.generated_dir / "uncertainty.tex");
  write_latex_fragment(args, st, "uncertainty_sobol_table.tex", findings.sobol_table);
  std::cout << "uncertainty: written to " << args.out_dir.string() << " and " << args.generated_dir.string() << "\n";
  return 0;
} catch (const std::exception& e) {
  return study_failed(argv[0], e);
}
