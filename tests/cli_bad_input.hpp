#pragma once
// Bad input of a command: each case exits with code 2, names its option on stderr, prints
// nothing on stdout and writes no `--csv` file.
#include "cli_runner.hpp"
#include "scratch_dir.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <initializer_list>
#include <string>

namespace hertzdash::test {

struct BadInput {
  std::string args, option;  ///< appended to the command; the option the refusal must name
};

inline void check_bad_inputs(const std::string& command, std::initializer_list<BadInput> cases) {
  const ScratchDir dir;
  const std::string csv = (dir.path / "never.csv").string();
  for (const BadInput& c : cases) {
    const auto r = run_cli(command + " " + c.args + " --csv " + csv);
    INFO(c.args << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.option) != std::string::npos);
    CHECK(r.out.empty());
    CHECK_FALSE(std::filesystem::exists(csv));
  }
}

}  // namespace hertzdash::test
