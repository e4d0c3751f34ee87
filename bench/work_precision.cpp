// Work-precision benchmark: hertzdash's integrators against Boost.Odeint, GSL and
// naive CVODE at equal accuracy, and the throughput of a parallel sweep and of the shaker.
//
// Workloads (the paper's steel case, h = 20 mm, every other parameter at its
// default): "contact", the contact phase alone, started at onset with the free-fall
// speed sqrt(2 g h) and gravity kept; "drop", the free fall from rest, the contact
// and the separation. Accuracy is |e_eff - e_ref|, e_eff the effective restitution
// (rebound over approach speed at separation). e_ref is the mean of two independent
// methods at tolerance 1e-13 -- hertzdash's Dormand-Prince 5(4) with events landed
// on, and GSL's rk8pd (order 8) with a Hermite crossing -- whose difference is
// printed and written as \perfReferenceAgreement...; it is far below the errors
// measured at the tolerances compared (1e-4 to 1e-10).
//
// Timing: for each solver and tolerance, one untimed impact gives the error and the
// right-hand-side evaluations (every impact of a workload is identical); then
// `repeats` timed runs of as many impacts as fill `budget_ms` each; the median of
// the per-impact times is reported. No test asserts any of these times.
#include "bench/work_precision.hpp"

#include "bench/impact_solvers.hpp"
#include "hertzdash/integrators/dormand_prince.hpp"
#include "hertzdash/integrators/taylor.hpp"
#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/csv_writer.hpp"
#include "validation/common/latex_macros.hpp"
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/damping/laws/undamped.hpp"
#include "validation/common/regularized_contact_singularities.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"
#include "hertzdash/simulation/sweep/parallel_sweep.hpp"
#include "hertzdash/simulation/uncertainty/sample_quantile.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace hertzdash::bench {

namespace {

using Clock = std::chrono::steady_clock;

struct Workload {
  std::string name;     ///< contact, drop
  std::string tag;      ///< for macro names: Contact, Drop
  DropTestSetup setup;
};

/// Who wrote the solver: hertzdash, or a peer library on the physical or on the
/// regularised variables (bench/impact_solvers.hpp).
enum class Group { hertzdash, physical_peer, regularized_peer };

struct SolverSpec {
  std::string name;  ///< CSV spelling, e.g. hertzdash-dopri5
  Group group;
  bool adaptive;     ///< tolerance-driven (else the "tolerance" column is the step [s])
  std::function<std::unique_ptr<ImpactSolver>(double)> make;
};

struct Point {
  std::string solver;
  double tolerance;
  double abs_error;
  long rhs_evaluations;
  double us_per_impact;
};

std::string machine_name() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(" \t", colon + 1));
    }
  }
  return "unknown CPU";
}

/// Median wall time per impact [us] of `solver` on `setup`.
double time_per_impact_us(ImpactSolver& solver, const DropTestSetup& setup, const WorkPrecisionConfig& c) {
  // Calibrate the number of impacts per repeat on one timed impact.
  auto t0 = Clock::now();
  double sink = solver.run(setup).e_effective;
  const double one_s = std::chrono::duration<double>(Clock::now() - t0).count();
  const long n = std::max(1L, static_cast<long>(c.budget_ms * 1e-3 / std::max(one_s, 1e-9)));
  std::vector<double> per_impact_us;
  for (int r = 0; r < c.repeats; ++r) {
    t0 = Clock::now();
    for (long i = 0; i < n; ++i) sink += solver.run(setup).e_effective;
    per_impact_us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - t0).count() / static_cast<double>(n));
  }
  if (!std::isfinite(sink)) throw std::runtime_error("benchmark: non-finite restitution");
  return sample_quantile(per_impact_us, 0.5);
}

/// Time [us] at which `solver` reaches error E along its work-precision front
/// (points not dominated by a faster, more accurate one), interpolated linearly in
/// log(time) against log(error) between the neighbouring front points. Empty if it
/// never reaches E.
std::optional<double> time_at_error(const std::vector<Point>& points, const std::string& solver, double E) {
  std::vector<Point> p;
  for (const Point& q : points)
    if (q.solver == solver) p.push_back(q);
  std::sort(p.begin(), p.end(), [](const Point& a, const Point& b) { return a.us_per_impact < b.us_per_impact; });
  const Point* previous = nullptr;
  double best = INFINITY;
  for (const Point& q : p) {
    if (!(q.abs_error < best)) continue;  // dominated
    best = q.abs_error;
    if (q.abs_error <= E) {
      if (!previous) return q.us_per_impact;
      const double le0 = std::log(std::max(previous->abs_error, 1e-17)), le1 = std::log(std::max(q.abs_error, 1e-17));
      const double s = (std::log(E) - le0) / (le1 - le0);
      return std::exp(std::log(previous->us_per_impact) + s * (std::log(q.us_per_impact) - std::log(previous->us_per_impact)));
    }
    previous = &q;
  }
  return std::nullopt;
}

/// Least-squares slope of log(error) against log(tolerance), and the spread
/// max/min of error/tolerance: 1 and small for an error proportional to tolerance.
struct Proportionality {
  double slope = NAN;
  double spread = NAN;
};
Proportionality proportionality(const std::vector<Point>& points, const std::string& solver) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, lo = INFINITY, hi = 0;
  int n = 0;
  for (const Point& q : points) {
    if (q.solver != solver || !(q.abs_error > 0)) continue;
    const double x = std::log10(q.tolerance), y = std::log10(q.abs_error);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++n;
    lo = std::min(lo, q.abs_error / q.tolerance);
    hi = std::max(hi, q.abs_error / q.tolerance);
  }
  if (n < 2) return {};
  return {(n * sxy - sx * sy) / (n * sxx - sx * sx), hi / lo};
}

/// How far Dormand-Prince's embedded estimate misses the true error of its order-5
/// solution on one step of y' = sqrt(t - t0) from t to t + h with t - t0 = a h: the
/// ratio (true error)/(estimated error), from the tableau's weights. At a = 0 the step
/// starts on the singularity (contact onset).
double sqrt_singularity_miss(double a) {
  using T = detail::DormandPrinceTableau;
  const double c[7] = {0, T::c2, T::c3, T::c4, T::c5, 1, 1};
  const double b[7] = {T::b1, 0, T::b3, T::b4, T::b5, T::b6, 0};
  const double e[7] = {T::e1, 0, T::e3, T::e4, T::e5, T::e6, T::e7};
  double quad = 0, est = 0;
  for (int i = 0; i < 7; ++i) {
    quad += b[i] * std::sqrt(a + c[i]);
    est += e[i] * std::sqrt(a + c[i]);
  }
  const double exact = 2.0 / 3.0 * (std::pow(a + 1, 1.5) - std::pow(a, 1.5));
  return std::abs((quad - exact) / est);
}

std::string macro_name(const std::string& solver) {
  // hertzdash-dopri5 -> HertzdashDopriFive: letters only.
  static const std::map<char, std::string> digits{{'0', "Zero"}, {'1', "One"}, {'2', "Two"}, {'3', "Three"},
                                                  {'4', "Four"}, {'5', "Five"}, {'6', "Six"}, {'7', "Seven"},
                                                  {'8', "Eight"}, {'9', "Nine"}};
  std::string out;
  bool upper = true;
  for (char ch : solver) {
    if (ch == '-' || ch == '_') {
      upper = true;
    } else if (digits.count(ch)) {
      out += digits.at(ch);
      upper = true;
    } else {
      out += upper ? static_cast<char>(std::toupper(static_cast<unsigned char>(ch))) : ch;
      upper = false;
    }
  }
  return out;
}

// ---- What is compared, on what.

/// The paper's steel case at h = 20 mm, twice: "contact", the contact phase alone (started
/// at onset with the free-fall speed sqrt(2 g h), gravity kept), and "drop", the whole drop.
/// The contact workload comes first.
std::vector<Workload> paper_workloads() {
  const PaperParameters paper = load_paper_parameters();
  Workload contact{"contact", "Contact", paper_setup(paper, "steel", 0.02)};
  contact.setup.impact_velocity_mps = std::sqrt(2 * contact.setup.gravity_mps2 * contact.setup.height_m);
  Workload drop{"drop", "Drop", paper_setup(paper, "steel", 0.02)};
  validate(contact.setup);
  validate(drop.setup);
  return {contact, drop};
}

/// Every row of the integrator table (tolerances for the adaptive ones, steps for the
/// fixed-step ones), then the peers.
std::vector<SolverSpec> compared_solvers() {
  std::vector<SolverSpec> solvers;
  for (const IntegratorTraits& row : all_integrator_traits)
    solvers.push_back({"hertzdash-" + std::string(row.name), Group::hertzdash, row.step_control == StepControl::adaptive,
                       [kind = row.kind](double t) { return make_hertzdash_solver(kind, t); }});
  solvers.push_back({"odeint-dopri5", Group::physical_peer, true, make_odeint_dopri5});
  solvers.push_back({"gsl-rk8pd", Group::physical_peer, true, make_gsl_rk8pd});
  solvers.push_back({"cvode-fresh", Group::physical_peer, true, make_cvode_fresh});
  solvers.push_back({"odeint-bs-regularized", Group::regularized_peer, true, make_odeint_bs_regularized});
  solvers.push_back({"odeint-bs-dense-regularized", Group::regularized_peer, true, make_odeint_bs_dense_regularized});
  solvers.push_back({"odeint-dopri5-regularized", Group::regularized_peer, true, make_odeint_dopri5_regularized});
  solvers.push_back({"gsl-rk8pd-regularized", Group::regularized_peer, true, make_gsl_rk8pd_regularized});
  return solvers;
}

/// The tolerances of the adaptive solvers, 1e-4 to 1e-10 every half decade (or decade),
/// or the steps [s] of the fixed-step ones.
std::vector<double> tolerances_or_steps(const SolverSpec& s, const WorkPrecisionConfig& c) {
  if (!s.adaptive) return {1e-5, 3e-6, 1e-6, 3e-7};
  std::vector<double> tolerances;
  for (int k = 0; k <= 12; k += c.half_decades ? 1 : 2) tolerances.push_back(std::pow(10.0, -4.0 - 0.5 * k));
  return tolerances;
}

struct Machine {
  std::string name;  ///< the CPU's model name
  unsigned cores;
};
Machine this_machine() { return {machine_name(), std::max(1u, std::thread::hardware_concurrency())}; }

// ---- Timing: what the solvers do, measured.

/// e_ref of a workload: the mean of two independent methods at tolerance 1e-13
/// (hertzdash's dopri5 and GSL's rk8pd), and how far apart they are.
struct Reference {
  double e_effective;
  double agreement;  ///< |e_dopri5 - e_rk8pd|
};
Reference reference_restitution(const DropTestSetup& setup) {
  const double e_dopri = make_hertzdash_solver(IntegratorKind::dopri5, 1e-13)->run(setup).e_effective;
  const double e_rk8 = make_gsl_rk8pd(1e-13)->run(setup).e_effective;
  return {0.5 * (e_dopri + e_rk8), std::abs(e_dopri - e_rk8)};
}

/// Every solver at each of its tolerances (or steps) on the workload: the error of
/// e_effective against e_ref and the evaluations of one untimed impact, then the median
/// time per impact. Prints a row for each.
std::vector<Point> measure_work_precision(const Workload& w, const std::vector<SolverSpec>& solvers, double e_ref,
                                          const WorkPrecisionConfig& c) {
  std::vector<Point> points;
  fmt::print("{:<18} {:>9} {:>12} {:>10} {:>12}\n", "solver", "tol/dt", "|error|", "rhs evals", "us/impact");
  for (const SolverSpec& s : solvers) {
    for (double tol : tolerances_or_steps(s, c)) {
      if (!s.adaptive && w.name == "drop" && tol < 1e-6) continue;  // minutes of fixed steps through the fall
      auto solver = s.make(tol);
      const ImpactResult r = solver->run(w.setup);
      const double us = time_per_impact_us(*solver, w.setup, c);
      points.push_back({s.name, tol, std::abs(r.e_effective - e_ref), r.rhs_evaluations, us});
      fmt::print("{:<18} {:>9.1e} {:>12.3e} {:>10} {:>12.2f}\n", s.name, tol, points.back().abs_error,
                 r.rhs_evaluations, us);
    }
  }
  return points;
}

/// OUT/work_precision_peers.csv (contact) or OUT/work_precision_peers_drop.csv (drop).
void write_points_csv(const Workload& w, const std::vector<Point>& points, const Reference& ref,
                      const Machine& machine, const WorkPrecisionConfig& c) {
  CsvWriter csv(fmt::format("Work precision of hertzdash's integrators and peer libraries, workload '{}' (steel, "
                            "h = 20 mm); tolerance is the step [s] for hertzdash-euler and hertzdash-rk4; rtol = tolerance, atol = "
                            "1e-4 tolerance; us_per_impact is the median of {} repeats on {} ({} cores)",
                            w.name, c.repeats, machine.name, machine.cores),
                {{"workload", w.name}, {"e_reference", fmt::format("{:.17g}", ref.e_effective)},
                 {"reference_agreement", fmt::format("{:.3g}", ref.agreement)}},
                {"solver", "tolerance", "abs_error_e_eff", "rhs_evals", "us_per_impact"});
  for (const Point& p : points) csv.add_row({p.solver, p.tolerance, p.abs_error, p.rhs_evaluations, p.us_per_impact});
  csv.save(c.out_dir / (w.name == "contact" ? "work_precision_peers.csv" : "work_precision_peers_drop.csv"));
}

/// The fastest solver of each group at error E, on the solvers' work-precision fronts
/// ("none" at infinite time for a group that never reaches E).
struct Fastest {
  std::string solver = "none";
  double us = INFINITY;
};
struct EqualError {
  double E;
  Fastest own, physical, regularized;
  double ratio_physical() const { return own.us / physical.us; }
  double ratio_regularized() const { return own.us / regularized.us; }
};
EqualError fastest_at_error(const std::vector<Point>& points, const std::vector<SolverSpec>& solvers, double E) {
  std::map<Group, Fastest> best;
  for (const SolverSpec& s : solvers) {
    const auto t = time_at_error(points, s.name, E);
    if (t && (!best.count(s.group) || *t < best[s.group].us)) best[s.group] = {s.name, *t};
  }
  return {E, best[Group::hertzdash], best[Group::physical_peer], best[Group::regularized_peer]};
}

// ---- The article's macros and table, and the pages' summary.

/// What the benchmark reports: the article's \perf... macros, its table of times at equal
/// error, and the rows of the pages' summary (Markdown).
struct Report {
  explicit Report(LatexMacros m) : macros(std::move(m)) {}
  LatexMacros macros;
  std::ostringstream table_tex;
  std::ostringstream summary_md;
};

const std::string summary_header =
    "| workload | error | fastest hertzdash [us] | fastest regularised peer [us] | ratio | fastest physical-variable "
    "peer [us] | ratio |\n|---|---|---|---|---|---|---|\n";

/// The macros' header and the machine, the table's head, and Dormand-Prince's miss of the
/// sqrt singularity (sqrt_singularity_miss).
Report start_report(const Machine& machine, const WorkPrecisionConfig& c) {
  Report r(LatexMacros("Work-precision benchmark against Boost.Odeint, GSL and CVODE (bench/work_precision.cpp)",
                       {{"machine", machine.name},
                        {"cores", std::to_string(machine.cores)},
                        {"repeats", std::to_string(c.repeats)}}));
  r.macros.add_text("perfMachine", machine.name);
  r.macros.add("perfCores", machine.cores, "{}");
  r.macros.add("perfSqrtMissAtStart", sqrt_singularity_miss(0.0), "{:.0f}");
  r.macros.add("perfSqrtMissQuarter", sqrt_singularity_miss(0.25), "{:.0f}");
  r.macros.add("perfSqrtMissOne", sqrt_singularity_miss(1.0), "{:.1f}");
  r.table_tex << "% generated by bench/work_precision.cpp: time per impact at equal error\n"
              << "\\resizebox{\\linewidth}{!}{%\n\\begin{tabular}{lllrlrrlrr}\n\\toprule\n"
              << "workload & error & \\multicolumn{2}{c}{fastest hertzdash [$\\mu$s]} & "
              << "\\multicolumn{3}{c}{fastest regularised peer [$\\mu$s], ratio} & "
              << "\\multicolumn{3}{c}{fastest physical-variable peer [$\\mu$s], ratio} \\\\\n\\midrule\n";
  return r;
}

void report_reference(const Workload& w, const Reference& ref, LatexMacros& macros) {
  fmt::print("\n== workload '{}': e_ref = {:.15f} (hertzdash-dopri5 and gsl-rk8pd at tol 1e-13 agree to {:.1e})\n",
             w.name, ref.e_effective, ref.agreement);
  macros.add("perfReference" + w.tag, ref.e_effective, "{:.12f}");
  macros.add_text("perfReferenceAgreement" + w.tag, latex_scientific(ref.agreement));
}

/// One error level: printed, as macros, a row of the article's table and one of the
/// summary; at 1e-9 the goals (<= 0.5 of the fastest regularised peer, <= 0.15 of the
/// fastest physical-variable one) met or missed.
void report_equal_error(const Workload& w, const EqualError& q, Report& report) {
  const auto& [own, t_own] = q.own;
  const auto& [physical, t_physical] = q.physical;
  const auto& [regularized, t_regularized] = q.regularized;
  const double ratio_physical = q.ratio_physical(), ratio_regularized = q.ratio_regularized();
  fmt::print("   error {:.0e}: {} {:.2f} us; fastest regularised peer {} {:.2f} us, ratio {:.3f}; fastest "
             "physical-variable peer {} {:.2f} us, ratio {:.3f}\n",
             q.E, own, t_own, regularized, t_regularized, ratio_regularized, physical, t_physical, ratio_physical);
  LatexMacros& macros = report.macros;
  const std::string e_tag = q.E == 1e-6 ? "Six" : q.E == 1e-8 ? "Eight" : "Nine";
  macros.add("perfRatio" + w.tag + e_tag, ratio_physical, "{:.2f}");
  macros.add("perfRegRatio" + w.tag + e_tag, ratio_regularized, "{:.2f}");
  macros.add("perfOwnUs" + w.tag + e_tag, t_own, "{:.1f}");
  macros.add("perfPeerUs" + w.tag + e_tag, t_physical, "{:.1f}");
  macros.add("perfRegPeerUs" + w.tag + e_tag, t_regularized, "{:.1f}");
  macros.add_text("perfOwnSolver" + w.tag + e_tag, own);
  macros.add_text("perfPeerSolver" + w.tag + e_tag, physical);
  macros.add_text("perfRegPeerSolver" + w.tag + e_tag, regularized);
  report.table_tex << fmt::format("{} & $10^{{-{}}}$ & \\texttt{{{}}} & {:.1f} & \\texttt{{{}}} & {:.1f} & {:.2f} & "
                                  "\\texttt{{{}}} & {:.1f} & {:.2f} \\\\\n",
                                  w.name, static_cast<int>(std::round(-std::log10(q.E))), own, t_own, regularized,
                                  t_regularized, ratio_regularized, physical, t_physical, ratio_physical);
  if (q.E == 1e-9) {
    const std::string regularized_goal = ratio_regularized <= 0.5 ? "met" : "missed",
                      physical_goal = ratio_physical <= 0.15 ? "met" : "missed";
    fmt::print("   goals at 1e-9: <= 0.5 of the fastest regularised peer ({}: {:.2f}), <= 0.15 of the fastest "
               "physical-variable peer ({}: {:.2f})\n",
               regularized_goal, ratio_regularized, physical_goal, ratio_physical);
    macros.add_text("perfRegGoal" + w.tag, regularized_goal);
    macros.add_text("perfGoal" + w.tag, physical_goal);
  }
  report.summary_md << fmt::format("| {} | {:.0e} | {} {:.1f} | {} {:.1f} | {:.2f} | {} {:.1f} | {:.2f} |\n", w.name,
                                   q.E, own, t_own, regularized, t_regularized, ratio_regularized, physical,
                                   t_physical, ratio_physical);
}

/// Ratios at equal error: the fastest hertzdash path against the fastest peer of each group.
void report_equal_errors(const Workload& w, const std::vector<SolverSpec>& solvers, const std::vector<Point>& points,
                         Report& report) {
  fmt::print("\n-- '{}': time per impact at equal error (log-log interpolation on each solver's front)\n", w.name);
  for (double E : {1e-6, 1e-8, 1e-9}) report_equal_error(w, fastest_at_error(points, solvers, E), report);
}

/// Each adaptive solver's error against its tolerance (proportionality).
void report_proportionality(const Workload& w, const std::vector<SolverSpec>& solvers,
                            const std::vector<Point>& points, LatexMacros& macros) {
  fmt::print("-- '{}': error against tolerance, slope of log error vs log tol and spread max/min of error/tol\n",
             w.name);
  for (const SolverSpec& s : solvers) {
    if (!s.adaptive) continue;
    const Proportionality q = proportionality(points, s.name);
    fmt::print("   {:<18} slope {:.2f}  spread {:.1f}\n", s.name, q.slope, q.spread);
    macros.add("perfSlope" + macro_name(s.name) + w.tag, q.slope, "{:.2f}");
    macros.add("perfSpread" + macro_name(s.name) + w.tag, q.spread, "{:.0f}");
  }
}

/// On the contact workload at tolerance 1e-8: CVODE with its memory reused, on the
/// regularised contact and created per impact; the cost per right-hand-side evaluation,
/// everything included, of the hertzdash paths; the regularised paths' errors.
void report_contact_costs(const std::vector<Point>& points, LatexMacros& macros) {
  static const std::map<std::string, std::string> per_eval_tags{{"hertzdash-cvode", "Cvode"},
                                                                {"hertzdash-dopri5", "Dopri"},
                                                                {"hertzdash-dopri5-regularized", "Regularized"},
                                                                {"hertzdash-gbs8-regularized", "Gbs"},
                                                                {"hertzdash-taylor-regularized", "Taylor"}};
  for (const Point& p : points) {
    if (std::abs(p.tolerance - 1e-8) >= 1e-20) continue;
    if (p.solver == "hertzdash-cvode") {
      macros.add("perfCvodeReusedUs", p.us_per_impact, "{:.1f}");
      fmt::print("-- hertzdash-cvode (memory reused) at rtol 1e-8: {:.1f} us per impact\n", p.us_per_impact);
    }
    if (p.solver == "hertzdash-cvode-regularized") {
      macros.add("perfCvodeRegularizedUs", p.us_per_impact, "{:.1f}");
      macros.add("perfCvodeRegularizedEvals", static_cast<double>(p.rhs_evaluations), "{:.0f}");
    }
    if (p.solver == "cvode-fresh") macros.add("perfCvodeFreshUs", p.us_per_impact, "{:.1f}");
    if (per_eval_tags.count(p.solver)) {
      const std::string tag = per_eval_tags.at(p.solver);
      macros.add("perf" + tag + "NsPerEval", 1e3 * p.us_per_impact / static_cast<double>(p.rhs_evaluations), "{:.0f}");
      macros.add("perf" + tag + "Evals", static_cast<double>(p.rhs_evaluations), "{:.0f}");
      if (tag == "Regularized" || tag == "Gbs" || tag == "Taylor")
        macros.add_text("perf" + tag + "ErrorEight", latex_scientific(p.abs_error));
    }
  }
}

/// An estimate of the fewest Taylor series the contact allows
/// (validation/common/regularized_contact_singularities.hpp): the undamped contact's singularities
/// against the series the Taylor path generates for it, at tolerance 1e-8 (the steel case
/// without damping and gravity, same impact speed).
void report_taylor_series_estimate(const DropTestSetup& contact, LatexMacros& macros) {
  constexpr double tol = 1e-8;
  const int p = taylor_order(tol);
  DropTestSetup undamped = contact;
  undamped.gravity_mps2 = 0.0;
  SolverSettings settings;
  settings.integrator = IntegratorKind::taylor_regularized;
  settings.rtol = tolerances_for(tol).rtol;
  settings.atol = tolerances_for(tol).atol;
  const ImpactSummary run = ImpactSimulator(settings).run<Undamped>(undamped);
  const UndampedRegularizedContact u = undamped_regularized_contact();
  const double series = static_cast<double>(run.work.rhs_evaluations) / p, least = least_taylor_series(tol, p);
  fmt::print("\n-- taylor-regularized, undamped contact at tol 1e-8: order {}, {:.0f} series; the singularities "
             "(Im s* = {:.3f} of the half duration from the turning point) give an estimated least {:.1f}\n",
             p, series, u.singular_height / u.half_duration, least);
  macros.add("perfTaylorOrderEight", p, "{:.0f}");
  macros.add("perfTaylorUndampedSeriesEight", series, "{:.0f}");
  macros.add("perfTaylorLeastSeriesEight", least, "{:.1f}");
  macros.add("perfTaylorSingularHeight", u.singular_height / u.half_duration, "{:.2f}");
  macros.add("perfTaylorContactRadii", contact_length_in_radii(), "{:.2f}");
}

/// The faster of the two regularised paths that need the polynomial form (gbs8-regularized,
/// taylor-regularized) at tolerance 1e-8, by `rate(settings, threads)` [impacts/s] on 1 thread:
/// its name, its rate on 1 thread and on `cores` threads. `what` names the run in the printed
/// lines; the goal is `goal` impacts/s per core; the macros are named `macro` + Impacts, RateOne,
/// RateAll, Solver, Goal.
struct FastestRate {
  std::string solver;
  double one = 0, all = 0;
};
template <class Rate>
FastestRate fastest_regularized(Rate rate, unsigned cores, const std::string& what, double impacts, double goal,
                                const std::string& macro, Report& report) {
  const Tolerances tol = tolerances_for(1e-8);
  FastestRate best;
  for (IntegratorKind kind : {IntegratorKind::gbs8_regularized, IntegratorKind::taylor_regularized}) {
    SolverSettings settings;
    settings.integrator = kind;
    settings.rtol = tol.rtol;
    settings.atol = tol.atol;
    const double r1 = rate(settings, 1), rn = rate(settings, cores);
    fmt::print("\n== {}, {} at tol 1e-8: {:.3g} impacts/s on 1 thread, {:.3g} impacts/s on {} threads ({:.3g} per "
               "core)\n",
               what, to_string(kind), r1, rn, cores, rn / cores);
    if (r1 > best.one) best = {to_string(kind), r1, rn};
  }
  fmt::print("   goal: >= {:g} impacts/s per core; measured {:.3g} on 1 thread ({}), {:.3g} per core on {} threads\n",
             goal, best.one, best.solver, best.all / cores, cores);
  report.macros.add(macro + "Impacts", impacts, "{:.0f}");
  report.macros.add(macro + "RateOne", best.one, "{:.0f}");
  report.macros.add(macro + "RateAll", best.all, "{:.0f}");
  report.macros.add_text(macro + "Solver", best.solver);
  report.macros.add_text(macro + "Goal", best.all / cores >= goal ? "met" : "missed");
  return best;
}

/// Parallel sweep throughput: a restitution map (h from 1 to 100 mm, e from 0.5 to 1),
/// contact phases at tolerance 1e-8 with each regularised path that needs the polynomial
/// form (gbs8-regularized, taylor-regularized); the faster is reported.
void report_parallel_sweep(const DropTestSetup& contact, long impacts, unsigned cores, Report& report) {
  const long n = impacts, side = static_cast<long>(std::sqrt(static_cast<double>(n)));
  std::vector<double> e(static_cast<std::size_t>(n));
  auto body = [&](ImpactSimulator& sim, std::size_t i) {
    DropTestSetup s = contact;
    const double h = 1e-3 + 99e-3 * static_cast<double>(static_cast<long>(i) % side) / static_cast<double>(side - 1);
    s.restitution = 0.5 + 0.5 * static_cast<double>(static_cast<long>(i) / side % side) / static_cast<double>(side - 1);
    s.impact_velocity_mps = std::sqrt(2 * s.gravity_mps2 * h);
    e[i] = sim.run<HongoPaper>(s).e_effective;
  };
  auto rate = [&](const SolverSettings& settings, unsigned threads) {
    const auto t0 = Clock::now();
    parallel_sweep(static_cast<std::size_t>(n), settings, body, {.threads = threads, .label = "restitution map"});
    return static_cast<double>(n) / std::chrono::duration<double>(Clock::now() - t0).count();
  };
  const auto [best, one, all] = fastest_regularized(rate, cores, fmt::format("parallel sweep (restitution map, {} impacts)", n),
                                                    static_cast<double>(n), 3e5, "perfSweep", report);
  report.summary_md << fmt::format("\nParallel sweep (restitution map of {} contact phases, {} at tolerance 1e-8): "
                                   "{:.3g} impacts/s on 1 thread, {:.3g} impacts/s on {} threads ({:.3g} per core; goal "
                                   ">= 3e5 per core).\n\n",
                                   n, best, one, all, cores, all / cores);
}

/// Shaker throughput (simulation/shaker/shaker.hpp): the paper's rod on the nylon hemisphere,
/// input e = 0.5, on a wall at 20 Hz, soft contacts (the paper's law) at tolerance 1e-8 and
/// exact flights, every impact counted (transient included); 16 independent runs at gamma
/// 1.2 ... 2.0 (period 1, its doublings and chaos, as in a bifurcation diagram), over
/// `impacts` impacts in all, with each regularised path that takes the wall's motion
/// (gbs8-regularized, taylor-regularized); the faster is reported beside the sweep's rate.
void report_shaker_rate(const DropTestSetup& contact, long impacts, unsigned cores, Report& report) {
  constexpr int values = 16, kept = 50;
  const int per_value = std::max<int>(kept + 50, static_cast<int>(impacts / values));
  DropTestSetup s = contact;
  s.restitution = 0.5;
  auto options = [&](std::size_t i) {
    ShakerOptions o;
    const double gamma = 1.2 + 0.8 * static_cast<double>(i) / (values - 1);
    o.wall = {.amplitude_m = shaker_amplitude_m(gamma, 20.0, s.gravity_mps2), .frequency_Hz = 20.0};
    o.impacts = kept;
    o.transient = per_value - kept;
    return o;
  };
  auto rate = [&](const SolverSettings& settings, unsigned threads) {
    std::vector<long> run(values);
    const auto t0 = Clock::now();
    parallel_for_chunks(
        values, [] { return 0; },
        [&](int, std::size_t i) { run[i] = run_shaker(s, "hongo", settings, options(i)).impacts_run; },
        {.threads = threads, .chunk = 1, .label = "shaker"});
    long total = 0;
    for (long n : run) total += n;
    return static_cast<double>(total) / std::chrono::duration<double>(Clock::now() - t0).count();
  };
  const auto [best, one, all] = fastest_regularized(
      rate, cores, fmt::format("shaker (paper's rod on nylon, soft contacts with flights, {} x {} impacts)", values, per_value),
      static_cast<double>(values) * per_value, 1e5, "perfShaker", report);
  report.summary_md << fmt::format("Shaker (the paper's rod on nylon on a 20 Hz wall, gamma 1.2-2.0, soft contacts "
                                   "and flights, {} impacts, {} at tolerance 1e-8): {:.3g} impacts/s on 1 thread, "
                                   "{:.3g} impacts/s on {} threads ({:.3g} per core; goal >= 1e5 per core).\n\n",
                                   values * per_value, best, one, all, cores, all / cores);
}

void report_figures_time(double seconds, unsigned cores, Report& report) {
  fmt::print("\n== make figures from the built tree: {:.1f} s on {} cores\n", seconds, cores);
  report.macros.add("perfFiguresSeconds", seconds, "{:.0f}");
  report.summary_md << fmt::format("`make figures` from a built tree: {:.1f} s on {} cores.\n", seconds, cores);
}

// ---- The pages' generated block.

/// The generated performance block of docs/performance.md (--performance-page): the machine, then
/// the summary table and lines.
std::string performance_block(const Machine& machine, const std::string& summary_md) {
  return fmt::format("Measured on {} ({} cores, shared), `make bench` (times are medians; regenerate on a quiet "
                     "machine):\n\n",
                     machine.name, machine.cores) +
         summary_header + summary_md;
}

/// Replaces what stands between the page's markers <!-- perf:begin ... --> and
/// <!-- perf:end --> by `block`, built piece by piece (no in-place replace); throws if the
/// page has no such block.
void refresh_performance_page(const std::filesystem::path& page, const std::string& block) {
  std::ifstream in(page);
  std::stringstream buf;
  buf << in.rdbuf();
  const std::string text = buf.str();
  const std::string begin = "<!-- perf:begin (generated by make bench) -->\n", end = "<!-- perf:end -->";
  const auto b = text.find(begin), e = text.find(end);
  if (b == std::string::npos || e == std::string::npos || e < b)
    throw std::runtime_error(page.string() + ": no generated performance block (" + begin.substr(0, begin.size() - 1) + ")");
  write_file_atomically(page, text.substr(0, b + begin.size()) + block + text.substr(e));
}

}  // namespace

int run_work_precision(const WorkPrecisionConfig& c) {
  const std::vector<Workload> workloads = paper_workloads();
  const DropTestSetup& contact = workloads.front().setup;
  const std::vector<SolverSpec> solvers = compared_solvers();
  const Machine machine = this_machine();
  fmt::print("work-precision benchmark on {} ({} cores); {} timed repeats of {} ms each, median\n", machine.name,
             machine.cores, c.repeats, c.budget_ms);

  Report report = start_report(machine, c);
  for (const Workload& w : workloads) {
    const Reference ref = reference_restitution(w.setup);
    report_reference(w, ref, report.macros);
    const std::vector<Point> points = measure_work_precision(w, solvers, ref.e_effective, c);
    write_points_csv(w, points, ref, machine, c);
    report_equal_errors(w, solvers, points, report);
    report_proportionality(w, solvers, points, report.macros);
    if (w.name == "contact") report_contact_costs(points, report.macros);
  }
  report.table_tex << "\\bottomrule\n\\end{tabular}}\n";  // ten columns: scaled to the line width
  report_taylor_series_estimate(contact, report.macros);
  report_parallel_sweep(contact, c.sweep_impacts, machine.cores, report);
  report_shaker_rate(contact, c.sweep_impacts / 4, machine.cores, report);
  if (c.figures_seconds > 0) report_figures_time(c.figures_seconds, machine.cores, report);

  fmt::print("\n== summary: wall time per impact at equal error, fastest hertzdash over the fastest peer of each group\n"
             "{}{}",
             summary_header, report.summary_md.str());
  report.macros.save(c.generated_dir / "work_precision_peers.tex");
  write_file_atomically(c.generated_dir / "work_precision_peers_table.tex", report.table_tex.str());
  for (const std::filesystem::path& page : c.performance_pages)
    refresh_performance_page(page, performance_block(machine, report.summary_md.str()));
  return 0;
}

}  // namespace hertzdash::bench
