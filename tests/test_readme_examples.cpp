// The README's examples are true: every ```console block that starts with
// "$ build/hertzdash ARGS" shows exactly what `hertzdash ARGS` prints.
#include "cli_runner.hpp"

#include <catch2/catch.hpp>

#include <sstream>

using hertzdash::test::run_cli;
using hertzdash::test::slurp;

TEST_CASE("README: every hertzdash example prints what the README shows", "[readme][cli]") {
  std::istringstream readme(slurp(std::filesystem::path(HERTZDASH_SOURCE_DIR) / "README.md"));
  const std::string prompt = "$ build/hertzdash ";
  std::string line;
  int examples = 0;
  while (std::getline(readme, line)) {
    if (line != "```console") continue;
    std::getline(readme, line);
    if (line.rfind(prompt, 0) != 0) continue;
    const std::string args = line.substr(prompt.size());
    std::string expected;
    while (std::getline(readme, line) && line != "```") expected += line + "\n";
    const auto r = run_cli(args);
    INFO("README example: hertzdash " << args);
    CHECK(r.exit_code == 0);
    CHECK(r.out == expected);
    ++examples;
  }
  CHECK(examples >= 1);
}
