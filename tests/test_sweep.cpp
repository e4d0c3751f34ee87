// Sweeps from case files (simulation/sweep/sweep_case.hpp, sweep_run.hpp): the runs a case means, the
// physics of what they return, failures kept per row, the summary's statistics, and tables that
// do not depend on how the runs were shared out.
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/sha256.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/sweep/sweep_run.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace hertzdash;

namespace {

double number(const SweepValue& v) { return std::get<double>(v); }

std::vector<std::size_t> all_runs(const SweepCase& c) {
  std::vector<std::size_t> runs(c.size());
  for (std::size_t i = 0; i < runs.size(); ++i) runs[i] = i;
  return runs;
}

// The table without its timing line.
std::string without_timing(const std::string& table) {
  std::string out;
  std::size_t begin = 0;
  while (begin < table.size()) {
    const std::size_t end = table.find('\n', begin) + 1;
    const std::string line = table.substr(begin, end - begin);
    if (line.rfind("# timing:", 0) != 0) out += line;
    begin = end;
  }
  return out;
}

}  // namespace

TEST_CASE("SHA-256 of the FIPS 180-4 examples", "[sweep]") {
  // FIPS 180-4 appendix examples (and the empty string), which also cross the one-block/two-block
  // padding boundary at 56 bytes.
  CHECK(sha256_hex("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(sha256_hex("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  CHECK(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq") ==
        "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  CHECK(sha256_hex(std::string(1000000, 'a')) == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}

TEST_CASE("A grid is the cartesian product in the file's order, ranges are linear or log", "[sweep]") {
  const SweepCase c = parse_sweep_case(R"(
[base]
rod = "duralumin-b"
[grid]
damping = ["hongo", "flores"]
height = { from = 0.002, to = 0.1, count = 5, spacing = "log" }
ball-E = { from = 1e9, to = 3e9, count = 3 }
)",
                                       "grid.toml");
  REQUIRE(c.size() == 2 * 5 * 3);
  CHECK(c.parameter_columns() == std::vector<std::string>{"damping", "height_m", "ball_E_Pa"});
  // Run i: damping i / 15, height (i / 3) % 5, ball-E i % 3 (the last key varies fastest).
  for (std::size_t i = 0; i < c.size(); ++i) {
    const auto p = c.parameters(i);
    CHECK(std::get<std::string>(p[0]) == (i / 15 == 0 ? "hongo" : "flores"));
    // Log spacing: h_k = 0.002 (0.1 / 0.002)^(k/4); the ends exactly as written.
    const double k = static_cast<double>((i / 3) % 5);
    CHECK(number(p[1]) == Approx(0.002 * std::pow(50.0, k / 4.0)).epsilon(1e-15));
    CHECK(number(p[2]) == Approx(1e9 + static_cast<double>(i % 3) * 1e9).epsilon(1e-15));
    const RunOptions o = c.options(i);
    CHECK(o.rod == "duralumin-b");
    CHECK(o.damping == std::get<std::string>(p[0]));
    CHECK(o.height_m == number(p[1]));
    CHECK(*o.ball_E_Pa == number(p[2]));
  }
  CHECK(number(c.parameters(0)[1]) == 0.002);
  CHECK(number(c.parameters(12)[1]) == 0.1);
}

TEST_CASE("A sample draws its inputs from the design, with a grid, the same draws at every point", "[sweep]") {
  const SweepCase c = parse_sweep_case(R"(
[grid]
rod = ["steel", "duralumin-a"]
[sample]
method = "latin-hypercube"
count = 40
seed = 3
ball-E = { distribution = "uniform", min = 1.2e9, max = 2.9e9 }
restitution = { distribution = "normal", mean = 0.831, sd = 0.003, max = 0.835 }
)",
                                       "sample.toml");
  REQUIRE(c.size() == 80);
  CHECK(c.parameter_columns() == std::vector<std::string>{"rod", "ball_E_Pa", "restitution"});
  // A Latin hypercube of a uniform: one draw in each of the 40 strata of [1.2e9, 2.9e9).
  std::vector<int> strata(40, 0);
  for (std::size_t i = 0; i < 40; ++i) {
    const double E = number(c.parameters(i)[1]);
    ++strata[static_cast<std::size_t>((E - 1.2e9) / (1.7e9 / 40.0))];
    // Truncated normal: never above 0.835.
    CHECK(number(c.parameters(i)[2]) <= 0.835);
    // Run 40 + i is draw i at the second grid point.
    CHECK(c.parameters(40 + i)[1] == c.parameters(i)[1]);
    CHECK(std::get<std::string>(c.parameters(40 + i)[0]) == "duralumin-a");
  }
  for (int n : strata) CHECK(n == 1);
}

TEST_CASE("Bad case files are refused naming the key, its line and what is allowed", "[sweep]") {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"[base]\nheight = 0x10\n", "base.height (bad.toml line 2) = 0x10: must be a decimal number"},
      {"[base]\nmass = 0o7\n", "base.mass (bad.toml line 2) = 0o7: must be a decimal number"},
      {"[base]\nmass = 0b1\n", "base.mass (bad.toml line 2) = 0b1: must be a decimal number"},
      {"[base]\nmass = nan\n", "base.mass (bad.toml line 2) = nan: must be a decimal number"},
      {"[grid]\nmass = [0.5, -nan]\n", "grid.mass (bad.toml line 2) = nan: must be a decimal number"},
      {"[grid]\nheight = { from = 0.01, to = 0x1, count = 3 }\n", "grid.height.to (bad.toml line 2) = 0x1: must be a decimal number"},
      {"[grid]\nheight = { from = 0.01, to = inf, count = 3 }\n", "grid.height.to (bad.toml line 2) = inf: must be a finite number"},
      {"[sample]\ncount = 0x10\nball-E = { distribution = \"uniform\", min = 1, max = 2 }\n", "sample.count (bad.toml line 2) = 0x10: must be a decimal number"},
      {"[sample]\ncount = 3\nball-E = { distribution = \"uniform\", min = nan, max = 2 }\n", "sample.ball-E.min (bad.toml line 3) = nan: must be a decimal number"},
      {"[base]\nheihgt = 1\n", "base.heihgt (bad.toml line 2)"},
      {"[bass]\n", "case.bass"},
      {"[base]\nrod = 3\n", "base.rod (bad.toml line 2) = 3: must be a string"},
      // Values against their declarations, before any run (issue 32: every run failed instead).
      {"[base]\nrod = \"stel\"\n", "base.rod (bad.toml line 2) = stel: must be one of: steel, duralumin-a"},
      {"[grid]\nrestitution = [0.8, 1.5]\n", "grid.restitution (bad.toml line 2) = 1.5: must be in (0, 1]"},
      {"[grid]\nrestitution = { from = 0.5, to = 1.5, count = 3 }\n",
       "grid.restitution (bad.toml line 2) = 1.5: must be in (0, 1] (point 3 of the range)"},
      {"[grid]\nrod-elements = { from = 2, to = 21, count = 3 }\n", "grid.rod-elements (bad.toml line 2) = 11.5"},
      {"[grid]\ndamping = [\"hongo\", \"hunt\"]\n", "grid.damping (bad.toml line 2) = hunt: must be one of: none, hongo"},
      {"[grid]\nheight = []\n", "grid.height (bad.toml line 2)"},
      {"[grid]\nheight = { from = 1, to = 2 }\n", "grid.height.count"},
      {"[grid]\nheight = { from = 0, to = 2, count = 3, spacing = \"log\" }\n", "grid.height.from (bad.toml line 2) = 0: must be > 0"},
      {"[grid]\nheight = { from = 1, to = 2, count = 0 }\n", "grid.height.count"},
      {"[grid]\ndamping = { from = 1, to = 2, count = 2 }\n", "grid.damping (bad.toml line 2)"},
      {"[base]\nheight = 1\n[grid]\nheight = [1, 2]\n", "grid.height (bad.toml line 4) = a second value"},
      {"[sample]\ncount = 3\n", "sample (bad.toml line 1) = no distribution"},
      {"[sample]\nball-E = { distribution = \"uniform\", min = 1, max = 2 }\n", "sample.count"},
      {"[sample]\ncount = 3\nball-E = { distribution = \"normal\", mean = 1 }\n", "sample.ball-E.sd"},
      {"[sample]\ncount = 3\nball-E = { distribution = \"weibull\" }\n", "must be one of: uniform, normal, lognormal"},
      {"[sample]\ncount = 3\nball-E = { distribution = \"uniform\", min = 2, max = 1 }\n", "sample.ball-E"},
      {"[sample]\ncount = 3\ndamping = { distribution = \"uniform\", min = 2, max = 1 }\n", "a numeric option"},
      {"[sample]\ncount = 3\nmethod = \"halton\"\nball-E = { distribution = \"uniform\", min = 1, max = 2 }\n",
       "one of: monte-carlo, latin-hypercube, sobol"},
      {"[output]\ncolumns = [\"e\"]\n", "output.columns (bad.toml line 2) = e: must be one of: e_effective"},
      {"[output]\ncolumns = [\"e_effective\", \"e_effective\"]\n", "listed once"},
      {"[grid]\nheight = { from = 1, to = 2, count = 5000 }\nball-E = { from = 1, to = 2, count = 5000 }\n",
       "the number of runs"},
  };
  for (const auto& [text, expected] : cases) {
    INFO(text);
    try {
      parse_sweep_case(text, "bad.toml");
      FAIL("accepted");
    } catch (const InvalidParameter& e) {
      CHECK_THAT(e.what(), Catch::Contains(expected));
    }
  }
  // Not TOML at all: the parser's message with file, line and column.
  CHECK_THROWS_WITH(parse_sweep_case("x = [", "bad.toml"), Catch::StartsWith("bad.toml:1:"));
  CHECK_THROWS_AS(parse_sweep_case("x = [", "bad.toml"), DataError);
}

TEST_CASE("An undamped sweep returns the closed-form Hertz impact at every speed", "[sweep]") {
  // e = 1 and no gravity: the undamped Hertz impact, X = (5 m v0^2 / (4 K))^{2/5},
  // F = K X^{3/2}, tc = 2.9432 X / v0 (model/hertz.hpp); e_effective = 1. The integrator keeps
  // each step's error below rtol, so a run's relative error is at most steps x rtol (as in
  // test_undamped_hertz_closed_form.cpp); the bound uses each run's own step count.
  const SweepCase c = parse_sweep_case(R"(
[base]
restitution = 1
gravity = 0
integrator = "gbs8-regularized"
rtol = 1e-10
[grid]
rod = ["steel", "duralumin-c"]
impact-velocity = { from = 0.05, to = 2.0, count = 7, spacing = "log" }
[output]
columns = ["e_effective", "peak_force_N", "contact_time_s", "max_deformation_m", "K_N_per_m_1_5", "steps"]
)",
                                       "undamped.toml");
  const PaperParameters paper = load_paper_parameters();
  const SweepResults r = run_sweep(c, all_runs(c), paper, {.threads = 2, .progress = false});
  REQUIRE(r.outputs == 6);
  for (std::size_t i = 0; i < c.size(); ++i) {
    INFO("run " << i);
    REQUIRE(r.errors[i].empty());
    const double* v = &r.values[i * 6];
    const RunOptions o = c.options(i);
    const double m = resolve_setup(o, paper).mass_kg;
    const UndampedHertzImpact u = undamped_hertz_impact(v[4], m, *o.impact_velocity_mps);
    const double bound = v[5] * 1e-10;
    CHECK(v[0] == Approx(1.0).epsilon(bound));
    CHECK(v[1] == Approx(u.peak_force_N).epsilon(bound));
    CHECK(v[2] == Approx(u.contact_time_s).epsilon(bound));
    CHECK(v[3] == Approx(u.max_deformation_m).epsilon(bound));
  }
}

TEST_CASE("A failing run records its error in its row, the others run", "[sweep]") {
  // Each value is valid alone (checked when the case is read); 100 m/s is not with the steel
  // rod on the nylon ball: the undamped Hertz deformation would pass the ball's radius above
  // v* = 81.3 m/s (tests/test_hertz_scale.cpp), so that run alone is refused.
  const SweepCase c = parse_sweep_case("[grid]\nimpact-velocity = [0.6, 100, 0.3]\n", "fail.toml");
  const SweepResults r = run_sweep(c, all_runs(c), load_paper_parameters(), {.threads = 2, .progress = false});
  CHECK(r.errors[0].empty());
  CHECK_THAT(r.errors[1], Catch::StartsWith("invalid impact-velocity = 100: must be below 81.3"));
  CHECK(r.errors[2].empty());
  CHECK(std::isnan(r.values[1 * r.outputs]));
  // Dissipative impacts: 0 < e_effective < 1.
  for (const std::size_t run : {0u, 2u}) {
    CHECK(r.values[run * r.outputs] > 0);
    CHECK(r.values[run * r.outputs] < 1);
  }
  const std::string table = sweep_table(c, r, "timing: test");
  // Three empty outputs, an empty warnings cell (a failed run carries no codes), the error.
  CHECK_THAT(table, Catch::Contains("\n1,100,,,,,invalid impact-velocity = 100: must be below 81.3"));
}

TEST_CASE("The summary's statistics are the sample's (quantiles of type 7)", "[sweep]") {
  // The approach speed is an output equal to the input: values 1..5 m/s in each of two groups.
  // Mean 3, sd sqrt(10/4), type-7 quantile at p: x[floor(h)] + frac(h) (x[floor(h)+1] - x[floor(h)]),
  // h = (n - 1) p: q05 = 1.2, q25 = 2, median 3, q75 = 4, q95 = 4.8.
  const SweepCase c = parse_sweep_case(R"(
[base]
gravity = 0
[grid]
damping = ["hongo", "flores"]
impact-velocity = [5, 1, 3, 2, 4]
[output]
columns = ["impact_velocity_mps"]
)",
                                       "stats.toml");
  const SweepResults r = run_sweep(c, all_runs(c), load_paper_parameters(), {.threads = 1, .progress = false});
  const std::string summary = sweep_summary_table(c, r);
  CHECK_THAT(summary, Catch::Contains("damping,output,runs,failed,mean,sd,min,q05,q25,median,q75,q95,max\n"));
  for (const char* law : {"hongo", "flores"}) {
    INFO(summary);
    // The speeds come back to within the integrator's tolerance, not bit for bit: compare numbers.
    const std::string prefix = std::string(law) + ",impact_velocity_mps,5,0,";
    const std::size_t at = summary.find(prefix);
    REQUIRE(at != std::string::npos);
    std::vector<double> stats;
    std::string rest = summary.substr(at + prefix.size(), summary.find('\n', at) - at - prefix.size());
    for (std::size_t b = 0; b <= rest.size();) {
      const std::size_t e = std::min(rest.find(',', b), rest.size());
      stats.push_back(std::stod(rest.substr(b, e - b)));
      b = e + 1;
    }
    const std::vector<double> expected{3.0, std::sqrt(2.5), 1.0, 1.2, 2.0, 3.0, 4.0, 4.8, 5.0};
    REQUIRE(stats.size() == expected.size());
    for (std::size_t k = 0; k < expected.size(); ++k) CHECK(stats[k] == Approx(expected[k]).epsilon(1e-12));
  }
}

TEST_CASE("A sweep's table does not depend on the number of threads", "[sweep]") {
  const SweepCase c = parse_sweep_case(R"(
[grid]
damping = ["hongo", "hunt-crossley", "kuwabara-kono"]
[sample]
method = "monte-carlo"
count = 50
seed = 11
height = { distribution = "lognormal", log_mean = -3.9, log_sd = 0.5, max = 0.2 }
)",
                                       "threads.toml");
  const PaperParameters paper = load_paper_parameters();
  const std::string one = sweep_table(c, run_sweep(c, all_runs(c), paper, {.threads = 1, .progress = false}), "timing: 1");
  const std::string two = sweep_table(c, run_sweep(c, all_runs(c), paper, {.threads = 2, .progress = false}), "timing: 2");
  CHECK(one != two);  // the timing lines differ ...
  CHECK(without_timing(one) == without_timing(two));  // ... and nothing else
}
