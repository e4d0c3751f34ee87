#pragma once
// "did you mean --height?": the message for options a command does not have (CLI11 reports
// them only as "The following arguments were not expected").
#include <CLI/CLI.hpp>

#include <string>

namespace hertzdash::cli {

/// For each argument `--name` (or `--name=value`) in argv that `command` has no option for: the
/// sentence "unknown option --name", with "; did you mean --other?" where an option of the
/// command is within an edit distance of 2 (or a third of the name's length, if more) of it.
/// Empty when every `--name` is known.
std::string unknown_options_message(const CLI::App& command, int argc, char** argv);

}  // namespace hertzdash::cli
