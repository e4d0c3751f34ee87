#pragma once
// Sweeps over many impacts (restitution maps, height sweeps, sensitivity grids) on
// all cores.
//
//   std::vector<double> e(n);
//   parallel_sweep(n, settings, [&](ImpactSimulator& sim, std::size_t i) {
//     e[i] = sim.run<HongoPaper>(setup_for(i)).e_effective;
//   }, {.label = "restitution map"});
//
// The index range [0, count) is handed out in chunks from an atomic counter to a
// pool of std::threads; each thread owns one ImpactSimulator (so the CVODE memory
// is reused within a thread, never shared). `body(simulator, i)` must only write
// results for index i. While the sweep runs, a progress line is drawn on stderr if
// stderr is a terminal (never into logs or pipes). The first exception thrown by a
// body stops the hand-out of new chunks and is rethrown after all threads joined.
#include "hertzdash/simulation/impact_simulator.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <cstdio>
#include <exception>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace hertzdash {

struct SweepOptions {
  unsigned threads = 0;          ///< 0: std::thread::hardware_concurrency()
  std::size_t chunk = 256;       ///< indices handed out at once
  std::string label = "sweep";   ///< shown in the progress line
  bool progress = true;          ///< draw the progress line (only ever on a terminal)
};

/// The number of worker threads `options` asks for (at least 1).
inline unsigned sweep_threads(const SweepOptions& options) {
  return std::max(1u, options.threads ? options.threads : std::thread::hardware_concurrency());
}

template <class Body>
void parallel_sweep(std::size_t count, const SolverSettings& settings, Body&& body, const SweepOptions& options = {}) {
  const unsigned n_threads = static_cast<unsigned>(std::min<std::size_t>(sweep_threads(options), std::max<std::size_t>(count, 1)));
  const std::size_t chunk = std::max<std::size_t>(options.chunk, 1);
  std::atomic<std::size_t> next{0}, done{0};
  std::atomic<bool> failed{false};
  std::exception_ptr error;
  std::mutex error_mutex;

  auto worker = [&] {
    ImpactSimulator simulator(settings);
    for (;;) {
      const std::size_t begin = next.fetch_add(chunk);
      if (begin >= count || failed.load(std::memory_order_relaxed)) return;
      const std::size_t end = std::min(count, begin + chunk);
      try {
        for (std::size_t i = begin; i < end; ++i) body(simulator, i);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        failed = true;
        return;
      }
      done += end - begin;
    }
  };

  // The progress line: redrawn every 0.2 s by a reporter thread, on a terminal only.
  const bool show = options.progress && isatty(STDERR_FILENO);
  std::mutex finished_mutex;
  std::condition_variable finished_cv;
  bool finished = false;
  std::thread reporter;
  if (show) {
    reporter = std::thread([&] {
      std::unique_lock lock(finished_mutex);
      while (!finished_cv.wait_for(lock, std::chrono::milliseconds(200), [&] { return finished; })) {
        const std::size_t d = done.load();
        std::fprintf(stderr, "\r%s: %zu / %zu impacts (%3.0f%%) on %u threads", options.label.c_str(), d, count,
                     count ? 100.0 * static_cast<double>(d) / static_cast<double>(count) : 100.0, n_threads);
        std::fflush(stderr);
      }
    });
  }

  std::vector<std::thread> pool;
  pool.reserve(n_threads);
  for (unsigned k = 0; k < n_threads; ++k) pool.emplace_back(worker);
  for (auto& th : pool) th.join();

  if (show) {
    {
      std::lock_guard lock(finished_mutex);
      finished = true;
    }
    finished_cv.notify_one();
    reporter.join();
    std::fprintf(stderr, "\r%s: %zu / %zu impacts done%*s\n", options.label.c_str(), done.load(), count, 20, "");
  }
  if (error) std::rethrow_exception(error);
}

}  // namespace hertzdash
