// The examples of the README and of the pages in docs/ are true: every ```console block
// that starts with "$ build/hertzdash ARGS" shows exactly what `hertzdash ARGS` prints.
#include "cli_runner.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

using hertzdash::test::run_cli;
using hertzdash::test::slurp;

TEST_CASE("README and docs/: every hertzdash example prints what the page shows", "[readme][cli]") {
  const std::filesystem::path source(HERTZDASH_SOURCE_DIR);
  std::vector<std::filesystem::path> pages{source / "README.md"};
  for (const auto& entry : std::filesystem::directory_iterator(source / "docs"))
    if (entry.path().extension() == ".md") pages.push_back(entry.path());
  const std::string prompt = "$ build/hertzdash ";
  int examples = 0, readme_examples = 0;
  for (const auto& page : pages) {
    std::istringstream text(slurp(page));
    std::string line;
    while (std::getline(text, line)) {
      if (line != "```console") continue;
      std::getline(text, line);
      if (line.rfind(prompt, 0) != 0) continue;
      const std::string args = line.substr(prompt.size());
      std::string expected;
      while (std::getline(text, line) && line != "```") expected += line + "\n";
      const auto r = run_cli(args);
      INFO(page.filename().string() << " example: hertzdash " << args);
      CHECK(r.exit_code == 0);
      CHECK(r.out == expected);
      ++examples;
      readme_examples += page.filename() == "README.md";
    }
  }
  CHECK(readme_examples >= 1);
  CHECK(examples > readme_examples);
}
