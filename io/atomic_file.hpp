#pragma once
// Outputs are written atomically: to a temporary file beside the target, then
// renamed over it, so a failed run never leaves a half-written file.
#include <filesystem>
#include <string>

namespace hertzdash {

/// Write `content` to `path` atomically; creates missing parent directories.
/// Throws std::runtime_error naming the path on failure.
void write_file_atomically(const std::filesystem::path& path, const std::string& content);

}  // namespace hertzdash
