// The examples of the README and of the pages in docs/ are true: every ```console block
// that starts with "$ build/hertzdash ARGS" shows exactly what `hertzdash ARGS` prints, stderr
// included, as a terminal shows it: the program's notes and warnings on stderr come before the
// result it prints on stdout; and docs/simulate.md names every integrator.
#include "cli_runner.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"

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
      CHECK(r.err + r.out == expected);
      ++examples;
      readme_examples += page.filename() == "README.md";
    }
  }
  CHECK(readme_examples >= 1);
  CHECK(examples > readme_examples);
}

TEST_CASE("docs/simulate.md lists every integrator of the table, in its order", "[readme]") {
  // The page spells the choices as `--integrator a|b|...`; a row added to the integrator
  // table (simulation/run/integrator_table.hpp) without the page left it out once.
  const std::string page = slurp(std::filesystem::path(HERTZDASH_SOURCE_DIR) / "docs" / "simulate.md");
  const std::string key = "`--integrator ";
  const auto start = page.find(key);
  REQUIRE(start != std::string::npos);
  const auto end = page.find('`', start + key.size());
  REQUIRE(end != std::string::npos);
  std::string expected;
  for (const hertzdash::IntegratorTraits& row : hertzdash::all_integrator_traits) {
    if (!expected.empty()) expected += '|';
    expected += row.name;
  }
  CHECK(page.substr(start + key.size(), end - start - key.size()) == expected);
}

TEST_CASE("The README is a front page: the two commands first, under 12,000 characters", "[readme]") {
  // Issue 32: the README had grown to a reference (the measured speed table among it); the
  // detail lives in docs/, the README says what hertzdash is and links there.
  const std::string readme = slurp(std::filesystem::path(HERTZDASH_SOURCE_DIR) / "README.md");
  CHECK(readme.size() < 12000);
  CHECK(readme.rfind("# hertzdash\n\n```sh\nmake figures", 0) == 0);
  CHECK(readme.find("\nmake test") < 200);
  CHECK(readme.find("perf:begin") == std::string::npos);  // the measured table is docs/performance.md's
}
