#pragma once
// Temporary files that SIGINT, SIGTERM or SIGHUP must not orphan. While a RemoveOnSignal is
// alive, its path is unlinked if one of those signals ends the process; the signal's default
// action (termination) follows. The handler is installed only over the default disposition:
// a program's own handler (the sweep's Ctrl-C, Python's KeyboardInterrupt) is left alone.
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

}  // namespace hertzdash
