#include "hertzdash/io/output_directories.hpp"

#include <cerrno>
#include <stdexcept>
#include <string>
#include <sys/stat.h>
#include <system_error>

namespace hertzdash {

namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const fs::path& dir, int error) {
  throw std::runtime_error("cannot create directory " + dir.string() + ": " + std::generic_category().message(error));
}

}  // namespace

std::vector<fs::path> missing_parent_directories(const fs::path& file) {
  std::vector<fs::path> missing;
  fs::path below;  // the directory that would be created inside `dir`; empty: `dir` is the parent
  for (fs::path dir = file.parent_path(); !dir.empty(); below = dir, dir = dir.parent_path()) {
    struct stat st {};
    if (::stat(dir.c_str(), &st) == 0) {
      if (S_ISDIR(st.st_mode)) break;
      if (below.empty()) throw std::runtime_error("cannot write into " + dir.string() + ": it is not a directory");
      fail(below, ENOTDIR);
    }
    if (errno != ENOENT) fail(dir, errno);
    missing.insert(missing.begin(), dir);
    if (dir == dir.parent_path()) break;
  }
  return missing;
}

void create_parent_directories(const fs::path& file) {
  for (const fs::path& dir : missing_parent_directories(file)) {
    if (::mkdir(dir.c_str(), 0777) == 0) continue;
    const int error = errno;
    struct stat st {};
    if (error == EEXIST && ::stat(dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode)) continue;  // made meanwhile
    fail(dir, error == EEXIST ? ENOTDIR : error);
  }
}

}  // namespace hertzdash
