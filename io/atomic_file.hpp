#pragma once
// Outputs never clobber what they should not.
// - A regular file, or a path where nothing exists yet, is written to a temporary file beside
//   it (NAME.tmp.PID.N) and renamed over it: a failed or killed run leaves the previous file
//   whole, and SIGINT/SIGTERM/SIGHUP remove the temporary (io/remove_on_signal.hpp).
// - A symbolic link is followed: the file it names is written (as above), the link stays.
// - Anything else that exists is written through, as a shell redirection would: a FIFO, a
//   character device (/dev/null, a terminal), and the process's own open files
//   (/dev/stdout, /dev/fd/N, /proc/self/fd/N: the descriptor itself, a pipe included).
// - A directory is an error, and so is a missing parent directory: none is created here
//   (the CLI's --mkdir does that, docs/output-files.md).
#include <filesystem>
#include <string>

namespace hertzdash {

/// Write `content` to `path` as described above. Throws std::runtime_error
/// "cannot write PATH: REASON" (REASON from errno, e.g. "Is a directory") on failure.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace hertzdash
