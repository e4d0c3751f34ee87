#pragma once
// Outputs never clobber what they should not.
// - A regular file, or a path where nothing exists yet, is written to a temporary file beside
//   it (NAME.tmp.PID.N) and renamed over it: a failed or killed run leaves the previous file
//   whole, and any signal but SIGKILL removes the temporary (io/remove_on_signal.hpp).
// - A symbolic link is followed: the file it names is written (as above), the link stays.
// - Anything else that exists is written through, as a shell redirection would: a FIFO, a
//   character device (/dev/null, a terminal), and the process's own open files
//   (/dev/stdout, /dev/fd/N, /proc/self/fd/N: the descriptor itself, a pipe included).
// - A directory is an error, and so is a missing parent directory: none is created here
//   (the CLI's --mkdir does that, docs/output-files.md).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hertzdash {

/// Write `content` to `path` as described above. Throws std::runtime_error
/// "cannot write PATH: REASON" (REASON from errno, e.g. "Is a directory") on failure.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

/// Write each (path, content) as write_file_atomically does, as a set: every temporary is
/// written and synced first, then all are renamed with the signals held (SignalHold), so a
/// signal leaves every file replaced or none. A failure before the renames replaces none.
void write_files_atomically(const std::vector<std::pair<std::filesystem::path, std::string>>& files);

/// A file's content made piece by piece: it calls `write` with each piece in order, so that a
/// large table goes to its file as it is formatted instead of being held whole. It must give
/// the same pieces each time it is called (a file written through is written after the renames).
using ContentPieces = std::function<void(const std::function<void(std::string_view)>& write)>;

/// write_files_atomically with each content given in pieces.
void write_files_atomically(const std::vector<std::pair<std::filesystem::path, ContentPieces>>& files);

/// The file a write to `path` replaces by rename (symbolic links followed, parent directory
/// canonical; it may not exist yet), or nullopt if the write goes through (a FIFO, a device,
/// an open descriptor). Throws as write_file_atomically (a missing directory, a directory).
std::optional<std::filesystem::path> replaced_file(const std::filesystem::path& path);

/// Check, before any work, that write_file_atomically(path, ...) can write: a temporary can be
/// made beside a regular or new file (it is removed at once), a file written through exists
/// and is writable. Throws as write_file_atomically ("cannot write PATH: Permission denied").
void check_writable(const std::filesystem::path& path);

/// `target`'s name with `suffix` appended, beside it, cut short (at a UTF-8 character's start)
/// to fit the 255 bytes a file name may have; the suffix is kept whole.
std::filesystem::path sibling_path(const std::filesystem::path& target, const std::string& suffix);

}  // namespace hertzdash
