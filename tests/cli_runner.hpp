#pragma once
// Runs build/hertzdash with arguments and captures exit code, stdout and stderr.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace hertzdash::test {

struct CliResult {
  int exit_code;
  std::string out, err;
};

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

/// Run `program <args>` through the shell (args are passed verbatim), optionally
/// with environment assignments prefixed (e.g. "HERTZDASH_DATA_DIR=/tmp/x").
inline CliResult run_cli_program(const std::string& program, const std::string& args, const std::string& env = "") {
  const auto dir = std::filesystem::temp_directory_path() / ("hertzdash_cli_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string cmd = env + " " + program + " " + args + " >" + (dir / "out").string() + " 2>" +
                          (dir / "err").string();
  const int status = std::system(cmd.c_str());
  CliResult r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "out"), slurp(dir / "err")};
  std::filesystem::remove_all(dir);
  return r;
}

/// Run `build/hertzdash <args>` (see run_cli_program).
inline CliResult run_cli(const std::string& args, const std::string& env = "") {
  return run_cli_program(HERTZDASH_BIN, args, env);
}

}  // namespace hertzdash::test
