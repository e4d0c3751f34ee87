#pragma once
// Temporary files that no signal but SIGKILL may orphan. While a RemoveOnSignal is alive, its
// path is unlinked if a signal whose default action ends the process arrives (SIGHUP, SIGINT,
// SIGQUIT, SIGTERM, SIGUSR1/2, SIGALRM, SIGPIPE, SIGXCPU, SIGVTALRM, SIGPROF, SIGIO, SIGPWR,
// the real-time signals, and SIGABRT, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGTRAP, SIGSYS); the
// signal's default action follows. The handler is installed only over the default
// disposition: a program's own handler (the sweep's Ctrl-C, Python's KeyboardInterrupt) is
// left alone. SIGXFSZ at its default is ignored from the first registration on (as Python
// does), so a write beyond `ulimit -f` fails with EFBIG, "File too large", which its writer
// reports after removing its temporary, instead of killing the process silently.
// At most 64 paths are registered at once; beyond that a file is written unregistered.
#include <filesystem>

namespace hertzdash {

class RemoveOnSignal {
 public:
  explicit RemoveOnSignal(const std::filesystem::path& path);
  ~RemoveOnSignal();  // unregisters (the owner renames or removes the file itself)
  RemoveOnSignal(const RemoveOnSignal&) = delete;
  RemoveOnSignal& operator=(const RemoveOnSignal&) = delete;

 private:
  int slot_;  // -1: not registered
};

/// While alive, the asynchronous signals above (all but SIGABRT, SIGSEGV, SIGBUS, SIGFPE,
/// SIGILL, SIGTRAP, SIGSYS, which a program raises against itself and cannot postpone) are held,
/// in every thread: one that arrives is recorded and delivered, with its default action, when
/// the last SignalHold ends. A set of renames made under one is all done or not begun when a
/// signal ends the program.
class SignalHold {
 public:
  SignalHold();
  ~SignalHold();
  SignalHold(const SignalHold&) = delete;
  SignalHold& operator=(const SignalHold&) = delete;
};

}  // namespace hertzdash
