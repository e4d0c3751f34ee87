#pragma once
// Running an installed engine on a deck of simulation/export/engine_models.hpp and reading back
// the impact: the rebound speed the deck prints, and its contact-force file (the contact time is
// the number of steps with a non-zero force times the time step, the peak force the largest).
#include "hertzdash/simulation/export/engine_models.hpp"

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

namespace hertzdash {

/// How long an engine run may take before it is killed: ten times the slowest run the suite and
/// the studies make (`make gas`'s 13824 spheres for 40 Haff times, about 80 s each law).
inline constexpr std::chrono::seconds engine_run_timeout{900};

/// Runs `args` (args[0] looked up on PATH) in `directory`, its standard output and error into
/// `screen`, and returns what it printed; an MPI program run alone is an isolated singleton.
/// Throws std::runtime_error saying the program cannot start (with `install_hint`), that it
/// failed (its first line that starts with "ERROR", or its exit status or signal, with the end of
/// its output), or that it ran past `timeout` (then it and every process it started, its process
/// group, are killed: a hung engine does not hang its caller). A run that stops without an ERROR
/// line, before the timeout, is run once more (a transient failure seen once, cause unknown).
std::string run_in_directory(std::vector<std::string> args, const std::filesystem::path& directory,
                             const std::filesystem::path& screen, const std::string& install_hint,
                             std::chrono::seconds timeout = engine_run_timeout);

/// Writes a deck's text to `path`; std::runtime_error if it cannot.
void write_deck(const std::filesystem::path& path, const std::string& text);

/// Runs the engine's program (engine_program(engine).command) on `deck` (written to `directory` as `deck_name`, with the
/// engine's screen output beside it as `deck_name`.out) and reads its result; `approach_speed_mps`
/// turns the rebound speed into e. Throws std::runtime_error naming the engine and its ERROR
/// line, or saying the program is not installed (`make deps-engines`).
EngineImpactResult run_engine_deck(Engine engine, const EngineDeck& deck, const std::filesystem::path& directory,
                                   const std::string& deck_name, double approach_speed_mps);

/// Whether the engine's program is on PATH.
bool engine_installed(Engine engine);

}  // namespace hertzdash
