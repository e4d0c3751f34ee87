#pragma once
// One writer per output file at a time: an advisory lock (flock) on NAME.lock beside the file
// a write replaces (io/atomic_file.hpp replaced_file: symbolic links followed, so two names of
// one file take one lock). Taken before the work that makes the file and held until it is
// written, so a second hertzdash aiming at the same file is refused at once, rather than
// running and interleaving its files with the first one's (the CSV of one, the summary of the
// other). The lock file holds the holder's process id and is removed when the lock ends
// (a signal too removes it, io/remove_on_signal.hpp); one left by SIGKILL is not held (the
// kernel releases the lock with the process) and is taken over by the next writer.
#include "hertzdash/io/remove_on_signal.hpp"

#include <filesystem>
#include <optional>
#include <stdexcept>

namespace hertzdash {

/// Thrown when another process holds the lock; what(): "FILE is being written by another
/// process (PID N holds FILE.lock)".
class OutputBusy : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class OutputLock {
 public:
  /// Locks `file` (a file write_file_atomically replaces). Throws OutputBusy, or
  /// std::runtime_error "cannot lock FILE: REASON".
  explicit OutputLock(const std::filesystem::path& file);
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;

 private:
  std::filesystem::path lock_path_;
  int fd_ = -1;
  std::optional<RemoveOnSignal> registered_;
};

}  // namespace hertzdash
