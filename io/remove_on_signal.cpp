#include "hertzdash/io/remove_on_signal.hpp"

#include <atomic>
#include <climits>
#include <csignal>
#include <cstring>
#include <unistd.h>

namespace hertzdash {

namespace {

// A slot is free (0), being filled (1) or holds a path the handler removes (2). The handler
// only reads slots in state 2, whose path is complete, and calls async-signal-safe functions.
struct Slot {
  std::atomic<int> state{0};
  char path[PATH_MAX];
};
static_assert(std::atomic<int>::is_always_lock_free);
Slot slots[64];
constexpr int cleaned_signals[] = {SIGINT, SIGTERM, SIGHUP};

extern "C" void remove_registered_files(int signal) {
  for (Slot& s : slots)
    if (s.state.load() == 2) ::unlink(s.path);
  ::signal(signal, SIG_DFL);
  ::raise(signal);  // delivered, with the default action, when this handler returns
}

void install_over_default() {
  for (int signal : cleaned_signals) {
    struct sigaction current {};
    if (::sigaction(signal, nullptr, &current) != 0) continue;
    if ((current.sa_flags & SA_SIGINFO) != 0 || current.sa_handler != SIG_DFL) continue;
    struct sigaction mine {};
    mine.sa_handler = remove_registered_files;
    sigemptyset(&mine.sa_mask);
    for (int other : cleaned_signals) sigaddset(&mine.sa_mask, other);
    ::sigaction(signal, &mine, nullptr);
  }
}

}  // namespace

RemoveOnSignal::RemoveOnSignal(const std::filesystem::path& path) : slot_(-1) {
  const std::string& text = path.native();
  if (text.size() >= PATH_MAX) return;
  install_over_default();
  for (int i = 0; i < static_cast<int>(std::size(slots)); ++i) {
    int expected = 0;
    if (!slots[i].state.compare_exchange_strong(expected, 1)) continue;
    std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
    slots[i].state.store(2);
    slot_ = i;
    return;
  }
}

RemoveOnSignal::~RemoveOnSignal() {
  if (slot_ >= 0) slots[slot_].state.store(0);
}

}  // namespace hertzdash
