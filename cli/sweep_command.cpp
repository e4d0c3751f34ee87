// `hertzdash sweep CASE.toml`: the runs of a case file (docs/sweep.md) on every core, or under
// an MPI launcher on every process of the job; one CSV row per run, optionally a summary.
//
// Under MPI, run i goes to rank i mod size (neighbouring runs, often alike in cost, are spread
// over the ranks); rank 0 gathers the outputs and errors and writes the same files the threaded
// run writes, byte for byte apart from the timing line.
#include "cli/command.hpp"
#include "cli/figure_file.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/process_group.hpp"
#include "cli/setup_options.hpp"
#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/output_directories.hpp"
#include "hertzdash/io/output_lock.hpp"
#include "hertzdash/simulation/sweep/sweep_run.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <deque>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <variant>

namespace hertzdash::cli {

namespace {

struct SweepCommandOptions {
  std::string case_path, out, summary, figure;
  unsigned threads = 0;
  bool quiet = false, mkdir = false;
};

#ifdef HERTZDASH_WITHOUT_TOML
// Built without toml++ (HERTZDASH_WITH_TOML, CMakeLists.txt): the options are parsed as usual,
// and the run says why there is none.
int run_sweep_command(const SweepCommandOptions&) {
  std::cerr << "hertzdash sweep: this hertzdash was built without TOML support, so it cannot read case files "
               "(toml++ was not found when it was configured, or HERTZDASH_WITH_TOML was OFF); install toml++ 3 "
               "(Debian: libtomlplusplus-dev) and configure and build it again\n";
  return 2;
}
#else
// Set by SIGINT/SIGTERM while the runs run; a second signal ends the program at once, through
// the disposition the runs began with (io/remove_on_signal.hpp's, which removes the lock files;
// nothing else has been written then: the files are written after the runs).
std::atomic<bool> interrupted{false};
static_assert(std::atomic<bool>::is_always_lock_free);
void (*previous_int)(int) = SIG_DFL;
void (*previous_term)(int) = SIG_DFL;

extern "C" void on_interrupt(int signal) {
  interrupted = true;
  std::signal(signal, signal == SIGINT ? previous_int : previous_term);
}

// The signal handlers for the duration of the runs.
class InterruptGuard {
 public:
  InterruptGuard() {
    interrupted = false;
    previous_int = std::signal(SIGINT, on_interrupt);
    previous_term = std::signal(SIGTERM, on_interrupt);
    if (previous_int == SIG_ERR || previous_term == SIG_ERR)
      throw std::runtime_error("cannot install the SIGINT/SIGTERM handlers of the sweep");
  }
  ~InterruptGuard() {
    std::signal(SIGINT, previous_int);
    std::signal(SIGTERM, previous_term);
  }
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;
};

std::filesystem::path summary_path(const std::filesystem::path& out) {
  std::filesystem::path p = out;
  return p.replace_extension(".summary.csv");
}

// Put this rank's results (runs rank, rank + size, ...) into the whole case's order.
// A rig's per-impact tables travel as one list of doubles: per run its cell count, then its cells.
std::vector<double> pack_impacts(const SweepResults& results) {
  std::vector<double> packed;
  for (const std::vector<double>& t : results.impacts) {
    packed.push_back(static_cast<double>(t.size()));
    packed.insert(packed.end(), t.begin(), t.end());
  }
  return packed;
}

SweepResults assemble(const std::vector<std::vector<double>>& values, const std::vector<std::string>& errors,
                      const std::vector<std::vector<double>>& diagnostics, const std::vector<std::vector<double>>& impacts,
                      std::size_t runs, std::size_t outputs) {
  SweepResults all{.outputs = outputs, .values = std::vector<double>(runs * outputs), .errors = std::vector<std::string>(runs),
                   .diagnostics = std::vector<DiagnosticSet>(runs), .impacts = std::vector<std::vector<double>>(runs)};
  const std::size_t size = values.size();
  for (std::size_t r = 0; r < size; ++r) {
    std::size_t j = 0, begin = 0, at = 0;
    for (std::size_t run = r; run < runs; run += size, ++j) {
      const auto cells = static_cast<std::ptrdiff_t>(impacts[r].at(at));
      const auto first = impacts[r].begin() + static_cast<std::ptrdiff_t>(at) + 1;
      all.impacts[run].assign(first, first + cells);
      at += 1 + static_cast<std::size_t>(cells);
      std::copy_n(values[r].begin() + static_cast<std::ptrdiff_t>(j * outputs), outputs,
                  all.values.begin() + static_cast<std::ptrdiff_t>(run * outputs));
      const std::size_t end = errors[r].find('\0', begin);
      all.errors[run] = errors[r].substr(begin, end - begin);
      all.diagnostics[run] = DiagnosticSet::from_bits(static_cast<std::uint16_t>(diagnostics[r][j]));
      begin = end + 1;
    }
  }
  return all;
}

// --figure draws a sweep of one varied key (validation/sweep_figure.gp): refused before any run
// for a case that varies more.
void check_sweep_figure(const SweepCase& c, const std::string& figure) {
  require_gnuplot("figure", figure);
  if (const std::vector<std::string> varied = c.parameter_columns(); varied.size() != 1)
    throw InvalidParameter("figure", figure,
                           fmt::format("given for a sweep of one varied key, its axis (this case varies {}: {})",
                                       varied.size(), fmt::join(varied, ", ")));
  const bool numeric = c.grid.empty() || std::all_of(c.grid.front().values.begin(), c.grid.front().values.end(),
                                                     [](const SweepValue& v) { return std::holds_alternative<double>(v); });
  if (!numeric)
    throw InvalidParameter("figure", figure,
                           fmt::format("given for a sweep over a number, its axis (this case varies {}, a choice)",
                                       c.parameter_columns().front()));
}

// A rig's bifurcation diagram from its per-impact table, or simulate's outputs from the rows.
void draw_sweep_figure(const SweepCase& c, const std::filesystem::path& out, const std::filesystem::path& impacts,
                       const std::string& figure) {
  const std::string key = c.parameter_columns().front();
  const std::string title = fmt::format("{}: {}", std::filesystem::path(c.source).filename().string(),
                                        c.rig ? std::string(c.rig->name) + " rig" : "simulate runs");
  if (c.rig) draw_figure_from_files("sweep_figure.gp", "rig", {impacts}, {title, key}, figure);
  else
    draw_figure_from_files("sweep_figure.gp", "rows", {out},
                {title, key, fmt::format("{}", fmt::join(c.outputs, " "))}, figure);
}

int run_sweep_command(const SweepCommandOptions& opt) {
  const ProcessGroup group;
  const SweepCase c = read_sweep_case(opt.case_path);
  const std::filesystem::path out = opt.out.empty() ? default_sweep_output(c) : std::filesystem::path(opt.out);
  const bool summary = c.summary || !opt.summary.empty();
  const std::filesystem::path summary_out = opt.summary.empty() ? summary_path(out) : std::filesystem::path(opt.summary);
  // A rig's per-impact tables: beside the rows, the CSV's name with .impacts.csv.
  const std::filesystem::path impacts_out = std::filesystem::path(out).replace_extension(".impacts.csv");
  const std::string out_option = opt.out.empty() ? "[output] file" : "--out";
  const std::string summary_option = opt.summary.empty() ? "[output] summary" : "--summary";
  if (!opt.figure.empty()) check_sweep_figure(c, opt.figure);
  prepare_output_file("--figure", opt.figure, opt.mkdir);
  prepare_output_file(out_option, out.string(), opt.mkdir);
  if (summary) prepare_output_file(summary_option, summary_out.string(), opt.mkdir);
  const std::string impacts_option = "the rig's per-impact tables";
  if (c.rig) prepare_output_file(impacts_option, impacts_out.string(), opt.mkdir);
  refuse_shared_files({{"the case file", opt.case_path}},
                      {{out_option, out.string()},
                       {summary_option, summary ? summary_out.string() : ""},
                       {impacts_option, c.rig ? impacts_out.string() : ""},
                       {"--figure", opt.figure}});
  // One sweep at a time per output, held from before the runs until both files are written (an
  // output whose directory --mkdir makes is locked once that is made, right before the write).
  std::vector<std::filesystem::path> outputs{out};
  if (summary) outputs.push_back(summary_out);
  if (c.rig) outputs.push_back(impacts_out);
  std::deque<OutputLock> locks;
  auto lock = [&locks](const std::filesystem::path& p) {
    if (const std::optional<std::filesystem::path> file = replaced_file(p)) locks.emplace_back(*file);
  };
  std::vector<std::filesystem::path> in_new_directories;
  std::string refusal;
  if (group.rank() == 0) try {
      for (const std::filesystem::path& p : outputs)
        if (missing_parent_directories(p).empty()) lock(p);
        else in_new_directories.push_back(p);
    } catch (const OutputBusy& e) {
      refusal = std::string(e.what()) + "; wait for it to end, or give another --out/--summary";
    } catch (const std::exception& e) {
      refusal = e.what();
    }
  if (group.any(!refusal.empty())) {  // every process leaves: none waits for rank 0 in a gather
    if (group.rank() == 0) std::cerr << "hertzdash: refused: " << refusal << "\n";
    return 2;
  }

  std::vector<std::size_t> mine;
  for (std::size_t run = static_cast<std::size_t>(group.rank()); run < c.size(); run += static_cast<std::size_t>(group.size()))
    mine.push_back(run);
  const unsigned threads =
      opt.threads ? opt.threads : std::max(1u, std::thread::hardware_concurrency() / static_cast<unsigned>(group.local_size()));
  const PaperParameters paper = load_paper_parameters();
  const auto start = std::chrono::steady_clock::now();
  SweepResults results;
  unsigned threads_used = threads;
  {
    const InterruptGuard guard;
    results = run_sweep(c, mine, paper,
                        {.threads = threads,
                         .label = group.size() > 1 ? fmt::format("sweep (rank 0 of {})", group.size()) : "sweep",
                         .progress = !opt.quiet && group.rank() == 0,
                         .log_interval_s = 10,
                         .cancel = &interrupted,
                         .threads_used = &threads_used});
  }
  if (threads_used < std::min<std::size_t>(threads, mine.size()))
    std::cerr << fmt::format("hertzdash: note: {} threads asked for{}, more than the system could create; this process "
                             "ran its share of the sweep on {}\n",
                             threads, opt.threads ? " (--threads)" : "", threads_used);
  if (group.any(interrupted)) {
    if (group.rank() == 0) std::cerr << "hertzdash: sweep interrupted; no file written\n";
    return 130;
  }
  std::string errors;
  for (const std::string& e : results.errors) errors += e + '\0';
  const std::vector<std::vector<double>> values = group.gather(results.values);
  const std::vector<std::string> error_parts = group.gather(errors);
  std::vector<double> codes;  // the diagnostic bits travel as doubles (exact below 2^53)
  for (const DiagnosticSet d : results.diagnostics) codes.push_back(d.bits());
  const std::vector<std::vector<double>> code_parts = group.gather(codes);
  const std::vector<std::vector<double>> impact_parts = group.gather(pack_impacts(results));
  if (group.rank() != 0) return 0;

  const SweepResults all = assemble(values, error_parts, code_parts, impact_parts, c.size(), c.outputs.size());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string timing =
      fmt::format("timing: {:.3f} s on {} process{} x {} thread{}, {:.3g} runs/s", seconds, group.size(),
                  group.size() > 1 ? "es" : "", threads_used, threads_used > 1 ? "s" : "",
                  static_cast<double>(c.size()) / seconds);
  for (const std::filesystem::path& p : in_new_directories) {
    create_output_directories(p.string(), opt.mkdir);
    lock(p);
  }
  // As a pair: a signal leaves both files new or both as they were. The per-run table goes to
  // its file as it is formatted, never held whole (a million runs are ~100 MB of text).
  std::vector<std::pair<std::filesystem::path, ContentPieces>> files{
      {out, [&](const std::function<void(std::string_view)>& write) { write_sweep_table(c, all, timing, write); }}};
  const std::string summary_text = summary ? sweep_summary_table(c, all) : std::string();
  if (summary) files.emplace_back(summary_out, [&](const std::function<void(std::string_view)>& write) { write(summary_text); });
  if (c.rig)
    files.emplace_back(impacts_out, [&](const std::function<void(std::string_view)>& write) { write_sweep_impacts(c, all, write); });
  write_files_atomically(files);

  if (!opt.figure.empty()) {
    create_output_directories(opt.figure, opt.mkdir);
    draw_sweep_figure(c, out, impacts_out, opt.figure);
  }
  std::size_t failed = 0;
  for (const std::string& e : all.errors) failed += e.empty() ? 0 : 1;
  std::cout << fmt::format("hertzdash sweep: {} runs, {} failed; wrote {}{}{}\n", c.size(), failed, out.string(),
                           summary ? " and " + summary_out.string() : "", c.rig ? " and " + impacts_out.string() : "");
  if (summary) std::cout << sweep_summary_text(c, all);
  if (const std::string counts = diagnostic_counts_text(all); !counts.empty())
    std::cerr << fmt::format("hertzdash: warning: runs with warnings, per code (of {}): {} (the warnings column says "
                             "which; docs/json-output.md explains each code)\n",
                             c.size(), counts);
  if (failed == 0) return 0;
  const auto first = std::find_if(all.errors.begin(), all.errors.end(), [](const std::string& e) { return !e.empty(); });
  std::cerr << fmt::format("hertzdash: {} of {} runs failed (the error column says why); run {}: {}\n", failed, c.size(),
                           first - all.errors.begin(), *first);
  return failed == c.size() ? 1 : 0;
}
#endif  // HERTZDASH_WITHOUT_TOML

}  // namespace

Command add_sweep_command(CLI::App& app) {
  auto opt = std::make_shared<SweepCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "sweep", "Run a case file's grid or sample of simulate runs (docs/sweep.md); under mpirun on every process");
  auto o = [](std::string_view key) { return declared_option("sweep", key); };
  sub->add_option("case", opt->case_path, o("case").help)->required();
  add_output_file_option(*sub, o("out").flag, opt->out, o("out").help);
  add_output_file_option(*sub, o("summary").flag, opt->summary, o("summary").help);
  add_output_file_option(*sub, o("figure").flag, opt->figure, o("figure").help);
  add_integer_option(*sub, o("threads").flag, opt->threads, o("threads").help);
  sub->add_flag(o("quiet").flag, opt->quiet, o("quiet").help);
  add_mkdir_flag(*sub, opt->mkdir);
  return {sub, [opt]() { return run_sweep_command(*opt); }};
}

}  // namespace hertzdash::cli
