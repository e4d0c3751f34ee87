// HERTZDASH_THREADS: the thread count of a sweep that does not set one (the studies of
// `make figures`; tests/study_threads.sh runs them on 1 and 3 threads and compares the files).
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/sweep/parallel_sweep.hpp"

#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <vector>

namespace {

/// Sets HERTZDASH_THREADS (or unsets it) for its lifetime, then restores the previous value.
class ThreadsVariable {
 public:
  explicit ThreadsVariable(const char* value) {
    if (const char* old = std::getenv("HERTZDASH_THREADS")) previous_ = old;
    if (value) ::setenv("HERTZDASH_THREADS", value, 1);
    else ::unsetenv("HERTZDASH_THREADS");
  }
  ~ThreadsVariable() {
    if (previous_) ::setenv("HERTZDASH_THREADS", previous_->c_str(), 1);
    else ::unsetenv("HERTZDASH_THREADS");
  }

 private:
  std::optional<std::string> previous_;
};

}  // namespace

TEST_CASE("HERTZDASH_THREADS sets the default thread count of a sweep, an explicit count wins", "[sweep]") {
  using hertzdash::SweepOptions;
  {
    const ThreadsVariable v("3");
    CHECK(hertzdash::default_sweep_threads() == 3);
    CHECK(hertzdash::sweep_threads(SweepOptions{}) == 3);
    CHECK(hertzdash::sweep_threads(SweepOptions{.threads = 2}) == 2);
  }
  {
    const ThreadsVariable v(nullptr);  // unset: the machine's cores, at least one
    CHECK(hertzdash::default_sweep_threads() == std::max(1u, std::thread::hardware_concurrency()));
  }
  {
    const ThreadsVariable v("");  // empty counts as unset, as in a shell's HERTZDASH_THREADS= prefix
    CHECK(hertzdash::default_sweep_threads() == std::max(1u, std::thread::hardware_concurrency()));
  }
}

TEST_CASE("HERTZDASH_THREADS that is not a whole number from 1 to 4096 is refused, naming the variable", "[sweep]") {
  for (const char* bad : {"0", "-1", "1.5", "0x3", "3 ", " 3", "abc", "4097", "99999999999"}) {
    INFO(bad);
    const ThreadsVariable v(bad);
    CHECK_THROWS_WITH(hertzdash::default_sweep_threads(),
                      "invalid HERTZDASH_THREADS = " + std::string(bad) +
                          ": must be a whole number from 1 to 4096 (threads of a sweep)");
  }
}

TEST_CASE("a small sweep spreads over every thread: chunks are a quarter of each thread's share", "[sweep_threads]") {
  using hertzdash::sweep_chunk;
  // clamp(count / (4 threads), 1, 256): 20 runs on 3 threads: 20 / 12 = 1; 1000 on 3: 83;
  // a million on 2: 125000, capped at 256; none at all: 1.
  CHECK(sweep_chunk(20, 3) == 1);
  CHECK(sweep_chunk(1000, 3) == 83);
  CHECK(sweep_chunk(1000000, 2) == 256);
  CHECK(sweep_chunk(0, 4) == 1);
  // 24 indices of 2 ms each on 3 threads: with chunks of 2 every thread takes some (the first
  // thread cannot take all 24 in the moment the others need to start). With the former fixed
  // chunk of 256 the first thread took all 24, so tests/study_threads.sh compared one thread
  // with one.
  std::atomic<int> states{0};
  std::vector<int> ran_on(24, -1);
  hertzdash::parallel_for_chunks(
      ran_on.size(), [&] { return states++; },
      [&](int state, std::size_t i) {
        ran_on[i] = state;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
      },
      {.threads = 3, .progress = false});
  std::set<int> used(ran_on.begin(), ran_on.end());
  CHECK(used.size() == 3);
  CHECK(used.count(-1) == 0);
}

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define HERTZDASH_TEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define HERTZDASH_TEST_SANITIZED 1
#endif
#endif

TEST_CASE("a sweep asking for more threads than the system creates runs on those it gets", "[sweep_threads]") {
#ifdef HERTZDASH_TEST_SANITIZED
  SUCCEED("not under AddressSanitizer: it reserves terabytes of address space, which the limit below forbids");
#else
  // Before, `sweep --threads 40000` died with "terminate called without an active exception"
  // (exit 134) once std::thread could not be created (EAGAIN). A child process whose address
  // space is capped 256 MiB above what it uses cannot map more than about 30 thread stacks of
  // 8 MiB; asked for 4096 threads, the sweep must still run every index, on fewer threads, and
  // say how many it ran on.
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    std::size_t mapped_kib = 0;  // VmSize of this process
    {
      std::FILE* status = std::fopen("/proc/self/status", "r");
      char line[256];
      while (status && std::fgets(line, sizeof line, status))
        if (std::sscanf(line, "VmSize: %zu kB", &mapped_kib) == 1) break;
      if (status) std::fclose(status);
    }
    const rlimit cap{(mapped_kib + 256 * 1024) * 1024, (mapped_kib + 256 * 1024) * 1024};
    if (mapped_kib == 0 || ::setrlimit(RLIMIT_AS, &cap) != 0) ::_exit(3);
    std::vector<std::atomic<int>> ran(10000);
    unsigned used = 0;
    try {
      hertzdash::parallel_for_chunks(
          ran.size(), [] { return 0; }, [&](int, std::size_t i) { ++ran[i]; },
          {.threads = 4096, .chunk = 1, .progress = false, .threads_used = &used});
    } catch (...) {
      ::_exit(4);
    }
    for (const auto& r : ran)
      if (r != 1) ::_exit(5);
    ::_exit(used >= 1 && used < 4096 ? 0 : 6);
  }
  int status = 0;
  REQUIRE(::waitpid(child, &status, 0) == child);
  INFO("child exit status " << (WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status))
                            << " (3: no limit set, 4: the sweep threw, 5: an index not run once, 6: thread count)");
  CHECK(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
#endif
}
