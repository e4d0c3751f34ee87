#include "cli/output_files.hpp"

#include "hertzdash/model/invalid_parameter.hpp"

#include <filesystem>

namespace hertzdash::cli {

void add_mkdir_flag(CLI::App& sub, bool& make_directories) {
  sub.add_flag("--mkdir", make_directories,
               "Create the missing parent directories of the output files (without it, a missing directory is an "
               "error)");
}

void prepare_output_file(const std::string& option, const std::string& path, bool make_directories) {
  namespace fs = std::filesystem;
  if (path.empty()) return;
  const fs::path file(path);
  if (fs::is_directory(file)) throw InvalidParameter(option, path, "a file, not a directory");
  const fs::path parent = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  if (fs::is_directory(parent)) return;
  if (fs::exists(parent)) throw InvalidParameter(option, path, "a file in a directory (" + parent.string() + " is not one)");
  if (!make_directories)
    throw InvalidParameter(option, path,
                           "a file in an existing directory (" + parent.string() + " does not exist; --mkdir creates it)");
  fs::create_directories(parent);
}

}  // namespace hertzdash::cli
