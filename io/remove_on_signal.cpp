#include "hertzdash/io/remove_on_signal.hpp"

#include <atomic>
#include <climits>
#include <csignal>
#include <cstring>
#include <unistd.h>
#include <vector>

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

// SignalHolds alive, and the signal that arrived meanwhile (0: none).
std::atomic<int> holds{0};
std::atomic<int> held_signal{0};

// Raised by the program against itself: the handler cannot return without the fault recurring
// (or abort() raising again), so these are never held.
constexpr int synchronous_signals[] = {SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGTRAP, SIGSYS};
constexpr int asynchronous_signals[] = {SIGHUP,  SIGINT,    SIGQUIT, SIGTERM, SIGUSR1, SIGUSR2, SIGALRM,
                                        SIGPIPE, SIGXCPU,   SIGVTALRM, SIGPROF, SIGIO, SIGPWR, SIGSTKFLT};

// Every signal whose default action ends the process, but SIGKILL (which cannot be caught) and
// SIGXFSZ (ignored instead, see the header).
std::vector<int> cleaned_signals() {
  std::vector<int> all(std::begin(asynchronous_signals), std::end(asynchronous_signals));
  all.insert(all.end(), std::begin(synchronous_signals), std::end(synchronous_signals));
  for (int s = SIGRTMIN; s <= SIGRTMAX; ++s) all.push_back(s);
  return all;
}

bool is_synchronous(int signal) {
  for (int s : synchronous_signals)
    if (s == signal) return true;
  return false;
}

extern "C" void remove_registered_files(int signal) {
  if (!is_synchronous(signal)) {
    held_signal.store(signal);
    if (holds.load() > 0) return;  // ~SignalHold delivers it
  }
  for (Slot& s : slots)
    if (s.state.load() == 2) ::unlink(s.path);
  ::signal(signal, SIG_DFL);
  ::raise(signal);  // delivered, with the default action, when this handler returns
}

bool has_default_action(int signal) {
  struct sigaction current {};
  if (::sigaction(signal, nullptr, &current) != 0) return false;
  return (current.sa_flags & SA_SIGINFO) == 0 && current.sa_handler == SIG_DFL;
}

void install_over_default() {
  if (has_default_action(SIGXFSZ)) ::signal(SIGXFSZ, SIG_IGN);
  struct sigaction mine {};
  mine.sa_handler = remove_registered_files;
  mine.sa_flags = SA_RESTART;
  sigfillset(&mine.sa_mask);
  for (int signal : cleaned_signals())
    if (has_default_action(signal)) ::sigaction(signal, &mine, nullptr);
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

SignalHold::SignalHold() {
  install_over_default();
  ++holds;
}

SignalHold::~SignalHold() {
  if (holds.fetch_sub(1) != 1) return;
  if (const int signal = held_signal.exchange(0)) ::raise(signal);  // its handler, now at no hold, ends the process
}

}  // namespace hertzdash
