#pragma once
// A scratch directory for one test: <temp>/hertzdash_test_<pid>_<n>, created empty and removed
// with all it holds when the test is done. The process id and a per-process count keep the
// directories of tests running at the same time (ctest -j) and of nested scratches apart.
#include <algorithm>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace hertzdash::test {

class ScratchDir {
 public:
  ScratchDir() : path(std::filesystem::temp_directory_path() / name()) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  /// Writes `text` to the file `file` in the directory; returns its path.
  std::filesystem::path write(const std::string& file, const std::string& text) const {
    std::ofstream(path / file) << text;
    return path / file;
  }
  /// The names in the directory, sorted.
  std::vector<std::string> names() const {
    std::vector<std::string> n;
    for (const auto& e : std::filesystem::directory_iterator(path)) n.push_back(e.path().filename().string());
    std::sort(n.begin(), n.end());
    return n;
  }

  const std::filesystem::path path;

 private:
  static std::string name() {
    static std::atomic<int> count{0};
    return "hertzdash_test_" + std::to_string(::getpid()) + "_" + std::to_string(count++);
  }
};

}  // namespace hertzdash::test
