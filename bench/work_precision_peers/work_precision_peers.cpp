// Work precision against the established integrators: is hertzdash faster than
// what a user would write with Boost.Odeint, GSL or CVODE, at equal accuracy?
//
// Users run thousands of impacts (restitution maps, sensitivity grids), so the
// suite must be both accurate and fast. This program times hertzdash's integrators
// (Dormand-Prince 5(4) with events landed on, CVODE with reused memory, RK4, the
// regularised paths) and three peers on the same right-hand side over tolerances
// 1e-4 to 1e-10, on one contact phase and on one full drop of the paper's steel case
// (h = 20 mm), and measures the throughput of a parallel restitution map. The
// measurement code is bench/work_precision.cpp.
//
//   work_precision_peers --out DIR [--generated DIR] [--reduced]
//   work_precision_peers --full --out DIR --generated DIR [--performance-page PAGE]... [--figures-ms MS]
//
// `make figures` runs it briefly, like every study (validation/run_studies.sh), so
// the figure stays current; --reduced is quicker still, for the pipeline test.
// `make bench` runs it with --full: many more repeats, the table and ratios printed,
// and (with --performance-page, once per page) the generated block of docs/performance.md
// refreshed; --figures-ms
// is the measured wall time of `make figures` from a built tree, reported there.
//
// Writes OUT/work_precision_peers.csv and OUT/work_precision_peers_drop.csv
// (solver, tolerance, abs_error_e_eff, rhs_evals, us_per_impact), drawn by
// work_precision_peers.gp; GENERATED/work_precision_peers.tex (\perf... macros)
// and GENERATED/work_precision_peers_table.tex. The timings depend on the machine
// (named in the files); the errors and evaluation counts do not.
#include "bench/work_precision.hpp"
#include "hertzdash/io/decimal_number.hpp"

#include <exception>
#include <iostream>
#include <optional>
#include <string>

int main(int argc, char** argv) {
  hertzdash::bench::WorkPrecisionConfig c;
  bool reduced = false, full = false, bad = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) c.out_dir = argv[++i];
    else if (arg == "--generated" && i + 1 < argc) c.generated_dir = argv[++i];
    else if (arg == "--reduced") reduced = true;
    else if (arg == "--full") full = true;
    else if (arg == "--performance-page" && i + 1 < argc) c.performance_pages.push_back(argv[++i]);
    else if (arg == "--figures-ms" && i + 1 < argc) {
      const std::optional<double> ms = hertzdash::parse_decimal(argv[++i]);
      if (ms && *ms > 0) c.figures_seconds = *ms / 1000.0;
      else bad = true;
    } else bad = true;
  }
  if (bad || c.out_dir.empty() || (reduced && full) || (!full && (!c.performance_pages.empty() || c.figures_seconds > 0))) {
    std::cerr << "usage: " << argv[0] << " --out DIR [--generated DIR] [--reduced]\n"
              << "       " << argv[0] << " --full --out DIR --generated DIR [--performance-page PAGE]... [--figures-ms MS, a decimal number > 0]\n";
    return 2;
  }
  if (c.generated_dir.empty()) c.generated_dir = c.out_dir.parent_path() / "generated";
  if (full) {  // make bench
    c.budget_ms = 20;
    c.repeats = 11;
    c.sweep_impacts = 200000;
  } else {  // make figures (--reduced: the pipeline test)
    c.budget_ms = reduced ? 0.2 : 2.0;
    c.repeats = reduced ? 1 : 5;
    c.half_decades = !reduced;
    c.sweep_impacts = reduced ? 2000 : 40000;
  }
  try {
    std::filesystem::create_directories(c.out_dir);
    std::filesystem::create_directories(c.generated_dir);
    return hertzdash::bench::run_work_precision(c);
  } catch (const std::exception& e) {
    std::cerr << "work_precision_peers: error: " << e.what() << "\n";
    return 1;
  }
}
