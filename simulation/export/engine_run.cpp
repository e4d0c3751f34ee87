// Running an installed engine on a deck (simulation/export/engine_run.hpp).
#include "hertzdash/simulation/export/engine_run.hpp"

#include "hertzdash/io/child_process.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace hertzdash {

bool engine_installed(Engine engine) { return on_path(std::string(engine_program(engine).program)); }

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
  // The engines are MPI programs: run alone, Open MPI's singleton would start a support daemon
  // (a few tenths of a second each run, and one more process to wait for under load); isolated,
  // it runs as the one process it is. mpirun ignores it. Its own process group, so that a timeout
  // kills mpirun's ranks with it.
  // YADE reads HOME at start (its IPython profile) and stops with a KeyError without one: a
  // run with no HOME (a bare CI container) gives it the run's directory.
  std::vector<std::string> environment{"OMPI_MCA_ess_singleton_isolated=1"};
  if (!std::getenv("HOME")) environment.push_back("HOME=" + directory.string());
  const ChildProcess child{.args = std::move(args), .directory = directory, .output = screen, .errors = {},
                           .environment = std::move(environment), .own_process_group = true, .timeout = timeout};
  // A run that stops without the engine's own ERROR line (an exit status or a signal, no
  // message) and before the timeout is run once more: once in some ten runs of the whole suite on
  // two loaded cores, the `conformance` test failed beside an mpirun and not again, its message
  // lost (an engine's start under load is the likely cause, not a proven one). An ERROR line (the
  // deck's fault) and a timeout are final.
  std::string first_failure;
  for (int attempt = 1;; ++attempt) {
    const ChildExit exit = run_child(child, "; " + install_hint);
    std::ostringstream said;
    said << std::ifstream(screen).rdbuf();
    const std::string error = line_starting(said.str(), "ERROR");
    if (exit.succeeded() && error.empty()) return said.str();
    // The directory may be a temporary one, gone with the exception: the message carries the
    // engine's own words, its ERROR line or the end of what it printed.
    const std::string& out = said.str();
    const std::string failure =
        fmt::format("{} failed: {}; the end of its output: {}", child.args[0], error.empty() ? exit.why(child) : error,
                    out.substr(out.size() > 600 ? out.size() - 600 : 0));
    if (!error.empty() || exit.timed_out || attempt == 2)
      throw std::runtime_error(first_failure.empty() ? failure : failure + " (run twice; the first time: " + first_failure + ")");
    first_failure = failure;
  }
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
