#pragma once
// The options of the commands themselves, beside the options of a run (run_options.hpp) and a
// rig's inputs (simulation/rigs/rig.hpp): what to print, which files to write, how many bounces,
// the calibration targets, each declared once (key, unit, range, default and its source, help;
// model/parameter.hpp). The command line's options take their names and help from here, and
// `hertzdash parameters` (docs/parameters.md) lists them per command.
#include "hertzdash/model/parameter.hpp"

#include <span>
#include <string_view>

namespace hertzdash {

/// A command's own options. `command` "RIG" holds those of every rig's command (`hertzdash
/// shaker`, `hertzdash walls`, ...), a rig's name those of that rig's command alone.
struct CommandOptions {
  std::string_view command;
  ParameterDecls options;
};

/// Every command, in the order of the commands, with its own options (`fit`'s empty here: ask
/// options_of_command("fit"), which is fit_command_options()).
std::span<const CommandOptions> command_options();

/// `hertzdash fit`'s own options, declared with the fit's table (empty until it is).
ParameterDecls fit_command_options();

/// The declared options of `command` (empty: none).
ParameterDecls options_of_command(std::string_view command);

/// The declaration of `command`'s option `key`; std::logic_error if there is none.
const ParameterDecl& command_option(std::string_view command, std::string_view key);

}  // namespace hertzdash
