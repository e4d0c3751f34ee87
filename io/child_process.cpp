// Running another program to its end (io/child_process.hpp).
#include "hertzdash/io/child_process.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char** environ;

namespace hertzdash {

bool ChildExit::succeeded() const { return !timed_out && WIFEXITED(status) && WEXITSTATUS(status) == 0; }

std::string ChildExit::why(const ChildProcess& p) const {
  if (timed_out) return fmt::format("ran past {} s and was killed", p.timeout ? p.timeout->count() : 0);
  if (WIFEXITED(status)) return fmt::format("exit status {}", WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return fmt::format("killed by signal {}", WTERMSIG(status));
  return "stopped";
}

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && access((std::filesystem::path(dir) / program).c_str(), X_OK) == 0) return true;
  return false;
}

ChildExit run_child(const ChildProcess& p, const std::string& hint) {
  const std::string& name = p.args.at(0);
  posix_spawn_file_actions_t actions;
  posix_spawnattr_t attributes;
  if (posix_spawn_file_actions_init(&actions) != 0) throw std::runtime_error("cannot prepare the run of " + name);
  if (posix_spawnattr_init(&attributes) != 0) {
    posix_spawn_file_actions_destroy(&actions);
    throw std::runtime_error("cannot prepare the run of " + name);
  }
  const auto release = [&] {
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attributes);
  };
  const bool prepared =
      (p.directory.empty() || posix_spawn_file_actions_addchdir_np(&actions, p.directory.c_str()) == 0) &&
      posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, p.output.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600) == 0 &&
      (p.errors.empty() ? posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO) == 0
                        : posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, p.errors.c_str(),
                                                           O_WRONLY | O_CREAT | O_TRUNC, 0600) == 0) &&
      (!p.own_process_group || (posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP) == 0 &&
                                posix_spawnattr_setpgroup(&attributes, 0) == 0));
  if (!prepared) {
    release();
    throw std::runtime_error(fmt::format("cannot prepare the output of {} ({})", name, p.output.string()));
  }
  std::vector<std::string> args = p.args, environment = p.environment;
  std::vector<char*> argv, env;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  for (std::string& e : environment) env.push_back(e.data());
  for (char** e = environ; *e; ++e) env.push_back(*e);
  env.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, name.c_str(), &actions, &attributes, argv.data(), env.data());
  release();
  if (spawned != 0) throw std::runtime_error(fmt::format("cannot run {}: {}{}", name, std::strerror(spawned), hint));
  ChildExit out;
  const auto deadline = p.timeout ? std::chrono::steady_clock::now() + *p.timeout : std::chrono::steady_clock::time_point::max();
  for (;;) {
    const pid_t done = waitpid(pid, &out.status, p.timeout ? WNOHANG : 0);
    if (done == pid) return out;
    if (done < 0 && errno != EINTR) throw std::runtime_error(fmt::format("waiting for {} failed", name));
    if (std::chrono::steady_clock::now() > deadline) {
      kill(p.own_process_group ? -pid : pid, SIGKILL);
      while (waitpid(pid, &out.status, 0) < 0 && errno == EINTR) {
      }
      out.timed_out = true;
      return out;
    }
    if (p.timeout) std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace hertzdash
