// The restitution-table reader (io/restitution_table.hpp; data/measurements/README.md,
// "Restitution tables"), on SYNTHETIC files written by the test itself: every refusal names the
// file (and FILE:LINE:COL of a bad field) and the defect.
#include "scratch_dir.hpp"
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/restitution_table.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace hertzdash;
using hertzdash::test::ScratchDir;

namespace {

const std::string header = "# source: SYNTHETIC test data written by tests/test_restitution_table.cpp\n"
                           "# synthetic: true\n";

}  // namespace

TEST_CASE("a restitution table is read with its provenance, repeated speeds and optional columns",
          "[restitution_table]") {
  ScratchDir dir;
  const auto file = dir.write("table.csv", "impact_speed_m_per_s,e,e_sd,contact_time_s\n" + header +
                                               "0.5,0.81,0.01,1.3e-3\n"
                                               "0.5,0.80,0.02,\n"
                                               "1.0,1,0.01,1.2e-3\n");
  const RestitutionTable t = read_restitution_table(file);
  CHECK(t.synthetic);
  CHECK(t.source.find("SYNTHETIC") != std::string::npos);
  REQUIRE(t.rows() == 3);
  CHECK(t.impact_speed_mps == std::vector<double>{0.5, 0.5, 1.0});  // a speed repeated: repeated trials
  CHECK(t.e == std::vector<double>{0.81, 0.80, 1.0});                 // e = 1 is in (0, 1]
  CHECK(t.e_sd == std::vector<double>{0.01, 0.02, 0.01});
  REQUIRE(t.contact_time_s.size() == 3);
  CHECK(std::isnan(t.contact_time_s[1]));  // an empty contact time: not measured

  const auto minimal = dir.write("minimal.csv", "# source: a paper\nimpact_speed_m_per_s,e\n0.2,0.9\n0.4,0.85\n");
  const RestitutionTable m = read_restitution_table(minimal);
  CHECK_FALSE(m.synthetic);  // default false
  CHECK_FALSE(m.has_sd());
  CHECK(m.contact_time_s.empty());

  // Written back, it reads the same.
  const auto again = dir.path / "again.csv";
  write_restitution_table(again, t, "test", {});
  const RestitutionTable u = read_restitution_table(again);
  CHECK(u.e == t.e);
  CHECK(u.e_sd == t.e_sd);
  CHECK(u.synthetic);
}

TEST_CASE("malformed restitution tables are refused naming the file, the line and the defect",
          "[restitution_table]") {
  ScratchDir dir;
  auto rejects = [&](const std::string& text, const std::string& expected) {
    const auto file = dir.write("bad.csv", text);
    CHECK_THROWS_WITH(read_restitution_table(file), Catch::Contains(file.string()) && Catch::Contains(expected));
  };
  const std::string cols = "impact_speed_m_per_s,e\n";
  rejects(cols + "0.2,0.9\n0.4,0.8\n", "missing header line '# source: ...'");
  rejects("# source:\n" + cols + "0.2,0.9\n0.4,0.8\n", "missing header line '# source: ...'");
  rejects("# source: x\n# synthetic: yes\n" + cols + "0.2,0.9\n0.4,0.8\n", "'synthetic: yes' must be true or false");
  rejects("# source: x\n# source: y\n" + cols + "0.2,0.9\n0.4,0.8\n", "header key 'source' again");
  rejects(header + "impact_speed_mps,e\n0.2,0.9\n0.4,0.8\n", "unknown column 'impact_speed_mps'");
  rejects(header + "impact_speed_m_per_s,e,height_m\n0.2,0.9,1\n0.4,0.8,1\n", "unknown column 'height_m'");
  rejects(header + "impact_speed_m_per_s,e_sd\n0.2,0.9\n0.4,0.8\n", "missing column 'e'");
  rejects(header + "e\n0.9\n0.8\n", "missing column 'impact_speed_m_per_s'");
  rejects(header + cols + "0.2,0.9\n", "needs at least two rows");
  rejects(header + cols, "needs at least two rows");
  // A bad field: FILE:LINE:COL, the column and the range (line 4: the header is lines 1-3).
  rejects(header + cols + "0.2,0.9\n0.4,1.5\n", "bad.csv:5:5: column 'e': 1.5 is not in (0, 1]");
  rejects(header + cols + "0.2,0\n0.4,0.8\n", "bad.csv:4:5: column 'e': 0 is not in (0, 1]");
  rejects(header + cols + "0.2,-0.1\n0.4,0.8\n", "is not in (0, 1]");
  rejects(header + cols + "0,0.9\n0.4,0.8\n", "bad.csv:4:1: column 'impact_speed_m_per_s': 0 is not a finite number > 0");
  rejects(header + cols + "-0.2,0.9\n0.4,0.8\n", "is not a finite number > 0");
  rejects(header + cols + "0.2,0.9\n1e400,0.8\n", "out of range of double");
  rejects(header + cols + "0.2,nan\n0.4,0.8\n", "column 'e': 'nan' is not a decimal number");
  rejects(header + cols + "0.2,\n0.4,0.8\n", "column 'e'");
  rejects(header + cols + "0x1p-2,0.9\n0.4,0.8\n", "is not a decimal number");
  rejects(header + "impact_speed_m_per_s,e,e_sd\n0.2,0.9,0\n0.4,0.8,0.01\n", "column 'e_sd': 0 is not a finite number > 0");
  rejects(header + "impact_speed_m_per_s,e,e_sd\n0.2,0.9,\n0.4,0.8,0.01\n", "column 'e_sd'");  // e_sd in every row
  rejects(header + "impact_speed_m_per_s,e,contact_time_s\n0.2,0.9,-1\n0.4,0.8,\n",
          "column 'contact_time_s': -1 is not a finite number > 0");
  rejects(header + cols + "0.2,0.9,1\n0.4,0.8\n", "bad.csv:4");  // a row with too many fields
}
