// Work precision against the established integrators: is hertzdash faster than
// what a user would write with Boost.Odeint, GSL or CVODE, at equal accuracy?
//
// Users run thousands of impacts (restitution maps, sensitivity grids), so the
// suite must be both accurate and fast. This study times hertzdash's integrators
// (Dormand-Prince 5(4) with events landed on, CVODE with reused memory, RK4) and
// three peers on the same right-hand side over tolerances 1e-4 to 1e-10, on one
// contact phase and on one full drop of the paper's steel case (h = 20 mm), and
// measures the throughput of a parallel restitution map. The measurement code is
// bench/work_precision.cpp; `make bench` runs it with more repeats (and prints the
// table); here it runs briefly so `make figures` stays quick, and --reduced makes
// it quicker still for the pipeline test.
//
// Writes OUT/work_precision_peers.csv and OUT/work_precision_peers_drop.csv
// (solver, tolerance, abs_error_e_eff, rhs_evals, us_per_impact), drawn by
// work_precision_peers.gp; GENERATED/work_precision_peers.tex (\perf... macros)
// and GENERATED/work_precision_peers_table.tex. The timings depend on the machine
// (named in the files); the errors and evaluation counts do not.
#include "bench/work_precision.hpp"
#include "validation/common/study_args.hpp"

int main(int argc, char** argv) {
  const hertzdash::StudyArgs args = hertzdash::parse_study_args(argc, argv);
  hertzdash::bench::WorkPrecisionConfig c;
  c.out_dir = args.out_dir;
  c.generated_dir = args.generated_dir;
  c.budget_ms = args.reduced ? 0.2 : 2.0;
  c.repeats = args.reduced ? 1 : 5;
  c.half_decades = !args.reduced;
  c.sweep_impacts = args.reduced ? 2000 : 40000;
  return hertzdash::bench::run_work_precision(c);
}
