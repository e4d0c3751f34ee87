#pragma once
// The output files of a command (docs/output-files.md): the options that name them (an empty
// path is refused), --mkdir, the check before any work that each path can be written, and the
// creation of the missing directories right before the write. Without --mkdir a missing parent
// directory is bad input (exit 2, the option and the missing directory named); with it, bad
// input of any kind still leaves no new directory: nothing is created until the output is.
// An output that is the same file as an input or as another output is refused too.
#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace hertzdash::cli {

/// Add the output file option `flag` to `sub`, bound to `path`; an empty path given is refused
/// (InvalidParameter naming the option).
CLI::Option* add_output_file_option(CLI::App& sub, const std::string& flag, std::string& path, const std::string& help);

/// Add --mkdir to `sub`, bound to `make_directories`.
void add_mkdir_flag(CLI::App& sub, bool& make_directories);

/// Check the output file `path` given by `option` (a no-op for an empty path: none asked for):
/// it is not a directory, its parent directory exists and a file can be made in it (or is
/// missing and can be created, the nearest existing one writable, and `make_directories` says
/// so). Creates nothing that stays. Throws InvalidParameter naming the option.
void prepare_output_file(const std::string& option, const std::string& path, bool make_directories);

/// A file a command reads or writes, and the option (or case-file key) that names it.
struct CommandFile {
  std::string option;
  std::string path;  // empty: none given
};

/// Refuse (InvalidParameter naming both options) an output that is the same file as an input
/// or as another output: the same device and inode for a file that exists, the same canonical
/// directory and name for one that does not yet, symbolic links followed and hard links found.
/// Outputs written through (/dev/null, a FIFO, a terminal) replace nothing and may be shared.
void refuse_shared_files(const std::vector<CommandFile>& inputs, const std::vector<CommandFile>& outputs);

/// Right before writing `path` (a no-op for an empty path): create its missing parent
/// directories if `make_directories`. Throws std::runtime_error "cannot create directory P:
/// REASON" on failure (exit 1).
void create_output_directories(const std::string& path, bool make_directories);

}  // namespace hertzdash::cli
