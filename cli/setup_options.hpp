#pragma once
// The command-line options of a run: every option of the library's table
// (simulation/options/run_options.hpp) as --name, bound to one RunOptions. Parsing only: the
// library validates (resolve_setup, resolve_solver) and names the option in its message.
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/reports/diagnostic_messages.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace hertzdash::cli {

/// Add every option of `group` to `app`, writing into `options` (which must outlive `app`).
void add_run_options(CLI::App& app, RunOptions& options, RunOption::Group group);

/// Both groups: the set-up's options, then the solver's.
void add_run_options(CLI::App& app, RunOptions& options);

/// The flag ("--key") and help (help_text) of command `command`'s own option `key`, declared in
/// simulation/options/command_options.hpp.
struct DeclaredOption {
  std::string flag, help;
};
DeclaredOption declared_option(std::string_view command, std::string_view key);

/// Each note and warning on stderr: "hertzdash: <kind>: <message>".
void report_diagnostics(const std::vector<RunDiagnostic>& diagnostics);

}  // namespace hertzdash::cli
