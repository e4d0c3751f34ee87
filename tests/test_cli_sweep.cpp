// `hertzdash sweep` as a user runs it: the README's example as written, the files it writes and
// where, bad case files, every run failing, Ctrl-C, a second writer, an oversized grid and a
// case file read from a FIFO.
#include "scratch_dir.hpp"
#include "cli_runner.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/output_lock.hpp"
#include "hertzdash/simulation/sweep/sweep_outputs.hpp"

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
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

/// `hertzdash sweep CASE --quiet` run in `dir`: its exit code (-1: killed), stderr and peak
/// memory. (Linux counts the forked test process's own ~10 MB before the exec in it: a floor
/// under every size compared.)
struct SweepPeak {
  int exit_code = -1;
  std::string err;
  long kB = 0;
};
SweepPeak sweep_peak(const fs::path& dir, const char* case_file) {
  const pid_t child = ::fork();
  REQUIRE(child >= 0);
  if (child == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(127);
    std::freopen("/dev/null", "w", stdout);
    std::freopen("err.txt", "w", stderr);
    ::execl(HERTZDASH_BIN, HERTZDASH_BIN, "sweep", case_file, "--quiet", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  struct rusage usage {};
  ::wait4(child, &status, 0, &usage);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir / "err.txt"), usage.ru_maxrss};
}

}  // namespace

TEST_CASE("The README's sweep example runs as written and prints what the README shows", "[cli][sweep][readme]") {
  // The README's ```toml block is saved under the name the text gives it, the command under it
  // is run in that folder, and its output must be the README's, line for line: the summary on
  // stdout, then the warnings on stderr (the progress line, redrawn in place on a terminal, aside).
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
  std::string warnings;
  std::istringstream err(r.err);
  for (std::string l; std::getline(err, l);)
    if (l.rfind("hertzdash: ", 0) == 0) warnings += l + "\n";
  CHECK(r.out + warnings == shown);
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
  // (Each speed is valid alone; with the steel rod on the nylon ball, above 81.3 m/s the Hertz
  // deformation passes the ball's radius.)
  dir.write("all.toml", "[grid]\nimpact-velocity = [100, 200]\n");
  r = run_in(dir.path, "sweep all.toml --quiet");
  CHECK(r.exit_code == 1);
  CHECK_THAT(r.err, Catch::Contains("2 of 2 runs failed"));
  CHECK_THAT(slurp(dir.path / "all.csv"), Catch::Contains("must be below 81.3"));
  // A value its declaration refuses stops the sweep before any run (issue 32).
  dir.write("stel.toml", "[base]\nrod = \"stel\"\n[grid]\nheight = [0.01, 0.02]\n");
  r = run_in(dir.path, "sweep stel.toml");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::Contains("invalid base.rod (stel.toml line 2) = stel: must be one of: steel"));
  CHECK(!fs::exists(dir.path / "stel.csv"));
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

TEST_CASE("CLI sweep: a second sweep to the outputs another one is writing is refused at once", "[cli][sweep]") {
  // Before, two sweeps to the same --out left the CSV of one beside the summary of the other.
  // Here the first writer is this test, holding the lock a sweep takes (io/output_lock.hpp).
  const ScratchDir dir;
  dir.write("ok.toml", "[grid]\nheight = [0.01, 0.02]\n[output]\nsummary = true\n");
  {
    const hertzdash::OutputLock first(dir.path / "ok.summary.csv");
    const auto r = run_in(dir.path, "sweep ok.toml --quiet");
    CHECK(r.exit_code == 2);
    CHECK(r.err == "hertzdash: refused: " + (dir.path / "ok.summary.csv").string() +
                       " is being written by another process (PID " + std::to_string(::getpid()) + " holds " +
                       (dir.path / "ok.summary.csv.lock").string() +
                       "); wait for it to end, or give another --out/--summary\n");
    CHECK(r.out.empty());
  }
  const auto r = run_in(dir.path, "sweep ok.toml --quiet");
  CHECK(r.exit_code == 0);
  // Both written, and no lock file left.
  CHECK(dir.names() == std::vector<std::string>{"ok.csv", "ok.summary.csv", "ok.toml"});
}

TEST_CASE("CLI sweep: an oversized grid is refused from the case's numbers, before any axis is built",
          "[cli][sweep]") {
  // Before, every axis was built first: eight axes of 1e7 values took 15.7 s and 3.4 GB before
  // the refusal, or ended in std::bad_alloc under ulimit -v. Here one axis of 1e7 values (about
  // 400 MB built) and one of 2: the program's peak memory must stay that of a small case, one
  // refused at the same point with an axis of 2 values (its baseline: the program, its libraries
  // and, under `make sanitize`, their shadow memory), to well under the 400 MB: 100 MB.
  const ScratchDir dir;
  dir.write("huge.toml", "[grid]\nheight = { from = 0.01, to = 0.02, count = 10000000 }\nrestitution = [0.5, 0.6]\n");
  dir.write("small.toml", "[grid]\nheight = { from = 0.01, to = 0.02, count = 2 }\nrestitution = [0.5, 0.6]\n"
                          "[sample]\nmethod = \"sobol\"\ncount = 5000001\nball-E = { distribution = \"uniform\", "
                          "min = 1.2e9, max = 2.9e9 }\n");
  const SweepPeak huge = sweep_peak(dir.path, "huge.toml"), small = sweep_peak(dir.path, "small.toml");
  CHECK(huge.exit_code == 2);
  CHECK(small.exit_code == 2);
  CHECK(huge.err ==
        "hertzdash: invalid the number of runs of huge.toml = 2e+07: must be at most 10000000 (grid points times "
        "sample count; split the case)\n");
  CHECK_THAT(small.err, Catch::Contains("must be at most 10000000"));  // refused at the same point
  CHECK(huge.kB < small.kB + 100 * 1024);  // the axis alone would be 400 MB
}

TEST_CASE("CLI sweep: a case file given as a FIFO is read", "[cli][sweep]") {
  // Before: "cannot read the case file: Operation not supported" (its size was asked first).
  const ScratchDir dir;
  REQUIRE(::mkfifo((dir.path / "case.toml").c_str(), 0600) == 0);
  dir.write("source.toml", "[grid]\nheight = [0.01, 0.02]\n");
  const auto r = run_cli_program("cd " + dir.path.string() + " && (" HERTZDASH_BIN
                                 " sweep case.toml --quiet --out out.csv & cat source.toml > case.toml; wait $!)",
                                 "");
  CHECK(r.exit_code == 0);
  CHECK(data_rows(slurp(dir.path / "out.csv")) == 2);
}

TEST_CASE("CLI sweep: the per-run table goes to its file as it is made, not held as text", "[cli][sweep]") {
#if defined(__SANITIZE_ADDRESS__)
  SUCCEED("not under AddressSanitizer: its redzones and quarantine change every allocation's size");
#else
  // Issue 31: a sweep of 1e7 runs took 4.1 GB, its table held whole as text beside the results
  // (about 450 bytes per run with the three default columns and the summary). The rows now go
  // to the file in pieces: what stays per run is the results in their few copies (values,
  // gathered and ordered; errors; warning codes; the summary's sorted columns), about 250
  // bytes. 200,000 fast runs (undamped, Taylor series) against 2: at most 300 bytes per run.
  const ScratchDir dir;
  const char* base = "[base]\ndamping = \"none\"\nintegrator = \"taylor-regularized\"\n[output]\nsummary = true\n";
  dir.write("small.toml", std::string(base) + "[grid]\nheight = { from = 0.01, to = 0.05, count = 2 }\n");
  dir.write("large.toml", std::string(base) + "[grid]\nheight = { from = 0.01, to = 0.05, count = 200000 }\n");
  const SweepPeak small_run = sweep_peak(dir.path, "small.toml"), large_run = sweep_peak(dir.path, "large.toml");
  REQUIRE(small_run.exit_code == 0);
  REQUIRE(large_run.exit_code == 0);
  const long small = small_run.kB, large = large_run.kB;
  const double bytes_per_run = static_cast<double>(large - small) * 1024.0 / 200000;
  INFO("peak " << small << " kB for 2 runs, " << large << " kB for 200000: " << bytes_per_run << " bytes per run");
  CHECK(bytes_per_run < 300);
  std::ifstream table(dir.path / "large.csv");  // 20 MB: beyond CsvTable's 16 MiB for data tables
  std::size_t lines = 0;
  for (std::string line; std::getline(table, line);) lines += line.empty() || line[0] != '#';
  CHECK(lines == 1 + 200000);  // the column names and every run's row
#endif
}
