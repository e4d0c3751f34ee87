#pragma once
// Sweeps over many impacts (restitution maps, height sweeps, sensitivity grids, case files) on
// all cores.
//
//   std::vector<double> e(n);
//   parallel_sweep(n, settings, [&](ImpactSimulator& sim, std::size_t i) {
//     e[i] = sim.run<HongoPaper>(setup_for(i)).e_effective;
//   }, {.label = "restitution map"});
//
// The index range [0, count) is handed out in chunks from an atomic counter to a pool of
// std::threads; each thread owns one ImpactSimulator (so the CVODE memory is reused within a
// thread, never shared). `body(simulator, i)` must only write results for index i.
// parallel_for_chunks is the same with a state of the caller's making per thread (a sweep whose
// runs differ in solver keeps one simulator per solver setting).
//
// Progress goes to stderr: on a terminal a line redrawn every 0.2 s (done, rate, ETA); elsewhere
// (logs, pipes, batch jobs) a plain line every `log_interval_s` seconds if that is > 0, else
// nothing. The first exception thrown by a body stops the hand-out of new chunks and is rethrown
// after all threads joined. A `cancel` flag set (by a signal handler, say) stops the hand-out
// likewise; the caller sees how far it got from the flag and its own results.
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <charconv>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <string>
#include <string_view>
#include <system_error>
#include <thread>
#include <vector>

namespace hertzdash {

struct SweepOptions {
  unsigned threads = 0;          ///< 0: default_sweep_threads()
  std::size_t chunk = 0;         ///< indices handed out at once; 0: sweep_chunk(count, threads)
  std::string label = "sweep";   ///< shown in the progress line
  bool progress = true;          ///< report progress (a redrawn line on a terminal)
  double log_interval_s = 0;     ///< not on a terminal: a plain progress line this often (0: never)
  const std::atomic<bool>* cancel = nullptr;  ///< stop handing out work once set
  /// Set to the worker threads that ran: fewer than asked when the system could create no more
  /// (a process or thread limit; the sweep still runs every index).
  unsigned* threads_used = nullptr;
};

/// The threads of a sweep that does not say: $HERTZDASH_THREADS if set (a whole number from 1 to
/// 4096; the studies of `make figures` have no option of their own), else the machine's cores.
inline unsigned default_sweep_threads() {
  const char* env = std::getenv("HERTZDASH_THREADS");
  if (env == nullptr || *env == '\0') return std::max(1u, std::thread::hardware_concurrency());
  const std::string_view text(env);
  unsigned n = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (ec != std::errc() || end != text.data() + text.size() || n < 1 || n > 4096)
    throw InvalidParameter("HERTZDASH_THREADS", std::string(text), "a whole number from 1 to 4096 (threads of a sweep)");
  return n;
}

/// The number of worker threads `options` asks for (at least 1).
inline unsigned sweep_threads(const SweepOptions& options) {
  return options.threads ? options.threads : default_sweep_threads();
}

/// The indices a thread takes at once unless a sweep says: a quarter of each thread's share,
/// at least 1 and at most 256. Every thread gets work in a small sweep (20 runs on 3 threads:
/// chunks of 1; a fixed 256 gave all 20 to one thread, so a study's 1-vs-3-thread comparison
/// compared one thread with one), and a large one takes the shared counter rarely.
inline std::size_t sweep_chunk(std::size_t count, unsigned threads) {
  return std::clamp<std::size_t>(count / (4 * std::size_t{std::max(threads, 1u)}), 1, 256);
}

namespace sweep_detail {

// "1234 / 5000 runs (25%), 3.1e+04 runs/s, ETA 0:00:12"
inline void print_progress(const SweepOptions& options, std::size_t done, std::size_t count, unsigned threads,
                           double elapsed_s, bool redraw) {
  const double rate = elapsed_s > 0 ? static_cast<double>(done) / elapsed_s : 0;
  const double eta = rate > 0 ? static_cast<double>(count - done) / rate : 0;
  const auto s = static_cast<long>(eta + 0.5);
  std::fprintf(stderr, "%s%s: %zu / %zu (%3.0f%%) on %u threads, %.3g per s, ETA %ld:%02ld:%02ld%s", redraw ? "\r" : "",
               options.label.c_str(), done, count,
               count ? 100.0 * static_cast<double>(done) / static_cast<double>(count) : 100.0, threads, rate, s / 3600,
               s / 60 % 60, s % 60, redraw ? "   " : "\n");
  std::fflush(stderr);
}

}  // namespace sweep_detail

/// Runs body(state, i) for every i in [0, count), each thread with its own state = make_state().
template <class MakeState, class Body>
void parallel_for_chunks(std::size_t count, MakeState&& make_state, Body&& body, const SweepOptions& options = {}) {
  const unsigned n_threads = static_cast<unsigned>(std::min<std::size_t>(sweep_threads(options), std::max<std::size_t>(count, 1)));
  const std::size_t chunk = options.chunk ? options.chunk : sweep_chunk(count, n_threads);
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto stopped = [&] { return failed.load(std::memory_order_relaxed) || (options.cancel && options.cancel->load()); };

  auto worker = [&] {
    try {
      auto state = make_state();
      for (;;) {
        const std::size_t begin = next.fetch_add(chunk);
        if (begin >= count || stopped()) return;
        const std::size_t end = std::min(count, begin + chunk);
        std::size_t i = begin;  // a cancel (Ctrl-C) waits for one run per thread, not for a chunk
        for (; i < end && !stopped(); ++i) body(state, i);
        done += i - begin;
        if (i < end) return;
      }
    } catch (...) {
      std::lock_guard lock(error_mutex);
      if (!error) error = std::current_exception();
      failed = true;
    }
  };

  const bool terminal = isatty(STDERR_FILENO) != 0;
  const bool show = options.progress && (terminal || options.log_interval_s > 0);
  const auto start = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
  std::mutex finished_mutex;
  std::condition_variable finished_cv;
  bool finished = false;
  std::thread reporter;
  if (show) {
    const auto period = terminal ? std::chrono::milliseconds(200)
                                 : std::chrono::milliseconds(static_cast<long>(1000 * options.log_interval_s));
    try {
      reporter = std::thread([&, period] {
        std::unique_lock lock(finished_mutex);
        while (!finished_cv.wait_for(lock, period, [&] { return finished; }))
          sweep_detail::print_progress(options, done.load(), count, n_threads, elapsed(), terminal);
      });
    } catch (...) {  // no thread for the progress line: the final line only
    }
  }

  // The threads the system lets us create: the work is handed out from one counter, so fewer
  // threads than asked still run every index (and none: this thread runs it). The count run is
  // reported through options.threads_used.
  std::vector<std::thread> pool;
  pool.reserve(n_threads);
  try {
    for (unsigned k = 0; k < n_threads; ++k) pool.emplace_back(worker);
  } catch (...) {  // std::system_error (EAGAIN: a process or thread limit, no memory for a stack), bad_alloc
  }
  if (options.threads_used) *options.threads_used = std::max<unsigned>(1, static_cast<unsigned>(pool.size()));
  if (pool.empty()) worker();
  for (auto& th : pool) th.join();

  if (show) {
    {
      std::lock_guard lock(finished_mutex);
      finished = true;
    }
    finished_cv.notify_one();
    if (reporter.joinable()) reporter.join();
    sweep_detail::print_progress(options, done.load(), count, n_threads, elapsed(), terminal);
    if (terminal) std::fputc('\n', stderr);
  }
  if (error) std::rethrow_exception(error);
}

/// Runs body(simulator, i) for every i in [0, count), one ImpactSimulator(settings) per thread.
template <class Body>
void parallel_sweep(std::size_t count, const SolverSettings& settings, Body&& body, const SweepOptions& options = {}) {
  parallel_for_chunks(
      count, [&] { return ImpactSimulator(settings); }, body, options);
}

}  // namespace hertzdash
