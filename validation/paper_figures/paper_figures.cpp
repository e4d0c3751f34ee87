// Figs. 5 and 6 of Hongo et al.: the rod falls h = 20 mm onto the nylon hemisphere;
// five panels each: (a) force, (b) displacement, (c) hysteresis loop force vs
// displacement, (d) acceleration, (e) velocity, for the steel rod (Fig. 5) and
// duralumin rod C (Fig. 6).
//
// The paper compares its model with measured traces, which it printed only as plots
// (no machine-readable copy exists), so what can be reproduced is the model side, and
// how much of it is fixed by the data: the one input the paper leaves open inside a
// stated range is the nylon modulus (catalogue 1.2-2.9 GPa, Table 3). So each panel shows
//   - the paper's model (law "hongo", CVODE, default parameters: nylon E = 2.0 GPa),
//   - a band: the envelope (min, max at each instant) of the same model over nylon
//     E in the catalogue range,
//   - the undamped Hertz response (law "none") as a reference line,
//   - any measured trace found in data/measurements/ for that rod and height
//     (format: data/measurements/README.md). None ships.
// All runs are put on one time grid measured from contact onset (ImpactHistory):
// the contact times differ across the band (t_c ~ K^{-2/5}), so the grid runs past
// the longest one and each run continues in free flight after its separation.
//
// Writes: OUT/fig5.csv, OUT/fig6.csv (exactly what fig5.gp and fig6.gp plot),
// OUT/fig5_measured_<k>.csv / fig6_measured_<k>.csv if measured traces exist,
// GENERATED/paper_figures.tex (macros \figs...).
#include "hertzdash/io/csv_writer.hpp"
#include "validation/common/latex_macros.hpp"
#include "hertzdash/io/measured_trace.hpp"
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/damping/laws/undamped.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_history.hpp"
#include "validation/common/study_args.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <limits>

using namespace hertzdash;

namespace {

constexpr double drop_height_m = 0.020;

struct FigureSpec {
  std::string name;  ///< fig5, fig6
  std::string rod;   ///< Table 1 rod
  std::string tag;   ///< macro tag: Five, Six
};

// A run of one law with the trace kept, as a function of time since onset.
template <DampingLaw Law>
std::pair<ImpactSummary, ImpactHistory> run_history(ImpactSimulator& sim, const DropTestSetup& setup) {
  std::vector<TraceSample> trace;
  const ImpactSummary s = sim.run<Law>(setup, &trace);
  if (!s.separated) throw std::runtime_error("paper_figures: the rod did not separate");
  return {s, ImpactHistory(std::move(trace), setup.gravity_mps2)};
}

void write_figure(const FigureSpec& fig, const PaperParameters& paper, const StudyArgs& args, LatexMacros& macros) {
  const DropTestSetup setup = paper_setup(paper, fig.rod, drop_height_m);
  validate(setup);

  // Step bound: the interpolation error of ImpactHistory is O(dt^2 |x''|); with
  // 2000 steps per undamped contact time it is ~1e-7 of the peak, far below a pixel.
  const double tc_ref = undamped_hertz_impact(hertz_stiffness(setup), setup.mass_kg, approach_speed(setup)).contact_time_s;
  SolverSettings solver;
  solver.max_step_s = tc_ref / (args.reduced ? 200.0 : 2000.0);
  validate(solver);
  ImpactSimulator sim(solver);

  // The paper's model at the default parameters, the Hertz reference, and the band.
  const auto [model, model_history] = run_history<HongoPaper>(sim, setup);
  const auto [hertz, hertz_history] = run_history<Undamped>(sim, setup);
  const int band_runs = args.reduced ? 3 : 9;  // nylon E evenly over the catalogue range, ends included
  std::vector<ImpactSummary> band;
  std::vector<ImpactHistory> band_history;
  for (int i = 0; i < band_runs; ++i) {
    DropTestSetup s = setup;
    s.ball.E_Pa = paper.ball.E_min_Pa + (paper.ball.E_max_Pa - paper.ball.E_min_Pa) * i / (band_runs - 1);
    auto [summary, history] = run_history<HongoPaper>(sim, s);
    band.push_back(summary);
    band_history.push_back(std::move(history));
  }

  // Common grid: from 5 % of the longest contact before onset to 20 % after it.
  double longest = model.contact_time_s;
  for (const auto& b : band) longest = std::max(longest, b.contact_time_s);
  const int samples = args.reduced ? 120 : 801;
  const double t_begin = -0.05 * longest, t_end = 1.20 * longest;

  Parameters header = describe_run(setup, "hongo", solver);
  header.emplace_back("band", fmt::format("min/max over {} runs with ball_E_Pa evenly spaced in the range below",
                                          band_runs));
  header.emplace_back("band_ball_E_min_Pa", fmt::format("{}", paper.ball.E_min_Pa));
  header.emplace_back("band_ball_E_max_Pa", fmt::format("{}", paper.ball.E_max_Pa));
  header.emplace_back("reference", "law none (undamped Hertz), same parameters");
  header.emplace_back("time_origin", "contact onset of each run");
  CsvWriter csv(fmt::format("hertzdash paper_figures: {} of Hongo et al. reproduced ({} rod, h = {} m): model, "
                            "nylon-modulus band, undamped Hertz reference. displacement = rod displacement since "
                            "contact onset (= deformation x), velocity and acceleration of the rod downward "
                            "positive, force compressive positive",
                            fig.name, fig.rod, drop_height_m),
                header,
                {"t_s", "force_N", "force_min_N", "force_max_N", "force_hertz_N", "displacement_m",
                 "displacement_min_m", "displacement_max_m", "displacement_hertz_m", "accel_mps2", "accel_min_mps2",
                 "accel_max_mps2", "accel_hertz_mps2", "velocity_mps", "velocity_min_mps", "velocity_max_mps",
                 "velocity_hertz_mps", "displacement_Emin_m", "force_Emin_N", "displacement_Emax_m", "force_Emax_N"});
  for (int k = 0; k < samples; ++k) {
    const double t = t_begin + (t_end - t_begin) * k / (samples - 1);
    const ImpactState m = model_history.at(t), h = hertz_history.at(t);
    ImpactState lo{+INFINITY, +INFINITY, +INFINITY, +INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY, -INFINITY};
    for (const auto& b : band_history) {
      const ImpactState s = b.at(t);
      lo = {std::min(lo.displacement_m, s.displacement_m), std::min(lo.velocity_mps, s.velocity_mps),
            std::min(lo.accel_mps2, s.accel_mps2), std::min(lo.force_N, s.force_N)};
      hi = {std::max(hi.displacement_m, s.displacement_m), std::max(hi.velocity_mps, s.velocity_mps),
            std::max(hi.accel_mps2, s.accel_mps2), std::max(hi.force_N, s.force_N)};
    }
    const ImpactState e_min = band_history.front().at(t), e_max = band_history.back().at(t);
    csv.add_row({t, m.force_N, lo.force_N, hi.force_N, h.force_N, m.displacement_m, lo.displacement_m,
                 hi.displacement_m, h.displacement_m, m.accel_mps2, lo.accel_mps2, hi.accel_mps2, h.accel_mps2,
                 m.velocity_mps, lo.velocity_mps, hi.velocity_mps, h.velocity_mps, e_min.displacement_m,
                 e_min.force_N, e_max.displacement_m, e_max.force_N});
  }
  csv.save(args.out_dir / (fig.name + ".csv"));

  // Measured traces, if any: copied beside the figure in the model's units and origin.
  namespace fs = std::filesystem;
  for (const auto& old : fs::directory_iterator(args.out_dir))
    if (old.path().filename().string().starts_with(fig.name + "_measured_")) fs::remove(old.path());
  const auto measured = find_measured_traces(default_data_dir() / "measurements", fig.rod, drop_height_m);
  for (std::size_t i = 0; i < measured.size(); ++i) {
    const MeasuredTrace& m = measured[i];
    CsvWriter out(fmt::format("measured trace for {} ({}), copied from {}{}", fig.name, fig.rod, m.path.string(),
                              m.synthetic ? " -- SYNTHETIC, not a measurement" : ""),
                  {{"source", m.source}, {"synthetic", m.synthetic ? "true" : "false"}},
                  {"t_s", "force_N", "accel_mps2", "velocity_mps", "displacement_m"});
    auto value = [](const std::vector<double>& v, std::size_t r) { return v.empty() ? NAN : v[r]; };
    for (std::size_t r = 0; r < m.t_s.size(); ++r)
      out.add_row({m.t_s[r], value(m.force_N, r), value(m.accel_mps2, r), value(m.velocity_mps, r),
                   value(m.displacement_m, r)});
    out.save(args.out_dir / fmt::format("{}_measured_{}.csv", fig.name, i + 1));
  }

  // Numbers for the reproduction section.
  auto range = [&](const std::string& name, auto get, double scale, const char* spec) {
    double lo = +INFINITY, hi = -INFINITY;
    for (const auto& b : band) lo = std::min(lo, get(b)), hi = std::max(hi, get(b));
    macros.add("figs" + fig.tag + name, scale * get(model), spec);
    macros.add("figs" + fig.tag + name + "Min", scale * lo, spec);
    macros.add("figs" + fig.tag + name + "Max", scale * hi, spec);
    macros.add("figs" + fig.tag + name + "Hertz", scale * get(hertz), spec);
  };
  range("PeakForceN", [](const ImpactSummary& s) { return s.peak_force_N; }, 1.0, "{:.0f}");
  range("MaxDisplacementMicrometre", [](const ImpactSummary& s) { return s.max_deformation_m; }, 1e6, "{:.0f}");
  range("ContactTimeMs", [](const ImpactSummary& s) { return s.contact_time_s; }, 1e3, "{:.3f}");
  range("RestitutionEffective", [](const ImpactSummary& s) { return s.e_effective; }, 1.0, "{:.3f}");
  // The rod's acceleration is g - P/m (downward positive): its deepest value, at the peak
  // force, is a deceleration of P_max/m - g, here in units of g.
  range("PeakDecelerationG", [&](const ImpactSummary& s) { return s.peak_force_N / setup.mass_kg / setup.gravity_mps2 - 1; },
        1.0, "{:.1f}");
  macros.add("figs" + fig.tag + "RestitutionInput", setup.restitution, "{:.3f}");
  macros.add("figs" + fig.tag + "ImpactVelocityMps", model.impact_velocity_mps, "{:.3f}");
  macros.add("figs" + fig.tag + "ReboundVelocityMps", model.rebound_velocity_mps, "{:.3f}");
  macros.add("figs" + fig.tag + "MassKg", setup.mass_kg, "{:.3f}");
  macros.add("figs" + fig.tag + "MeasuredTraces", static_cast<double>(measured.size()), "{:.0f}");
  macros.add("figs" + fig.tag + "SyntheticTraces",
             static_cast<double>(std::count_if(measured.begin(), measured.end(),
                                               [](const MeasuredTrace& m) { return m.synthetic; })),
             "{:.0f}");

  // Where the force peaks relative to the deepest compression: the dashpot adds to
  // the force while compressing, so the damped peak comes first.
  // The least force over the contact: negative means the law pulls (tension) before separation.
  double t_peak = 0, t_deepest = 0, peak = -INFINITY, deepest = -INFINITY, least = INFINITY;
  for (int k = 0; k < 20001; ++k) {
    const double t = model.contact_time_s * k / 20000.0;
    const ImpactState s = model_history.at(t);
    if (s.force_N > peak) peak = s.force_N, t_peak = t;
    if (s.displacement_m > deepest) deepest = s.displacement_m, t_deepest = t;
    least = std::min(least, s.force_N);
  }
  macros.add("figs" + fig.tag + "LeastForceN", least, "{:.1f}");
  macros.add("figs" + fig.tag + "LeastForcePercent", 100.0 * least / model.peak_force_N, "{:.1f}");
  macros.add("figs" + fig.tag + "PeakForceLeadMs", 1e3 * (t_deepest - t_peak), "{:.3f}");
  macros.add("figs" + fig.tag + "PeakForceLeadPercent", 100.0 * (t_deepest - t_peak) / model.contact_time_s, "{:.1f}");

  std::cout << fmt::format("{} ({}): peak force {:.1f} N (nylon E min {:.1f}, max {:.1f}; Hertz {:.1f}), max displacement {:.1f} um, "
                           "contact time {:.4f} ms, e_eff {:.4f} (input {}), {} measured trace(s)\n",
                           fig.name, fig.rod, model.peak_force_N, band.front().peak_force_N, band.back().peak_force_N,
                           hertz.peak_force_N, 1e6 * model.max_deformation_m, 1e3 * model.contact_time_s,
                           model.e_effective, setup.restitution, measured.size());
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const PaperParameters paper = load_paper_parameters();
  LatexMacros macros("hertzdash paper_figures: Figs. 5 and 6 of Hongo et al. reproduced (model side)",
                     {{"height_m", fmt::format("{}", drop_height_m)}, {"reduced", args.reduced ? "true" : "false"}});
  macros.add("figsNylonEminGPa", paper.ball.E_min_Pa / 1e9, "{:.1f}");
  macros.add("figsNylonEmaxGPa", paper.ball.E_max_Pa / 1e9, "{:.1f}");
  macros.add("figsNylonEdefaultGPa", paper.ball.E_Pa / 1e9, "{:.1f}");
  macros.add("figsHeightMm", 1e3 * drop_height_m, "{:.0f}");
  for (const FigureSpec& fig : {FigureSpec{"fig5", "steel", "Five"}, FigureSpec{"fig6", "duralumin-c", "Six"}})
    write_figure(fig, paper, args, macros);
  macros.save(args.generated_dir / "paper_figures.tex");
  return 0;
} catch (const std::exception& e) {
  return study_failed(argv[0], e);
}
