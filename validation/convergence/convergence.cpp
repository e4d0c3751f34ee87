// Convergence study: how fast does each integrator's answer approach the exact one
// on this problem, and why.
//
// What it reproduces: nothing in the paper -- the paper gives no numerical error.
// A reproduction is only as credible as its numerical error is known, so this study
// measures it for every integrator hertzdash offers: explicit Euler and classical RK4
// (fixed step, with and without event location at contact onset and separation),
// CVODE Adams and BDF (against tolerance), and RK4 in regularising variables
// (model/contact_system.hpp), the remedy this study arrives at.
//
// The problem (validation/common/convergence_runs.hpp): the paper's steel rod
// meeting the nylon hemisphere at v0 = sqrt(2 g h), h = 20 mm, gravity off during
// the contact, starting in flight a fraction of a step before onset. Two laws:
//   - `none` (undamped Hertz, F = K x^{3/2}): exact references in closed form
//     (model/hertz.hpp, model/undamped_hertz_trajectory.hpp);
//   - `hongo` (the paper's law, F = K x^{1/2}(x + tau x')): no closed form; the
//     reference is RK4 in regularising variables at 40000 steps per contact, a
//     formulation none of the tested physical-variable runs share. How it is
//     verified is printed: its own order 4 against the closed forms of the
//     undamped law, its change from 20000 to 40000 steps, and its distance from
//     CVODE Adams and BDF at rtol 1e-13 in the physical variables. (For the
//     regularised RK4 series itself this makes the paper's-law sweep a
//     self-convergence check; its independent check is the undamped law.)
//
// What it measures, per integrator and resolution: relative errors of the effective
// restitution, peak force, maximum deformation, contact time and the state at
// t* = onset + 0.3 tc; the observed order between successive resolutions; a
// least-squares order over the finest resolutions; the work (right-hand-side
// evaluations, CPU time). Fixed-step errors are the largest over four positions of
// onset inside a step (convergence_runs.hpp: step_phases).
//
// What it writes (OUT = --out): convergence.csv (paper's law) and
// convergence_undamped.csv with columns integrator, event_location, quantity, step,
// error, observed_order (`step` is the fixed step [s], the mean time step tc/N for
// the regularised runs, CVODE's rtol for CVODE); work_precision.csv (paper's law);
// GENERATED/convergence.tex (\conv... macros) and GENERATED/convergence_table.tex.
// It prints the order tables. The figures come from convergence.gp and
// work_precision.gp.
//
// Results (discussed in docs/convergence.md and paper/sections/convergence.tex):
// Euler reaches order 1 everywhere. RK4 does not reach 4: with located events it
// reaches 2.5 on the Hertz law and 1.5 on the paper's law. The reason is the force
// at x = 0: along the motion x ~ v0 (t - t_on), so the acceleration carries a term
// (t - t_on)^{3/2} (spring) or (t - t_on)^{1/2} (the paper's dashpot x^{1/2} x').
// A step of length h that starts at the kink integrates s^alpha exactly only up to
// its polynomial part and errs by O(h^{alpha+1}); later steps err by
// O(h^5 (k h)^{alpha-4}), a convergent sum. One such step at onset and one at
// separation give a global error O(h^{alpha+1}): 2.5 and 1.5. Locating the events
// cannot help, because the kink is in the solution at the event, not across it.
// Without location the same steps straddle separation, and the quantities read at
// step ends get the accuracy of the step grid: peak force and maximum deformation
// are sampled maxima, O(h^2); the contact time is known to a step, O(h). CVODE's
// error follows its tolerance roughly proportionally for the state and the contact
// time, more slowly for the peak force and the maximum deformation, with scatter
// from its order and step selection. RK4 in the regularising variables u = x^{1/2},
// dt/dtau = 2u, where every law of this family is polynomial, recovers order 4.
#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/csv_writer.hpp"
#include "validation/common/latex_macros.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/run/step_resolution.hpp"
#include "validation/common/study_args.hpp"
#include "validation/common/convergence_runs.hpp"

#include <fmt/format.h>

#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace hertzdash;
using namespace hertzdash::convergence;

namespace {

// Errors at or below this are not used for orders: the paper's-law reference agrees
// with CVODE Adams at rtol 1e-13 to ~2e-12, and the event functions resolve peak
// force and maximum deformation to ~1e-13 relative.
constexpr double error_floor = 1e-12;
// The accuracy the simulate warning is about: 0.1 %, below the last digit of the
// restitution the paper prints (Table 2: e = 0.795).
constexpr double target_error = step_resolution_target_error;

/// One resolution of one series: errors of every quantity and the work.
struct Level {
  double step;        ///< fixed step [s], mean time step [s] or rtol
  long steps_per_contact;  ///< N for fixed-step runs, 0 for CVODE
  std::array<double, quantity_count> error;
  long rhs_evaluations;
  double cpu_time_s;
};

/// One integrator configuration swept over resolutions.
struct Series {
  std::string integrator, event_location;
  double nominal_order;
  std::vector<Level> levels;
};

double max_error(const Level& l) { return *std::max_element(l.error.begin(), l.error.end()); }

/// Least-squares slope of log(error) against log(step) over the `count` finest
/// resolutions whose error is above the floor (NaN with fewer than three).
double fitted_order(const Series& s, int q, std::size_t count = 5) {
  std::vector<double> steps, errors;
  for (auto it = s.levels.rbegin(); it != s.levels.rend() && steps.size() < count; ++it)
    if (it->error[q] > error_floor) steps.push_back(it->step), errors.push_back(it->error[q]);
  return steps.size() < 3 ? std::nan("") : fitted_slope(steps, errors);
}

/// Smallest N of the sweep from which on every quantity's error stays <= target (0 if none).
long steps_needed(const Series& s) {
  long needed = 0;
  for (auto it = s.levels.rbegin(); it != s.levels.rend(); ++it) {
    if (max_error(*it) > target_error) break;
    needed = it->steps_per_contact;
  }
  return needed;
}

struct Sweep {
  std::vector<long> steps_per_contact;  ///< fixed-step resolutions N
  std::vector<long> regularized_steps;  ///< RK4 in tau
  std::vector<double> rtols;            ///< CVODE
  double min_timing_s;                  ///< time each run for at least this long
};

Sweep make_sweep(bool reduced) {
  Sweep w;
  for (long N = 5; N <= (reduced ? 320 : 10240); N *= 2) w.steps_per_contact.push_back(N);
  for (long N = 10; N <= (reduced ? 160 : 1280); N *= 2) w.regularized_steps.push_back(N);
  for (int k = 4; k <= (reduced ? 8 : 12); ++k) w.rtols.push_back(std::pow(10.0, -k));
  w.min_timing_s = reduced ? 0.0 : 2e-3;
  return w;
}

/// Every series for one law against its reference.
template <DampingLaw Law>
std::vector<Series> run_series(const ConvergenceProblem& p, const ImpactQuantities& ref, const Sweep& w) {
  std::vector<Series> all;
  auto fixed = [&]<class Method>(std::type_identity<Method>, bool locate) {
    Series s{Method::name, locate ? "located" : "unlocated", double(Method::order), {}};
    for (long N : w.steps_per_contact) {
      const auto [err, m] = worst_over_phases<Method, Law>(p, ref, N, locate, w.min_timing_s);
      s.levels.push_back({fixed_step_for(p, N), N, err, m.rhs_evaluations, m.cpu_time_s});
    }
    all.push_back(std::move(s));
  };
  for (bool locate : {true, false}) fixed(std::type_identity<ExplicitEuler>{}, locate);
  for (bool locate : {true, false}) fixed(std::type_identity<ClassicalRk4>{}, locate);

  Series reg{"rk4-regularized", "located", 4.0, {}};
  const double tau_c = regularized_contact_tau<Law>(p);
  for (long N : w.regularized_steps) {
    const Measurement m = measure_regularized<ClassicalRk4, Law>(p, tau_c / double(N), w.min_timing_s);
    reg.levels.push_back({p.tc_scale_s / double(N), N, relative_errors(p, m.q, ref), m.rhs_evaluations,
                          m.cpu_time_s});
  }
  all.push_back(std::move(reg));

  for (CvodeMethod method : {CvodeMethod::adams, CvodeMethod::bdf}) {
    // Nominal: error proportional to the tolerance (slope 1).
    Series s{std::string("cvode-") + to_string(method), "located", 1.0, {}};
    for (double rtol : w.rtols) {
      const Measurement m = measure_cvode<Law>(p, method, rtol, w.min_timing_s);
      s.levels.push_back({rtol, 0, relative_errors(p, m.q, ref), m.rhs_evaluations, m.cpu_time_s});
    }
    all.push_back(std::move(s));
  }
  return all;
}

void print_table(const std::string& law, const std::vector<Series>& all) {
  for (const Series& s : all) {
    std::cout << fmt::format("\n{} law, {} ({} events), nominal order {}\n", law, s.integrator, s.event_location,
                             s.nominal_order);
    std::cout << fmt::format("{:>11} {:>9}", s.integrator.rfind("cvode", 0) == 0 ? "rtol" : "step [s]", "rhs");
    for (int q = 0; q < quantity_count; ++q) std::cout << fmt::format(" {:>22}", quantity_name(q));
    std::cout << "\n";
    for (std::size_t i = 0; i < s.levels.size(); ++i) {
      const Level& l = s.levels[i];
      std::cout << fmt::format("{:11.4g} {:9d}", l.step, l.rhs_evaluations);
      for (int q = 0; q < quantity_count; ++q) {
        const double order = i ? observed_order(s.levels[i - 1].step, s.levels[i - 1].error[q], l.step, l.error[q],
                                                error_floor)
                               : std::nan("");
        std::cout << fmt::format(" {:12.3e} ({:>6})", l.error[q], std::isnan(order) ? "-" : fmt::format("{:.2f}", order));
      }
      std::cout << "\n";
    }
    std::cout << fmt::format("{:>21}", "fitted order");
    for (int q = 0; q < quantity_count; ++q) {
      const double f = fitted_order(s, q);
      std::cout << fmt::format(" {:>22}", std::isnan(f) ? "-" : fmt::format("{:.2f}", f));
    }
    std::cout << "\n";
  }
}

void write_csv(const std::filesystem::path& path, const std::string& law, const Parameters& params,
               const std::vector<Series>& all) {
  CsvWriter csv("convergence study, law '" + law +
                    "': relative error of each quantity against the reference; step = fixed step [s] "
                    "(rk4-regularized: mean time step tc/N [s]; cvode-*: rtol); observed_order = "
                    "log(error ratio)/log(step ratio) against the previous row (nan on the first row and "
                    "where an error is below 1e-12)",
                params, {"integrator", "event_location", "quantity", "step", "error", "observed_order"});
  for (const Series& s : all)
    for (int q = 0; q < quantity_count; ++q)
      for (std::size_t i = 0; i < s.levels.size(); ++i) {
        const Level& l = s.levels[i];
        const double order = i ? observed_order(s.levels[i - 1].step, s.levels[i - 1].error[q], l.step, l.error[q],
                                                error_floor)
                               : std::nan("");
        csv.add_row({s.integrator, s.event_location, std::string(quantity_name(q)), l.step, l.error[q], order});
      }
  csv.save(path);
}

void write_work_precision(const std::filesystem::path& path, const Parameters& params, const std::vector<Series>& all) {
  CsvWriter csv("work-precision, paper's law: largest relative error over the five quantities against the "
                "right-hand-side evaluations and the thread CPU time of one impact (fastest of repeated batches; fixed step: "
                "mean over the four onset phases)",
                params, {"integrator", "event_location", "step", "rhs_evaluations", "cpu_time_s", "error"});
  for (const Series& s : all)
    for (const Level& l : s.levels)
      csv.add_row({s.integrator, s.event_location, l.step, l.rhs_evaluations, l.cpu_time_s, max_error(l)});
  csv.save(path);
}

// Macro names: letters only. "rk4-regularized" -> "RkFourRegularized".
std::string macro_part(const std::string& name) {
  static const std::map<std::string, std::string> parts{
      {"euler", "Euler"},          {"rk4", "RkFour"},           {"rk4-regularized", "RkFourRegularized"},
      {"cvode-adams", "CvodeAdams"}, {"cvode-bdf", "CvodeBdf"}, {"located", "Located"},
      {"unlocated", "Unlocated"},  {"e_effective", "Restitution"}, {"peak_force", "PeakForce"},
      {"max_deformation", "MaxDeformation"}, {"contact_time", "ContactTime"}, {"state_at_t_star", "State"}};
  return parts.at(name);
}

std::string order_cell(double f) { return std::isnan(f) ? "--" : fmt::format("{:.2f}", f); }

/// LaTeX table: fitted orders, one row per series, one column per quantity, both laws.
std::string latex_table(const std::vector<Series>& hertz, const std::vector<Series>& paper) {
  std::string t = "% Generated by validation/convergence; do not edit.\n"
                  "\\begin{tabular}{llrrrrr}\n\\hline\n"
                  "integrator & events & $e$ & $F_{\\max}$ & $x_{\\max}$ & $t_c$ & $y(t^*)$ \\\\\n\\hline\n";
  auto block = [&](const std::string& title, const std::vector<Series>& all) {
    t += "\\multicolumn{7}{l}{\\emph{" + title + "}} \\\\\n";
    for (const Series& s : all) {
      t += s.integrator + " & " + s.event_location;
      for (int q = 0; q < quantity_count; ++q) t += " & " + order_cell(fitted_order(s, q));
      t += " \\\\\n";
    }
  };
  block("undamped Hertz law (closed-form reference)", hertz);
  block("paper's law (numerical reference)", paper);
  return t + "\\hline\n\\end{tabular}\n";
}

void add_order_macros(LatexMacros& tex, const std::string& law, const std::vector<Series>& all) {
  for (const Series& s : all) {
    const std::string stem = "conv" + law + macro_part(s.integrator) + macro_part(s.event_location);
    for (int q = 0; q < quantity_count; ++q) tex.add_text(stem + macro_part(quantity_name(q)) + "Order",
                                                          order_cell(fitted_order(s, q)));
    if (s.levels.front().steps_per_contact > 0) tex.add(stem + "StepsNeeded", double(steps_needed(s)), "{:.0f}");
  }
}

/// Steps per contact that reach the target for both laws (the larger), per series.
long steps_needed_both(const std::vector<Series>& a, const std::vector<Series>& b, const std::string& integrator,
                       const std::string& location) {
  long n = 0;
  for (const auto* all : {&a, &b})
    for (const Series& s : *all)
      if (s.integrator == integrator && s.event_location == location) {
        const long k = steps_needed(s);
        n = (k == 0 || n < 0) ? -1 : std::max(n, k);
      }
  return n;
}

}  // namespace

int main(int argc, char** argv) try {
  const StudyArgs args = parse_study_args(argc, argv);
  const Sweep sweep = make_sweep(args.reduced);
  const ConvergenceProblem p = make_problem(load_paper_parameters());
  std::cout << fmt::format("Convergence study: steel rod, v0 = {:.6g} m/s, K = {:.6g} N/m^1.5, undamped tc = {:.6g} s, "
                           "X = {:.6g} m, t* = onset + {:.6g} s{}\n",
                           p.v0_mps, p.K, p.tc_scale_s, p.X_scale_m, p.t_star_s, args.reduced ? " (reduced)" : "");

  // References. The undamped law's are exact; the paper's law's is numerical, and its
  // verification is printed and written for the paper.
  const ImpactQuantities hertz_ref = *closed_form_reference<Undamped>(p);
  const NumericalReference paper_ref = numerical_reference<HongoPaper>(p);
  std::cout << fmt::format("Paper's-law reference (RK4, regularised, 40000 steps): e = {:.15g}, peak force = {:.15g} N, "
                           "x_max = {:.15g} m, tc = {:.15g} s\n  largest relative difference: 20000 steps {:.2e}, "
                           "CVODE Adams rtol 1e-13 {:.2e}, CVODE BDF rtol 1e-13 {:.2e}\n",
                           paper_ref.q.e_effective, paper_ref.q.peak_force_N, paper_ref.q.max_deformation_m,
                           paper_ref.q.contact_time_s, paper_ref.self_difference, paper_ref.adams_difference,
                           paper_ref.bdf_difference);

  const std::vector<Series> hertz = run_series<Undamped>(p, hertz_ref, sweep);
  const std::vector<Series> paper = run_series<HongoPaper>(p, paper_ref.q, sweep);
  print_table("undamped Hertz ('none')", hertz);
  print_table("paper's ('hongo')", paper);

  // The simulate warning's thresholds (the rows' min_steps_per_contact_* in
  // simulation/run/integrator_table.hpp) must be what this sweep finds; say so loudly if
  // they drift apart.
  std::cout << fmt::format("\nSteps per contact for every error <= {:g} (both laws; the sweep doubles N):\n", target_error);
  for (const auto& [integrator, location, constant] :
       {std::tuple{"euler", "located", min_steps_per_contact(IntegratorKind::euler, true)},
        std::tuple{"euler", "unlocated", min_steps_per_contact(IntegratorKind::euler, false)},
        std::tuple{"rk4", "located", min_steps_per_contact(IntegratorKind::rk4, true)},
        std::tuple{"rk4", "unlocated", min_steps_per_contact(IntegratorKind::rk4, false)}}) {
    const long found = steps_needed_both(hertz, paper, integrator, location);
    std::cout << fmt::format("  {:6} {:10} {:>6} (integrator table: {}){}\n", integrator, location,
                             found < 0 ? std::string("> sweep") : std::to_string(found), constant,
                             !args.reduced && found != constant ? "  <-- MISMATCH: update simulation/run/integrator_table.hpp" : "");
  }

  // The set-up as `hertzdash simulate` describes it, without the entries the sweep varies.
  Parameters params;
  const std::set<std::string> varied{"damping", "integrator", "cvode_method", "rtol", "atol"};
  for (auto& entry : describe_run(p.setup, "", SolverSettings{}))
    if (!varied.contains(entry.first)) params.push_back(entry);
  params.emplace_back("t_star_after_onset_s", fmt::format("{}", p.t_star_s));
  params.emplace_back("fixed_step_onset_phases", "0.1 0.35 0.6 0.85 (error = largest)");
  params.emplace_back("cvode_atol", "rtol (of the impact's scales: undamped max deformation, v0)");
  params.emplace_back("reduced", args.reduced ? "true" : "false");
  write_csv(args.out_dir / "convergence.csv", "hongo", params, paper);
  write_csv(args.out_dir / "convergence_undamped.csv", "none", params, hertz);
  write_work_precision(args.out_dir / "work_precision.csv", params, paper);

  LatexMacros tex("convergence study (validation/convergence)", params);
  add_order_macros(tex, "Hertz", hertz);
  add_order_macros(tex, "Paper", paper);
  tex.add("convReferenceSelfDifference", paper_ref.self_difference, "{:.1e}");
  tex.add("convReferenceAdamsDifference", paper_ref.adams_difference, "{:.1e}");
  tex.add("convReferenceBdfDifference", paper_ref.bdf_difference, "{:.1e}");
  tex.add("convErrorFloor", error_floor, "{:.0e}");
  tex.add("convTargetError", target_error, "{:g}");
  tex.add("convTStarFraction", t_star_fraction, "{:g}");
  // Steps per contact the sweep finds for the target (both laws, both event settings for Euler).
  auto needed_text = [&](const char* integrator, const char* location) {
    const long n = steps_needed_both(hertz, paper, integrator, location);
    if (n < 0) return fmt::format("more than {}", sweep.steps_per_contact.back());
    if (n == sweep.steps_per_contact.front()) return fmt::format("at most {} (the coarsest step tested)", n);
    return std::to_string(n);
  };
  tex.add_text("convMinStepsEuler", needed_text("euler", "located"));
  tex.add_text("convMinStepsRkFourLocated", needed_text("rk4", "located"));
  tex.add_text("convMinStepsRkFourUnlocated", needed_text("rk4", "unlocated"));
  tex.save(args.generated_dir / "convergence.tex");
  write_file_atomically(args.generated_dir / "convergence_table.tex", latex_table(hertz, paper));
  std::cout << "\nwrote convergence.csv, convergence_undamped.csv, work_precision.csv to " << args.out_dir.string()
            << "; convergence.tex, convergence_table.tex to " << args.generated_dir.string() << "\n";
  return 0;
} catch (const std::exception& e) {
  return study_failed(argv[0], e);
}
