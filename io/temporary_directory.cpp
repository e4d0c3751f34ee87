// A temporary directory removed with its contents (io/temporary_directory.hpp).
#include "hertzdash/io/temporary_directory.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string>
#include <system_error>

namespace hertzdash {

TemporaryDirectory::TemporaryDirectory(std::string_view purpose) {
  std::string pattern = (std::filesystem::temp_directory_path() / ("hertzdash-" + std::string(purpose) + ".XXXXXX")).string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary directory for the " + std::string(purpose));
  path = pattern;
}

TemporaryDirectory::~TemporaryDirectory() {
  std::error_code ignored;
  std::filesystem::remove_all(path, ignored);
}

}  // namespace hertzdash
