// The build times the README states are measured, not typed: the README's sentence and the table
// of docs/build-times.md are the generated blocks tools/measure-build-times.sh (make build-times)
// writes from one measurement, so the README's cold-build and rebuild times are the table's.
#include "cli_runner.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <string>

using hertzdash::test::slurp;

namespace {

/// The text between "<!-- build-times:begin" (that line excluded) and "<!-- build-times:end -->".
std::string build_times_block(const std::string& page) {
  const std::size_t begin = page.find("<!-- build-times:begin");
  const std::size_t end = page.find("<!-- build-times:end -->");
  if (begin == std::string::npos || end == std::string::npos || end < begin) return {};
  const std::size_t first = page.find('\n', begin) + 1;
  return first <= end ? page.substr(first, end - first) : std::string{};
}

/// The text between `after` and the next `until` in `text` (a duration: "30 min 43 s").
std::string duration_after(const std::string& text, const std::string& after, const std::string& until) {
  const std::size_t at = text.find(after);
  if (at == std::string::npos) return {};
  const std::size_t start = at + after.size();
  return text.substr(start, text.find(until, start) - start);
}

}  // namespace

TEST_CASE("the README's build times are docs/build-times.md's measurement", "[readme]") {
  const std::filesystem::path source(HERTZDASH_SOURCE_DIR);
  const std::string readme_page = slurp(source / "README.md");
  const std::string readme = build_times_block(readme_page);
  const std::string page = build_times_block(slurp(source / "docs/build-times.md"));
  REQUIRE(!readme.empty());
  REQUIRE(!page.empty());
  // Beside the two opening commands: right after them.
  CHECK(readme_page.find("<!-- build-times:begin") > readme_page.find("\nmake test"));
  CHECK(readme_page.find("<!-- build-times:begin") < 400);
  const std::string cold = duration_after(readme, "Cold build: ", " on ");
  const std::string rebuild = duration_after(readme, "); ", " after editing one law");
  INFO("README: " << readme);
  REQUIRE(!cold.empty());
  REQUIRE(!rebuild.empty());
  CHECK(page.find("| " + cold + " |") != std::string::npos);
  CHECK(page.find("| " + rebuild + " |") != std::string::npos);
}
