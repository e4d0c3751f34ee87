// Running an installed engine on a deck (simulation/export/engine_run.hpp).
#include "hertzdash/simulation/export/engine_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <fstream>
#include <spawn.h>
#include <sstream>
#include <stdexcept>
#include <csignal>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace hertzdash {

bool engine_installed(Engine engine) {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  for (std::string dir; std::getline(dirs, dir, ':');)
    if (!dir.empty() && access((std::filesystem::path(dir) / engine_program(engine).program).c_str(), X_OK) == 0) return true;
  return false;
}

namespace {

/// The engine's line that starts with `prefix` in its screen output, or "".
std::string line_starting(const std::string& output, std::string_view prefix) {
  std::istringstream in(output);
  for (std::string line; std::getline(in, line);)
    if (line.rfind(prefix, 0) == 0) return line;
  return {};
}

}  // namespace

std::string run_in_directory(std::vector<std::string> args, const std::filesystem::path& directory,
                             const std::filesystem::path& screen, const std::string& install_hint,
                             std::chrono::seconds timeout) {
  posix_spawn_file_actions_t actions;
  if (posix_spawn_file_actions_init(&actions) != 0)
    throw std::runtime_error(fmt::format("cannot prepare {}'s output in {}", args[0], directory.string()));
  if (posix_spawn_file_actions_addchdir_np(&actions, directory.c_str()) != 0 ||
      posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, screen.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600) != 0 ||
      posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO) != 0) {
    posix_spawn_file_actions_destroy(&actions);
    throw std::runtime_error(fmt::format("cannot prepare {}'s output in {}", args[0], directory.string()));
  }
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  // The engines are MPI programs: run alone, Open MPI's singleton would start a support daemon
  // (a few tenths of a second each run, and one more process to wait for under load); isolated,
  // it runs as the one process it is. mpirun ignores it.
  std::string isolated = "OMPI_MCA_ess_singleton_isolated=1";
  std::vector<char*> env{isolated.data()};
  for (char** e = environ; *e; ++e) env.push_back(*e);
  env.push_back(nullptr);
  // Its own process group, so that a timeout kills mpirun's ranks with it.
  posix_spawnattr_t attributes;
  if (posix_spawnattr_init(&attributes) != 0 || posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP) != 0 ||
      posix_spawnattr_setpgroup(&attributes, 0) != 0) {
    posix_spawn_file_actions_destroy(&actions);
    throw std::runtime_error(fmt::format("cannot prepare {}'s process group", args[0]));
  }
  pid_t pid = 0;
  const int spawned = posix_spawnp(&pid, argv[0], &actions, &attributes, argv.data(), env.data());
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  if (spawned != 0) throw std::runtime_error(fmt::format("cannot run {}: {}; {}", args[0], std::strerror(spawned), install_hint));
  int status = 0;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const pid_t done = waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) throw std::runtime_error(fmt::format("waiting for {} failed", args[0]));
    if (std::chrono::steady_clock::now() > deadline) {
      kill(-pid, SIGKILL);
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      throw std::runtime_error(fmt::format("{} ran past {} s and was killed (its output: {})", args[0], timeout.count(),
                                           screen.string()));
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::ostringstream said;
  said << std::ifstream(screen).rdbuf();
  const std::string error = line_starting(said.str(), "ERROR");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || !error.empty()) {
    // The directory may be a temporary one, gone with the exception: the message carries the
    // engine's own words, its ERROR line or the end of what it printed.
    const std::string& out = said.str();
    const std::string why = !error.empty()           ? error
                            : WIFEXITED(status)      ? fmt::format("exit status {}", WEXITSTATUS(status))
                            : WIFSIGNALED(status)    ? fmt::format("killed by signal {}", WTERMSIG(status))
                                                     : "stopped";
    throw std::runtime_error(fmt::format("{} failed: {}; the end of its output: {}", args[0], why,
                                         out.substr(out.size() > 600 ? out.size() - 600 : 0)));
  }
  return said.str();
}

void write_deck(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  if (!out.flush()) throw std::runtime_error("cannot write the deck " + path.string());
}

EngineImpactResult run_engine_deck(Engine engine, const EngineDeck& deck, const std::filesystem::path& directory,
                                   const std::string& deck_name, double approach_speed_mps) {
  const std::string program(engine_program(engine).program);
  write_deck(directory / deck_name, deck.text);
  const std::filesystem::path screen = directory / (deck_name + ".out");
  const std::string said = run_in_directory(engine_program(engine).command(deck_name), directory, screen,
                                            "`make deps-engines` installs it (debian-packages-engines.txt)");
  const std::string result = line_starting(said, "hertzdash_result ");
  EngineImpactResult r;
  if (result.empty() || !(std::istringstream(result.substr(17)) >> r.restitution))
    throw std::runtime_error(fmt::format("{} printed no hertzdash_result line ({})", program, screen.string()));
  r.restitution /= approach_speed_mps;
  std::ifstream forces(directory / deck.force_file);
  long in_contact = 0;
  for (std::string line; std::getline(forces, line);) {
    if (line.empty() || line[0] == '#') continue;
    const double f = std::strtod(line.c_str(), nullptr);
    if (f != 0) ++in_contact;
    r.peak_force_N = std::max(r.peak_force_N, f);
  }
  if (in_contact == 0)
    throw std::runtime_error(fmt::format("{} recorded no contact force in {}", program, (directory / deck.force_file).string()));
  r.contact_time_s = static_cast<double>(in_contact) * deck.timestep_s;
  return r;
}

}  // namespace hertzdash
