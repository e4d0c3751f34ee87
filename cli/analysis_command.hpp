#pragma once
// The commands that analyse a rig's impact sequence (simulation/rigs/rig_orbit.hpp): `orbit`,
// `continue` and `lyapunov`, each one subcommand per rig with a sequence (Rig::sequence), with
// the rig's options for instantaneous impacts (cli/rig_options.hpp) and the command's own,
// declared in simulation/options/command_options.cpp: numbers and texts into `given`, --json,
// --csv FILE and --mkdir where declared. The frame and the three commands: analysis_commands.cpp.
#include "cli/command.hpp"

#include <functional>
#include <string>
#include <string_view>

namespace hertzdash::cli {

/// One parsed subcommand's request.
struct AnalysisRequest {
  const Rig* rig = nullptr;
  CLI::App* sub = nullptr;
  RunOptions run;
  RigInputs inputs, given;
  std::string csv_path;
  bool json = false, mkdir = false;
};

/// Runs a parsed request and returns the exit code.
using AnalysisRun = std::function<int(const AnalysisRequest&)>;

/// `hertzdash COMMAND RIG` for every rig with a sequence; `what` is the subcommand's description
/// after "... of `hertzdash RIG`".
Command add_analysis_command(CLI::App& app, std::string_view command, const std::string& description,
                             const std::string& what, AnalysisRun run);

}  // namespace hertzdash::cli
