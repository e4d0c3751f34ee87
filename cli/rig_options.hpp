#pragma once
// The options of a run of a registered rig (simulation/rigs/rig.hpp) on a subcommand, generated
// from its schemas: `hertzdash RIG` (cli/rig_command.cpp) and `hertzdash orbit RIG`
// (cli/orbit_command.cpp) share them.
#include "hertzdash/simulation/rigs/rig.hpp"

#include <CLI/CLI.hpp>

namespace hertzdash::cli {

/// The options of a run the rig reads (the others stay options, refused with their reason when
/// given, but out of the help) and its own inputs (--KEY, help, valid values and default from
/// the declarations, in the group "The RIG rig"), parsed into `run` and `inputs`, which the
/// caller keeps alive as long as `sub`. `instantaneous`: for `orbit RIG` and `continue RIG`, which
/// analyse instantaneous impacts (simulation/rigs/rig_orbit.hpp): the impact model defaults to
/// instantaneous, and the help lists only the run options those read (Rig::instantaneous_reads).
void add_rig_options(CLI::App& sub, const Rig& rig, RunOptions& run, RigInputs& inputs, bool instantaneous = false);

}  // namespace hertzdash::cli
