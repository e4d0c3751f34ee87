// `hertzdash shaker --sweep` (cli/shaker_sweep.hpp).
#include "cli/shaker_sweep.hpp"

#include "cli/output_files.hpp"
#include "cli/process_group.hpp"
#include "hertzdash/model/shaker_sweep_parameters.hpp"
#include "hertzdash/simulation/reports/shaker_sweep_report.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <iostream>
#include <thread>
#include <vector>

namespace hertzdash::cli {

int run_shaker_sweep_command(const ShakerSweepRequest& q) {
  if (q.sweep.empty()) throw InvalidParameter("threads", format_value(*q.threads), "given with `sweep` only");
  if (q.json) throw InvalidParameter("json", "true", "not given with `sweep` (the diagram goes to `csv`)");
  if (q.csv_path.empty()) throw InvalidParameter("csv", "none", "a file name with `sweep`");
  check_rig_inputs(shaker_rig(), q.run, q.shaker);
  const ShakerSweepAxis axis = parse_shaker_sweep(q.sweep);
  if (q.threads) require_in_range(shaker_sweep_parameters::threads, *q.threads);
  const ProcessGroup group;
  ShakerSweep sweep = resolve_shaker_sweep(q.run, load_paper_parameters(), q.shaker, axis);

  std::vector<std::size_t> mine;
  for (auto v = static_cast<std::size_t>(group.rank()); v < sweep.runs.size(); v += static_cast<std::size_t>(group.size()))
    mine.push_back(v);
  // --threads, else under MPI the machine's cores shared among its processes, else the sweep's
  // default (every core, or $HERTZDASH_THREADS).
  unsigned threads = 0;
  if (q.threads && *q.threads > 0) threads = static_cast<unsigned>(*q.threads);
  else if (group.size() > 1)
    threads = std::max(1u, std::thread::hardware_concurrency() / static_cast<unsigned>(group.local_size()));
  unsigned used = 1;
  const auto start = std::chrono::steady_clock::now();
  std::exception_ptr failure;
  try {
    run_shaker_sweep(sweep, mine, {.threads = threads, .label = "shaker sweep", .threads_used = &used});
  } catch (...) {
    failure = std::current_exception();
  }
  if (group.size() == 1 && failure) std::rethrow_exception(failure);
  if (group.any(failure != nullptr)) {  // every process leaves: none waits for another in a gather
    if (failure) try {
        std::rethrow_exception(failure);
      } catch (const std::exception& e) {
        std::cerr << fmt::format("hertzdash shaker: process {}: {}\n", group.rank(), e.what());
      }
    return 1;
  }
  if (group.size() > 1) {
    const std::vector<std::vector<double>> numbers = group.gather(pack_shaker_runs(sweep, mine));
    const std::vector<std::string> warnings = group.gather(pack_shaker_warnings(sweep, mine));
    if (group.rank() != 0) return 0;
    for (std::size_t r = 1; r < numbers.size(); ++r) {
      std::vector<std::size_t> theirs;
      for (std::size_t v = r; v < sweep.runs.size(); v += numbers.size()) theirs.push_back(v);
      unpack_shaker_runs(sweep, theirs, numbers[r], warnings[r]);
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const CsvWriter csv = shaker_sweep_csv(sweep);
  create_output_directories(q.csv_path, q.mkdir);
  csv.save(q.csv_path);
  std::size_t rows = 0, warned = 0;
  for (const ShakerCommandRun& r : sweep.runs) {
    rows += r.run.impacts.size();
    warned += r.run.warnings.empty() ? 0 : 1;
  }
  std::cout << fmt::format("hertzdash shaker: {} values of {} from {} to {}, {} rows to {} in {:.3g} s on {} x {} threads",
                           axis.count, axis.key, axis.from, axis.to, rows, q.csv_path, seconds,
                           group.size() == 1 ? "1 process" : fmt::format("{} processes", group.size()), std::max(used, 1u));
  if (warned) std::cout << fmt::format("; {} runs warned (the file's # warning lines)", warned);
  std::cout << "\n";
  return 0;
}

}  // namespace hertzdash::cli
