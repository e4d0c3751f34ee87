#include "cli/output_files.hpp"

#include "hertzdash/io/output_directories.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <filesystem>
#include <system_error>
#include <vector>

namespace hertzdash::cli {

CLI::Option* add_output_file_option(CLI::App& sub, const std::string& flag, std::string& path, const std::string& help) {
  return sub.add_option_function<std::string>(
      flag,
      [&path, flag](const std::string& text) {
        if (text.empty()) throw InvalidParameter(flag, "''", "a file path (not empty)");
        path = text;
      },
      help);
}

void add_mkdir_flag(CLI::App& sub, bool& make_directories) {
  sub.add_flag("--mkdir", make_directories,
               "Create the missing parent directories of the output files, right before writing them (without it, a "
               "missing directory is an error)");
}

void prepare_output_file(const std::string& option, const std::string& path, bool make_directories) {
  namespace fs = std::filesystem;
  if (path.empty()) return;
  const fs::path file(path);
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (status.type() == fs::file_type::directory) throw InvalidParameter(option, path, "a file, not a directory");
  std::vector<fs::path> missing;
  try {
    missing = missing_parent_directories(file);
  } catch (const std::runtime_error& e) {
    throw InvalidParameter(option, path, std::string("a file in a directory that exists or can be created (") + e.what() + ")");
  }
  if (ec && status.type() != fs::file_type::not_found)
    throw InvalidParameter(option, path, "a path that can be written (" + ec.message() + ")");
  if (!missing.empty() && !make_directories)
    throw InvalidParameter(option, path,
                           "a file in an existing directory (" + file.parent_path().string() +
                               " does not exist; --mkdir creates it)");
}

void create_output_directories(const std::string& path, bool make_directories) {
  if (!path.empty() && make_directories) create_parent_directories(path);
}

}  // namespace hertzdash::cli
