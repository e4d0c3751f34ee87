#pragma once
// The output files of a command: --mkdir, and the check, before any work, that each output
// path can be written (docs/output-files.md). Without --mkdir a missing parent directory is
// bad input (exit 2, the option and the missing directory named); nothing is created silently.
#include <CLI/CLI.hpp>

#include <string>

namespace hertzdash::cli {

/// Add --mkdir to `sub`, bound to `make_directories`.
void add_mkdir_flag(CLI::App& sub, bool& make_directories);

/// Check the output file `path` given by `option` (a no-op for an empty path): its parent
/// directory exists, or is created when `make_directories`; the path is not a directory.
/// Throws InvalidParameter naming the option otherwise.
void prepare_output_file(const std::string& option, const std::string& path, bool make_directories);

}  // namespace hertzdash::cli
