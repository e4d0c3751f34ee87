// Every kind of CSV the program writes reads with the two conventional calls of Python,
// pandas.read_csv(f, comment='#') and numpy.genfromtxt(f, delimiter=',', names=True, comments='#'),
// with the right column names and every row (issue 32): the column names come first, the
// provenance follows as '#' lines (io/csv_writer.hpp). The study CSVs are checked the same way in
// tests/test_figures_pipeline.cpp. And a trace written by `simulate --trace` is a trace `fit` reads.
#include "cli_runner.hpp"
#include "python_csv_readers.hpp"
#include "scratch_dir.hpp"
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/measured_trace.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using hertzdash::CsvTable;
using hertzdash::test::run_cli;
using hertzdash::test::ScratchDir;

TEST_CASE("Every CSV kind of the program reads with pandas and numpy, column names first", "[csv][python]") {
  const ScratchDir dir;
  const std::string d = dir.path.string() + "/";
  // The kinds: a model trace, a virtual measurement, a bounce sequence, a sweep's rows and its
  // summary, a fit's curves.
  REQUIRE(run_cli("simulate --trace " + d + "model.csv").exit_code == 0);
  REQUIRE(run_cli("simulate --trace " + d + "measured.csv --trace-format measured --noise 0.01").exit_code == 0);
  REQUIRE(run_cli("bounce --bounces 3 --trace " + d + "bounce.csv").exit_code == 0);
  dir.write("speeds.toml", "[grid]\nimpact-velocity = [0.5, 1.0]\ndamping = [\"hongo\", \"flores\"]\n");
  REQUIRE(run_cli("sweep " + d + "speeds.toml --out " + d + "sweep.csv --summary " + d + "summary.csv --quiet")
              .exit_code == 0);
  REQUIRE(run_cli("fit --trace " + d + "measured.csv --fit restitution --curves " + d + "curves.csv").exit_code == 0);
  std::vector<fs::path> files;
  for (const char* f : {"model.csv", "measured.csv", "bounce.csv", "sweep.csv", "summary.csv", "curves.csv"}) {
    const fs::path p = dir.path / f;
    const CsvTable t = CsvTable::read(p);
    INFO(f);
    CHECK(hertzdash::test::slurp(p).rfind(t.columns().front() + ",", 0) == 0);  // the first line names the columns
    CHECK_FALSE(t.comments().empty());                                            // the provenance below them
    files.push_back(p);
  }
  const auto r = hertzdash::test::read_with_python_readers(files, dir.path);
  INFO(r.report);
  CHECK(r.passed);
}

TEST_CASE("fit reads the trace simulate --trace writes, and recovers the input e it was made with", "[csv][fit]") {
  // The model trace is noise-free and sampled at the integrator's steps: fitting e to it must
  // return the e that made it. Not to rounding: the fit compares each sample with the model's
  // history interpolated between the model's own steps (simulation/run/impact_history.hpp), and
  // the steps of CVODE at its default tolerance are up to about a hundredth of the contact, whose
  // interpolation error moves e by about 5e-5 (measured: 0.70005). A misread trace (time from
  // the release, a column of another quantity) cannot fit at all. The fit says the trace is
  // synthetic and names the model's own columns it did not fit.
  const ScratchDir dir;
  const std::string trace = (dir.path / "model.csv").string();
  REQUIRE(run_cli("simulate --rod duralumin-b --height 0.03 --restitution 0.7 --trace " + trace).exit_code == 0);
  const auto r = run_cli("fit --trace " + trace + " --fit restitution --json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["trace"]["synthetic"] == true);
  CHECK(j["trace"]["model_columns"] == nlohmann::json::array({"x_m", "xdot_mps", "contact_force_N", "rod_accel_mps2"}));
  CHECK(j["fits"][0]["parameters"][0]["estimate"].get<double>() == Approx(0.7).margin(2e-4));
  // A run given its impact velocity has no drop height: its trace says the height a free fall
  // from rest reaches that speed from, v0^2 / (2 g), as a virtual measurement does, so fit reads it.
  REQUIRE(run_cli("simulate --impact-velocity 0.8 --trace " + trace).exit_code == 0);
  CHECK(hertzdash::read_measured_trace(trace).height_m == Approx(0.8 * 0.8 / (2 * 9.80665)).epsilon(1e-15));
  CHECK_THAT(r.err, Catch::Contains("model columns (x_m, xdot_mps, contact_force_N, rod_accel_mps2) are not fitted"));
}
