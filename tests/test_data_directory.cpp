// The data tables are found at run time, not through a path compiled into the program:
// $HERTZDASH_DATA_DIR if set, else share/hertzdash/data in the program's directory or the one above it
// (simulation/paper_parameters.hpp). Checked on copies of build/hertzdash laid out as an
// installation would be (PREFIX/bin/hertzdash with PREFIX/share/hertzdash/data), so the
// program cannot be finding the source tree by a remembered path.
#include "cli_runner.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

/// PREFIX/bin/hertzdash, a copy of the built program, in a fresh scratch prefix.
fs::path scratch_prefix(const std::string& name) {
  const fs::path prefix = fs::temp_directory_path() / ("hertzdash_" + name + "_" + std::to_string(::getpid()));
  fs::remove_all(prefix);
  fs::create_directories(prefix / "bin");
  fs::copy_file(HERTZDASH_BIN, prefix / "bin" / "hertzdash");
  return prefix;
}

hertzdash::test::CliResult run(const fs::path& program, const std::string& env = "") {
  return hertzdash::test::run_cli_program(program.string(), "simulate --json", env);
}

}  // namespace

TEST_CASE("The program finds PREFIX/share/hertzdash/data from PREFIX/bin", "[data]") {
  const fs::path prefix = scratch_prefix("prefix");
  fs::create_directories(prefix / "share" / "hertzdash");
  fs::copy(fs::path(HERTZDASH_SOURCE_DIR) / "data", prefix / "share" / "hertzdash" / "data", fs::copy_options::recursive);
  const auto r = run(prefix / "bin" / "hertzdash");
  INFO(r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("\"e_effective\"") != std::string::npos);
  fs::remove_all(prefix);
}

TEST_CASE("Without tables beside it, the program says so and how to point at them", "[data]") {
  const fs::path prefix = scratch_prefix("no_data");
  const auto missing = run(prefix / "bin" / "hertzdash");
  CHECK(missing.exit_code != 0);
  CHECK(missing.out.empty());
  CHECK(missing.err.find("HERTZDASH_DATA_DIR") != std::string::npos);
  CHECK(missing.err.find("share/hertzdash/data") != std::string::npos);

  // The variable overrides the search.
  const auto given = run(prefix / "bin" / "hertzdash", "HERTZDASH_DATA_DIR=" + std::string(HERTZDASH_SOURCE_DIR) + "/data");
  INFO(given.err);
  CHECK(given.exit_code == 0);
  fs::remove_all(prefix);
}
