#pragma once
// The missing directories above an output file, found and created as `mkdir -p` would, with
// the system's reason in every error (docs/output-files.md). The CLI looks them up while it
// validates its input and creates them only right before it writes (--mkdir).
#include <filesystem>
#include <vector>

namespace hertzdash {

/// The directories above `file` that do not exist yet, outermost first (empty: its parent
/// exists). Throws std::runtime_error "cannot create directory P: REASON" when one could not be
/// created: a component of the path is a file (Not a directory), a symbolic-link loop (Too many
/// levels of symbolic links), a directory that cannot be searched (Permission denied); or
/// "cannot write into P: it is not a directory" when the parent P is a file.
std::vector<std::filesystem::path> missing_parent_directories(const std::filesystem::path& file);

/// Create missing_parent_directories(file), outermost first (mode 0777 less the umask). Throws
/// the same std::runtime_error, REASON from errno, if one cannot be created.
void create_parent_directories(const std::filesystem::path& file);

}  // namespace hertzdash
