#include "hertzdash/io/file_identity.hpp"

#include "hertzdash/io/atomic_file.hpp"

#include <sys/stat.h>

#include <filesystem>
#include <stdexcept>
#include <system_error>
#include <utility>

namespace hertzdash {

namespace {

// What makes two paths one file: "device:inode" of a file that exists, else where it would be
// made. nullopt: an output written through, which replaces nothing.
std::optional<std::string> identity(const std::string& path, bool output) {
  namespace fs = std::filesystem;
  fs::path file(path);
  if (output) {
    try {
      const std::optional<fs::path> replaced = replaced_file(file);
      if (!replaced) return std::nullopt;
      file = *replaced;
    } catch (const std::runtime_error&) {  // its directory is still to be made (--mkdir): nothing in it exists
      std::error_code ec;
      file = fs::weakly_canonical(fs::absolute(file, ec), ec);
    }
  }
  struct stat st {};
  if (::stat(file.c_str(), &st) == 0) return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino);
  std::error_code ec;
  return fs::weakly_canonical(fs::absolute(file, ec), ec).string();
}

}  // namespace

std::optional<SharedFile> find_shared_file(const std::vector<std::string>& inputs,
                                           const std::vector<std::string>& outputs) {
  struct Seen {
    std::size_t index;
    bool input;
    std::string id;
  };
  std::vector<Seen> seen;  // the inputs, then the outputs checked
  for (std::size_t i = 0; i < inputs.size(); ++i)
    if (!inputs[i].empty())
      if (std::optional<std::string> id = identity(inputs[i], false)) seen.push_back({i, true, std::move(*id)});
  for (std::size_t o = 0; o < outputs.size(); ++o) {
    if (outputs[o].empty()) continue;
    std::optional<std::string> id = identity(outputs[o], true);
    if (!id) continue;
    for (const Seen& s : seen)
      if (s.id == *id) return SharedFile{o, s.index, s.input};
    seen.push_back({o, false, std::move(*id)});
  }
  return std::nullopt;
}

}  // namespace hertzdash
