// The measured-trace reader (data/measurements/README.md), exercised on SYNTHETIC
// files written by the test itself: no measured data exists for the paper.
#include "scratch_dir.hpp"
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/measured_trace.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

using namespace hertzdash;
namespace fs = std::filesystem;

using hertzdash::test::ScratchDir;

namespace {

// A fresh directory per test case, removed afterwards.

const std::string synthetic_header =
    "# source: SYNTHETIC test data written by tests/test_measured_trace.cpp, not a measurement\n"
    "# synthetic: true\n"
    "# rod: steel\n"
    "# height_m: 0.020\n";

}  // namespace

TEST_CASE("a well-formed synthetic trace is read with its provenance and gaps", "[measured_trace]") {
  ScratchDir dir;
  const auto file = dir.write("steel_h20mm_synthetic.csv", synthetic_header +
                                                              "t_s,force_N,accel_mps2\n"
                                                              "0.0,0.0,9.8\n"
                                                              "1e-4,120.5,\n"
                                                              "2e-4,300.0,-375.0\n");
  const MeasuredTrace m = read_measured_trace(file);
  CHECK(m.synthetic);
  CHECK(m.rod == "steel");
  CHECK(m.height_m == 0.020);
  CHECK(m.source.find("SYNTHETIC") != std::string::npos);
  REQUIRE(m.t_s.size() == 3);
  CHECK(m.force_N == std::vector<double>{0.0, 120.5, 300.0});
  REQUIRE(m.accel_mps2.size() == 3);
  CHECK(std::isnan(m.accel_mps2[1]));  // an empty field is a sample not measured
  CHECK(m.velocity_mps.empty());        // a column absent is a quantity not measured
  CHECK(m.displacement_m.empty());
}

TEST_CASE("columns in other units are read into SI", "[measured_trace]") {
  // 250 us = 2.5e-4 s; 1.5 kN = 1500 N; -2 g = -2 x 9.80665 m/s^2 (standard gravity); 3 mm = 3e-3 m.
  ScratchDir dir;
  const auto file = dir.write("units.csv", synthetic_header + "t_us,force_kN,accel_g,displacement_mm\n"
                                                               "0,0,1,0\n"
                                                               "250,1.5,-2,3\n");
  const MeasuredTrace m = read_measured_trace(file);
  CHECK(m.t_s == std::vector<double>{0.0, 250 * 1e-6});
  CHECK(m.force_N == std::vector<double>{0.0, 1.5 * 1e3});
  CHECK(m.accel_mps2 == std::vector<double>{9.80665, -2 * 9.80665});
  CHECK(m.displacement_m == std::vector<double>{0.0, 3 * 1e-3});
}

TEST_CASE("malformed traces are rejected with a message naming the file and the defect", "[measured_trace]") {
  ScratchDir dir;
  auto rejects = [&](const std::string& text, const std::string& expected) {
    const auto file = dir.write("bad.csv", text);
    CHECK_THROWS_WITH(read_measured_trace(file),
                      Catch::Contains(file.string()) && Catch::Contains(expected));
  };
  rejects("# rod: steel\n# height_m: 0.02\nt_s,force_N\n0,0\n1e-4,1\n", "'# source: ...'");
  rejects("# source: x\n# height_m: 0.02\nt_s,force_N\n0,0\n1e-4,1\n", "'# rod: ...'");
  rejects("# source: x\n# rod: steel\n# height_m: -1\nt_s,force_N\n0,0\n1e-4,1\n", "must be a decimal number > 0");
  rejects("# source: x\n# rod: steel\n# height_m: 0x1p-5\nt_s,force_N\n0,0\n1e-4,1\n", "must be a decimal number > 0");
  rejects("# source: x\n# rod: steel\n# height_m: inf\nt_s,force_N\n0,0\n1e-4,1\n", "must be a decimal number > 0");
  rejects(synthetic_header + "time,force_N\n0,0\n1e-4,1\n", "unknown column 'time'");
  rejects(synthetic_header + "force_N,accel_g\n0,0\n1e-4,1\n", "missing the time column (t_s, t_ms or t_us)");
  rejects(synthetic_header + "t_s,force_lbf\n0,0\n1e-4,1\n", "unknown column 'force_lbf'");
  rejects(synthetic_header + "t_s\n0\n1e-4\n", "at least one measured quantity");
  rejects(synthetic_header + "t_s,force_N\n0,0\n", "at least two samples");
  rejects(synthetic_header + "t_s,force_N\n0,0\n0,1\n", "the time must increase strictly (sample 2)");
  rejects(synthetic_header + "t_s,force_N\n0,0\n1e-4,abc\n", "'abc' is not a decimal number");
  // Issue 19: strtod read hexadecimal (0x1p-1 = 0.5) and inf; numbers are decimal only.
  rejects(synthetic_header + "t_s,force_N\n0,0\n1e-4,0x1p-1\n", "'0x1p-1' is not a decimal number");
  rejects(synthetic_header + "t_s,force_N\n0,0\n1e-4,inf\n", "'inf' is not a decimal number");
  rejects(synthetic_header + "t_s,force_N\n0,0\n1e-4,-inf\n", "'-inf' is not a decimal number");
  rejects(synthetic_header + "t_s,force_N\n0,0\n0x1p-5,1\n", "'0x1p-5' is not a decimal number");
  rejects(synthetic_header + "t_s,force_N\n0,0\n1e-4\n", "expected 2 fields");
  // A second header line of a key (the last won silently) and numbers beyond a double.
  rejects(synthetic_header + "# height_m: 0.03\nt_s,force_N\n0,0\n1e-4,1\n",
          ":5:3: header key 'height_m' again (first on line 4); each header key appears once");
  rejects(synthetic_header + "t_s,force_N\n0,0\n1e-4,1e400\n", ":7:6: column 'force_N': '1e400' is out of range of double");
  rejects("# source: x\n# rod: steel\n# height_m: 1e400\nt_s,force_N\n0,0\n1e-4,1\n",
          "header 'height_m: 1e400': '1e400' is out of range of double");
}

TEST_CASE("traces are found by the rod and height in their header", "[measured_trace]") {
  ScratchDir dir;
  const std::string body = "t_s,force_N\n0,0\n1e-4,1\n";
  dir.write("b.csv", synthetic_header + body);
  dir.write("a.csv", synthetic_header + body);
  dir.write("other_rod.csv", "# source: x\n# rod: duralumin-c\n# height_m: 0.020\n" + body);
  dir.write("other_height.csv", "# source: x\n# rod: steel\n# height_m: 0.030\n" + body);
  dir.write("README.md", "not a trace\n");
  const auto found = find_measured_traces(dir.path, "steel", 0.0201);  // within the 0.5 mm tolerance
  REQUIRE(found.size() == 2);
  CHECK(found[0].path.filename() == "a.csv");  // sorted by file name
  CHECK(found[1].path.filename() == "b.csv");
  CHECK(find_measured_traces(dir.path, "steel", 0.0206).empty());
  CHECK(find_measured_traces(dir.path / "missing", "steel", 0.02).empty());
}

TEST_CASE("every trace shipped in data/measurements/ reads cleanly", "[measured_trace]") {
  // None ships today (the paper printed its traces only as plots); any added later must
  // follow the format, or the figure programs would stop on it.
  const fs::path dir = fs::path(HERTZDASH_SOURCE_DIR) / "data" / "measurements";
  REQUIRE(fs::is_directory(dir));
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".csv") CHECK_NOTHROW(read_measured_trace(entry.path()));
}
