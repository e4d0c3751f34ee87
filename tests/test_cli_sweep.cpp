// `hertzdash sweep` as a user runs it: the README's example as written, the files it writes and
// where, bad case files, every run failing, and Ctrl-C.
#include "scratch_dir.hpp"
#include "cli_runner.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/simulation/sweep/sweep_outputs.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

using hertzdash::test::run_cli_program;
using hertzdash::test::slurp;
namespace fs = std::filesystem;

using hertzdash::test::ScratchDir;

namespace {

// `hertzdash ARGS` run in `dir`.
hertzdash::test::CliResult run_in(const fs::path& dir, const std::string& args) {
  return run_cli_program("cd " + dir.string() + " && " HERTZDASH_BIN, args);
}

std::size_t data_rows(const std::string& csv) {
  std::size_t rows = 0;
  std::istringstream in(csv);
  for (std::string line; std::getline(in, line);) rows += !line.empty() && line[0] != '#';
  return rows - 1;  // the column names
}

}  // namespace

TEST_CASE("The README's sweep example runs as written and prints what the README shows", "[cli][sweep][readme]") {
  // The README's ```toml block is saved under the name the text gives it, the command under it
  // is run in that folder, and its output must be the README's, line for line.
  std::istringstream readme(slurp(fs::path(HERTZDASH_SOURCE_DIR) / "README.md"));
  std::string line, toml, command, shown;
  while (std::getline(readme, line) && line != "```toml") {}
  while (std::getline(readme, line) && line != "```") toml += line + "\n";
  while (std::getline(readme, line) && line.rfind("$ build/hertzdash sweep ", 0) != 0) {}
  command = line.substr(std::string("$ build/hertzdash ").size());
  while (std::getline(readme, line) && line != "```") shown += line + "\n";
  REQUIRE(!toml.empty());
  REQUIRE(command == "sweep laws-heights.toml");

  const ScratchDir dir;
  dir.write("laws-heights.toml", toml);
  const auto r = run_in(dir.path, command);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out == shown);
  const auto table = hertzdash::CsvTable::read(dir.path / "laws-heights.csv");
  CHECK(table.columns() ==
        std::vector<std::string>{"run", "damping", "height_m", "e_effective", "peak_force_N", "contact_time_s",
                                   "warnings", "error"});
  REQUIRE(table.rows() == 120);
  for (std::size_t i = 0; i < table.rows(); ++i) {
    CHECK(table.text(i, "error").empty());
    // Every law dissipates: 0 < e_effective < 1; free fall from h gives the speed, so the peak
    // force grows with h within each law (Hertz: F ~ v0^{6/5}).
    CHECK(table.number(i, "e_effective") > 0);
    CHECK(table.number(i, "e_effective") < 1);
    if (i % 40 != 0) CHECK(table.number(i, "peak_force_N") > table.number(i - 1, "peak_force_N"));
  }
  CHECK(table.number(0, "height_m") == 0.002);
  CHECK(table.number(39, "height_m") == Approx(0.1).epsilon(1e-15));
  // The header carries the case file's text.
  CHECK_THAT(slurp(dir.path / "laws-heights.csv"), Catch::Contains("# | damping = [\"hongo\", \"hunt-crossley\", \"flores\"]\n"));
}

TEST_CASE("CLI sweep: where the files go, and the summary", "[cli][sweep]") {
  const ScratchDir dir;
  fs::create_directories(dir.path / "cases");
  dir.write("cases/speeds.toml",
            "[grid]\nimpact-velocity = [0.5, 1.0]\n[output]\nfile = \"out/speeds-rows.csv\"\nsummary = true\n");
  // [output] file is relative to the case file's folder; summary = true adds NAME.summary.csv.
  // Its folder is not created unless --mkdir (docs/output-files.md).
  auto r = run_in(dir.path, "sweep cases/speeds.toml --quiet");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("invalid [output] file = cases/out/speeds-rows.csv: must be a file in an existing "
                                    "directory (cases/out does not exist; --mkdir creates it)"));
  CHECK_FALSE(fs::exists(dir.path / "cases/out"));
  r = run_in(dir.path, "sweep cases/speeds.toml --quiet --mkdir");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(data_rows(slurp(dir.path / "cases/out/speeds-rows.csv")) == 2);
  CHECK(data_rows(slurp(dir.path / "cases/out/speeds-rows.summary.csv")) == 3);  // one row per output
  CHECK_THAT(r.out, Catch::Contains("e_effective"));
  // --out and --summary override, relative to the working directory.
  r = run_in(dir.path, "sweep cases/speeds.toml --out a.csv --summary b.csv --quiet");
  REQUIRE(r.exit_code == 0);
  CHECK(fs::exists(dir.path / "a.csv"));
  CHECK(fs::exists(dir.path / "b.csv"));
}

TEST_CASE("CLI sweep: a bad case exits 2 with no file, every run failing exits 1", "[cli][sweep]") {
  const ScratchDir dir;
  dir.write("bad.toml", "[grid]\nheight = [0x10]\n");
  auto r = run_in(dir.path, "sweep bad.toml");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("invalid grid.height (bad.toml line 2) = 0x10: must be a decimal number"));
  CHECK(!fs::exists(dir.path / "bad.csv"));
  r = run_in(dir.path, "sweep missing.toml");
  CHECK(r.exit_code == 2);
  // Every run invalid: the rows say why, the exit code says it failed.
  dir.write("all.toml", "[grid]\nrestitution = [1.5, 2]\n");
  r = run_in(dir.path, "sweep all.toml --quiet");
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("2 of 2 runs failed"));
  CHECK_THAT(slurp(dir.path / "all.csv"), Catch::Contains("must be in (0, 1]"));
}

TEST_CASE("CLI sweep: Ctrl-C stops the runs and writes no file", "[cli][sweep]") {
  // Two million runs take tens of seconds; SIGINT after one second must end the program with
  // exit 130 and leave neither the CSV nor a temporary file.
  const ScratchDir dir;
  dir.write("long.toml", "[sample]\ncount = 2000000\nball-E = { distribution = \"uniform\", min = 1.2e9, max = 2.9e9 }\n");
  const auto r = run_cli_program("cd " + dir.path.string() + " && (" HERTZDASH_BIN
                                 " sweep long.toml --quiet & pid=$!; sleep 1; kill -INT $pid; wait $pid)",
                                 "");
  CHECK(r.exit_code == 130);
  CHECK_THAT(r.err, Catch::Contains("sweep interrupted; no file written"));
  std::size_t files = 0;
  for (const auto& e : fs::directory_iterator(dir.path)) files += e.path().filename() != "long.toml";
  CHECK(files == 0);
}

TEST_CASE("docs/sweep.md names every column a sweep can record", "[sweep][readme]") {
  const std::string page = slurp(fs::path(HERTZDASH_SOURCE_DIR) / "docs" / "sweep.md");
  for (const hertzdash::SweepOutput& o : hertzdash::sweep_output_table) {
    std::string quoted = "`";  // (built up: "`" + name + "`" trips GCC 12's -Wrestrict false positive)
    quoted.append(o.name).append("`");
    INFO(quoted);
    CHECK_THAT(page, Catch::Contains(quoted));
  }
}
