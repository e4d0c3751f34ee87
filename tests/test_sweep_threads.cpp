// HERTZDASH_THREADS: the thread count of a sweep that does not set one (the studies of
// `make figures`; tests/study_threads.sh runs them on 1 and 3 threads and compares the files).
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/parallel_sweep.hpp"

#include <catch2/catch.hpp>

#include <cstdlib>
#include <optional>
#include <string>
#include <thread>

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
