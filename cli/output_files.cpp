#include "cli/output_files.hpp"

#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/file_identity.hpp"
#include "hertzdash/io/output_directories.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/options/command_options.hpp"

#include <filesystem>
#include <optional>
#include <sys/stat.h>
#include <system_error>
#include <unistd.h>
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
  sub.add_flag("--mkdir", make_directories, std::string(command_option("RIG", "mkdir").help));
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
  // Found now, not after the runs: a folder the user may not write to, a read-only file system.
  if (!missing.empty()) {
    const fs::path existing = missing.front().parent_path();
    if (::access(existing.empty() ? "." : existing.c_str(), W_OK | X_OK) != 0)
      throw InvalidParameter(option, path,
                             "a file in a directory that can be created (cannot create directory " +
                                 missing.front().string() + ": " + std::generic_category().message(errno) + ")");
    return;
  }
  try {
    check_writable(file);
  } catch (const std::runtime_error& e) {
    throw InvalidParameter(option, path, std::string("a file that can be written (") + e.what() + ")");
  }
}

void refuse_shared_files(const std::vector<CommandFile>& inputs, const std::vector<CommandFile>& outputs) {
  std::vector<std::string> input_paths, output_paths;
  for (const CommandFile& f : inputs) input_paths.push_back(f.path);
  for (const CommandFile& f : outputs) output_paths.push_back(f.path);
  if (const std::optional<SharedFile> shared = find_shared_file(input_paths, output_paths)) {
    const CommandFile& out = outputs[shared->output];
    const CommandFile& other = shared->other_is_input ? inputs[shared->other] : outputs[shared->other];
    throw InvalidParameter(out.option, out.path,
                           "another file than " + other.option + " (" + other.path + "), which " +
                               (shared->other_is_input ? "is read" : "is written too") + ": they are the same file");
  }
}

void create_output_directories(const std::string& path, bool make_directories) {
  if (!path.empty() && make_directories) create_parent_directories(path);
}

}  // namespace hertzdash::cli
