// The input distributions of data/assumptions.csv (simulation/uncertainty/uncertain_inputs.hpp): they agree
// with the paper's own tables where those fix them, and a malformed row is refused naming the
// file and the parameter.
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>

using namespace hertzdash;
namespace fs = std::filesystem;

namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The data tables copied to a scratch directory, with `from` replaced by `to` in
// assumptions.csv; returns the message load_paper_parameters() throws ("loaded" if none).
std::string load_with(const std::string& from, const std::string& to) {
  const fs::path dir = fs::temp_directory_path() / ("hertzdash_assumptions_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  for (const auto& f : fs::directory_iterator(default_data_dir()))
    if (f.is_regular_file()) fs::copy_file(f.path(), dir / f.path().filename());
  std::string text = read_text(dir / "assumptions.csv");
  const auto at = text.find(from);
  REQUIRE(at != std::string::npos);
  text.replace(at, from.size(), to);
  std::ofstream(dir / "assumptions.csv") << text;
  std::string message = "loaded";
  try {
    load_paper_parameters(dir);
  } catch (const DataError& e) {
    message = e.what();
  }
  fs::remove_all(dir);
  return message;
}

}  // namespace

TEST_CASE("Input distributions: the nylon modulus spans Table 3's catalogue range", "[paper][uncertainty]") {
  const PaperParameters p = load_paper_parameters();
  const InputDistribution& E = p.uncertain_input("nylon_E_Pa").distribution;
  CHECK(E.kind == DistributionKind::uniform);
  CHECK(E.quantile(0.0) == p.ball.E_min_Pa);
  CHECK(E.quantile(1.0) == p.ball.E_max_Pa);
  // The assumed values every other study uses lie inside their distributions.
  for (const UncertainInput& in : p.uncertain_inputs) {
    INFO(in.parameter);
    CHECK(in.distribution.quantile(0.0) <= in.value);
    CHECK(in.value <= in.distribution.quantile(1.0));
    CHECK(!in.reason.empty());
  }
  // Not every row is varied: g and the elastic rig's parameters are stated as fixed.
  CHECK_THROWS_AS(p.uncertain_input("gravity_mps2"), DataError);
  CHECK_THROWS_AS(p.uncertain_input("load_cell_stiffness_N_per_m"), DataError);
}

TEST_CASE("Input distributions: the scatter of e is Table 2's repeat of rod A", "[paper][uncertainty]") {
  // Two measurements x1, x2 of one quantity estimate its sd as |x1 - x2| / sqrt(2) (the sample
  // sd of a pair); rod A's 0.828 and 0.834 give 0.00424, printed as 0.0042 (to 5e-5).
  const PaperParameters p = load_paper_parameters();
  const RodData& a = p.rod("duralumin-a");
  const InputDistribution& dev = p.uncertain_input("restitution_deviation").distribution;
  const double sd = std::abs(a.restitution_second - a.restitution) / std::sqrt(2.0);
  CHECK(dev.kind == DistributionKind::normal);
  CHECK(dev.p1 == 0.0);
  CHECK(dev.p2 == Approx(sd).margin(5e-5));
  // Truncated at 3 sd (to the printed digits), symmetric: every rod's e stays in (0, 1).
  CHECK(dev.upper == Approx(3 * dev.p2).margin(5e-5));
  CHECK(dev.lower == -dev.upper);
  for (const RodData& r : p.rods) CHECK(r.restitution + dev.upper < 1.0);
}

TEST_CASE("Input distributions: a malformed row names the file and the parameter", "[paper][uncertainty]") {
  const std::string row = "nylon_nu,0.40,-,assumption: typical nylon 0.39-0.41; the paper gives no Poisson ratio,";
  auto refused = [](const std::string& message, const std::string& why) {
    INFO(message);
    CHECK(message.find("assumptions.csv:") != std::string::npos);
    CHECK(message.find("nylon_nu") != std::string::npos);
    CHECK(message.find(why) != std::string::npos);
  };
  refused(load_with(row + "uniform,,,0.39,0.41,", row + "gaussian,,,0.39,0.41,"), "none of: fixed, uniform");
  refused(load_with(row + "uniform,,,0.39,0.41,", row + "uniform,,,0.39,,"), "needs column 'upper'");
  refused(load_with(row + "uniform,,,0.39,0.41,", row + "uniform,,,0.41,0.39,"), "greater than min");
  refused(load_with(row + "uniform,,,0.39,0.41,", row + "uniform,0.4,,0.39,0.41,"), "takes no 'location'");
  refused(load_with(row + "uniform,,,0.39,0.41,", row + "normal,0.40,abc,,,"), "'abc' is not a decimal number");
  refused(load_with(row + "uniform,,,0.39,0.41,", row + "normal,0.40,-0.01,,,"), "nylon_nu.sd");
  refused(load_with(row + "uniform,,,0.39,0.41,", row + "lognormal,0,0.1,,,"), "median (location) > 0");
  refused(load_with(row + "uniform,,,0.39,0.41,", row + "uniform,,,0.20,0.30,"), "outside its distribution");
  refused(load_with(row + "uniform,,,0.39,0.41,", row + "fixed,,,0.39,0.41,"), "fixed parameter takes no 'lower'");
  refused(load_with(row + "uniform,,,0.39,0.41,the typical range of nylon with no value favoured",
                    row + "uniform,,,0.39,0.41,"),
          "'distribution_reason' is empty");
  // The unmodified copy loads: the failures above come from the edits alone.
  CHECK(load_with(row, row) == "loaded");
}
