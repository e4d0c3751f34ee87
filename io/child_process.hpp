#pragma once
// Running another program to its end: gnuplot for a figure (cli/figure_file.cpp), a
// discrete-element engine on a deck (simulation/export/engine_run.cpp). One place spawns, redirects,
// waits and kills; each caller reads what the program wrote.
#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

struct ChildProcess {
  std::vector<std::string> args;          ///< args[0] looked up on PATH
  std::filesystem::path directory;        ///< where it runs; empty: the caller's
  std::filesystem::path output;           ///< its standard output (created or truncated; "/dev/null" allowed)
  std::filesystem::path errors;           ///< its standard error; empty: into `output`
  std::vector<std::string> environment;   ///< NAME=VALUE set for it, before the caller's own
  /// A process group of its own, so that a timeout kills whatever it started (mpirun's ranks);
  /// false: it stays in the caller's group and takes the terminal's Ctrl-C at once.
  bool own_process_group = false;
  std::optional<std::chrono::seconds> timeout;  ///< past it, killed (its group with it)
};

struct ChildExit {
  int status = 0;          ///< as waitpid() reports it (WIFEXITED, WEXITSTATUS, WIFSIGNALED)
  bool timed_out = false;  ///< killed at the timeout
  bool succeeded() const;  ///< exited, with status 0
  /// "exit status N", "killed by signal N", "ran past T s and was killed".
  std::string why(const ChildProcess& p) const;
};

/// Runs `p` to its end. Throws std::runtime_error("cannot run ARGS0: REASON" + hint) when it cannot
/// start (`hint`: how to install it).
ChildExit run_child(const ChildProcess& p, const std::string& hint);

/// Whether `program` is an executable file in a directory of PATH.
bool on_path(const std::string& program);

}  // namespace hertzdash
