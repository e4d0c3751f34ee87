#pragma once
// A temporary directory of a program's own (mkdtemp under the system's temporary directory),
// removed with everything in it when it goes out of scope: where a figure is drawn, an engine
// runs its decks.
#include <filesystem>
#include <string_view>

namespace hertzdash {

class TemporaryDirectory {
 public:
  /// Creates <temp>/hertzdash-<purpose>.XXXXXX; std::runtime_error naming `purpose` if it cannot.
  explicit TemporaryDirectory(std::string_view purpose);
  ~TemporaryDirectory();
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

  std::filesystem::path path;
};

}  // namespace hertzdash
