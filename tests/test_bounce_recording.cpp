// The bounce-recording reader (io/bounce_recording.hpp; data/measurements/README.md, "Bounce
// recordings"), on SYNTHETIC files written by the test itself: drops grouped by label in the
// order of their first row, any clock origin, dirty times kept as given (the check finds them,
// tests/test_bounce_recording_check.cpp); every refusal names the file (and FILE:LINE:COL of a
// bad field) and the defect.
#include "scratch_dir.hpp"
#include "hertzdash/io/bounce_recording.hpp"
#include "hertzdash/io/csv_table.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

using namespace hertzdash;
using hertzdash::test::ScratchDir;

namespace {

const std::string header = "# source: SYNTHETIC test data written by tests/test_bounce_recording.cpp\n"
                           "# synthetic: true\n";

}  // namespace

TEST_CASE("a bounce recording is read drop by drop with its provenance and heights", "[bounce_recording]") {
  ScratchDir dir;
  // Two drops interleaved, a negative clock origin, a time going backwards (kept: the check's).
  const auto file = dir.write("rec.csv", "drop,impact_time_s,drop_height_m\n" + header +
                                             "a,-1.5,0.5\n"
                                             "b,10,\n"
                                             "a,-1.0,\n"
                                             "a,-1.2,0.5\n"
                                             "b,10.4,0.25\n"
                                             "b,10.7,\n");
  const BounceRecording r = read_bounce_recording(file);
  CHECK(r.synthetic);
  CHECK(r.source.find("SYNTHETIC") != std::string::npos);
  REQUIRE(r.drops.size() == 2);
  CHECK(r.impacts() == 6);
  CHECK(r.drops[0].label == "a");
  CHECK(r.drops[0].impact_time_s == std::vector<double>{-1.5, -1.0, -1.2});  // as given
  CHECK(r.drops[0].drop_height_m == 0.5);
  CHECK(r.drops[1].label == "b");
  CHECK(r.drops[1].impact_time_s == std::vector<double>{10, 10.4, 10.7});
  CHECK(r.drops[1].drop_height_m == 0.25);  // given on a later row
  CHECK(r.drops[0].where[1] == file.string() + ":6");

  const auto minimal = dir.write("minimal.csv", "# source: a stopwatch\ndrop,impact_time_s\n1,0.1\n1,0.5\n1,0.8\n");
  const BounceRecording m = read_bounce_recording(minimal);
  CHECK_FALSE(m.synthetic);
  REQUIRE(m.drops.size() == 1);
  CHECK(m.drops[0].drop_height_m == 0);  // not given

  // Written back, it reads the same.
  const auto again = dir.path / "again.csv";
  write_bounce_recording(again, r, "test", {});
  const BounceRecording u = read_bounce_recording(again);
  REQUIRE(u.drops.size() == 2);
  CHECK(u.drops[0].impact_time_s == r.drops[0].impact_time_s);
  CHECK(u.drops[1].drop_height_m == 0.25);
  CHECK(u.synthetic);
}

TEST_CASE("malformed bounce recordings are refused naming the file, the line and the defect", "[bounce_recording]") {
  ScratchDir dir;
  auto rejects = [&](const std::string& text, const std::string& expected) {
    const auto file = dir.write("bad.csv", text);
    CHECK_THROWS_WITH(read_bounce_recording(file), Catch::Contains(file.string()) && Catch::Contains(expected));
  };
  const std::string cols = "drop,impact_time_s\n";
  rejects(cols + "1,0.1\n1,0.5\n", "missing header line '# source: ...'");
  rejects("# source: x\n# synthetic: maybe\n" + cols + "1,0.1\n", "'synthetic: maybe' must be true or false");
  rejects(header + "drop,impact_time_ms,impact_time_s\n1,100,0.1\n", "both impact_time_s and impact_time_ms");
  rejects(header + "drop,impact_time_s,height_m\n1,0.1,0.5\n", "unknown column 'height_m'");
  rejects(header + "drop\n1\n", "missing column 'impact_time_s'");
  rejects(header + cols, "no impacts");
  // A bad field: FILE:LINE:COL and the column (the header is lines 1-3).
  rejects(header + cols + "1,0.1\n,0.5\n", "bad.csv:5:1: column 'drop': empty drop label");
  rejects(header + cols + "1,0.1\n\"a,b\",0.5\n", "bad.csv:5:1: column 'drop': a drop label is text without commas");
  rejects(header + cols + "1,0.1\n\"a\"\"b\",0.5\n", "a drop label is text without commas, double quotes");
  rejects(header + cols + "1,0.1\n\"#2\",0.5\n", "a drop label is text without commas, double quotes, '#'");
  rejects(header + cols + "1,0.1\na\x01,0.5\n", "or control characters");
  rejects(header + cols + "1,0.1\n 1,nan\n", "bad.csv:5:4: column 'impact_time_s': 'nan' is not a decimal number");
  rejects(header + cols + "1,0.1\n1,1e400\n", "out of range of double");
  rejects(header + cols + "1,0.1\n1,\n", "column 'impact_time_s'");
  rejects(header + "drop,impact_time_s,drop_height_m\n1,0.1,0\n", "bad.csv:4:7: column 'drop_height_m': 0 is not a finite number > 0");
  rejects(header + "drop,impact_time_s,drop_height_m\n1,0.1,-1\n", "is not a finite number > 0");
  rejects(header + "drop,impact_time_s,drop_height_m\n1,0.1,0.5\n2,0.1,0.3\n1,0.4,0.3\n",
          "bad.csv:6:7: column 'drop_height_m': drop '1' has drop_height_m 0.3 here and 0.5 at " +
              (dir.path / "bad.csv").string() + ":4");
  rejects(header + cols + "1,0.1\n1,0.2,3\n", "bad.csv:5");  // a row with too many fields
}

// Issue 46: a single drop needs no `drop` column (it is drop "1"), and times may be given in ms
// (`impact_time_ms`, as traces take t_ms), read into seconds: 412.5 ms is 0.4125 s.
TEST_CASE("a bounce recording of one drop needs no drop column, and its times may be in ms", "[bounce_recording]") {
  ScratchDir dir;
  const auto path = dir.write("one.csv", header + "impact_time_ms\n0\n412.5\n740.1\n");
  const BounceRecording r = read_bounce_recording(path);
  REQUIRE(r.drops.size() == 1);
  CHECK(r.drops[0].label == "1");
  REQUIRE(r.drops[0].impact_time_s.size() == 3);
  CHECK(r.drops[0].impact_time_s[0] == 0.0);
  CHECK(r.drops[0].impact_time_s[1] == 0.4125);  // 412.5 / 1000, both exact in binary up to the quotient's rounding
  CHECK(r.drops[0].impact_time_s[2] == Approx(0.7401).epsilon(1e-15));
}
