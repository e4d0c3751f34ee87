// hertzdash fit (simulation/fit/trace_fit.hpp) on SYNTHETIC traces, virtual experiments made by
// the model itself with known truth (simulation/fit/virtual_measurement.hpp): no measured trace of
// the paper exists. The truths are recovered within the method's stated errors, the
// estimates' error bars are honest, degenerate parameters are flagged, and the identities of
// the laws (the paper's dashpot c x^{1/2} xdot has the form of Kuwabara-Kono's) hold in the fit.
#include "cli_runner.hpp"
#include "scratch_dir.hpp"
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <catch2/catch.hpp>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace hertzdash;
using hertzdash::test::run_cli;
using hertzdash::test::ScratchDir;
namespace fs = std::filesystem;

namespace {

// The truth of the done-when of issue 16: steel rod from 20 mm, nylon E = 1.7 GPa, e = 0.80.
RunOptions truth_options() {
  RunOptions o;
  o.ball_E_Pa = 1.7e9;
  o.restitution = 0.80;
  // A fine fixed step: the virtual experiment's samples between steps are linear interpolations,
  // here with error (pi 2e-7 / 1.3e-3)^2 / 8 = 3e-8 of the peak.
  o.integrator = "rk4";
  o.dt_s = 2e-7;
  return o;
}

MeasuredTrace virtual_trace(const RunOptions& o, const MeasurementChain& chain) {
  const PaperParameters paper = load_paper_parameters();
  const SimulateRun run = run_simulate(o, paper, true);
  MeasuredTrace m = virtual_measurement(run, o.rod, chain);
  m.path = "virtual.csv";
  return m;
}

}  // namespace

TEST_CASE("fit: a noise-free virtual experiment gives back its truth", "[fit]") {
  // Truth and model differ only by their discretisations: the trace interpolates RK4 at 2e-7 s,
  // the model RK4 at t_H / 2000 = 6.2e-7 s (t_H at the starting values), both linearly:
  // (pi / 2000)^2 / 8 = 3e-7 of the peak. The estimates move by the same order relative to
  // their sensitivities (d ln F / d ln E ~ 0.4): 1e-5 bounds it with margin.
  MeasurementChain chain;
  const MeasuredTrace m = virtual_trace(truth_options(), chain);
  const FitResult f = fit_trace(m, RunOptions{}, load_paper_parameters(), TraceFitSettings{});
  INFO("E " << f.parameter("ball-E").estimate << " e " << f.parameter("restitution").estimate << " t0 "
            << f.parameter("onset-time").estimate);
  CHECK(f.parameter("ball-E").estimate == Approx(1.7e9).epsilon(1e-5));
  CHECK(f.parameter("restitution").estimate == Approx(0.80).epsilon(1e-5));
  // The onset is the trace's zero to within a fraction of the model's step.
  CHECK(std::abs(f.parameter("onset-time").estimate) < 1e-8);
  CHECK(f.identifiable);
}

TEST_CASE("fit: 1 % noise, the estimates lie within their 2-sigma intervals, each under 3 % wide", "[fit]") {
  // Issue 16's acceptance. The noise is white, so the least-squares estimate is unbiased to
  // first order with the covariance s^2 (J^T J)^{-1}; a 2-sigma interval misses with
  // probability 4.6 % per parameter. Three fixed seeds, checked once (not fished for).
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    MeasurementChain chain;
    chain.noise_fraction = 0.01;
    chain.seed = seed;
    const FitResult f = fit_trace(virtual_trace(truth_options(), chain), RunOptions{}, load_paper_parameters(), {});
    for (const auto& [name, truth] : {std::pair{"ball-E", 1.7e9}, std::pair{"restitution", 0.80}}) {
      const FittedParameter& p = f.parameter(name);
      INFO("seed " << seed << ": " << name << " = " << p.estimate << " +- " << p.standard_error);
      CHECK(std::abs(p.estimate - truth) < 2 * p.standard_error);
      CHECK(4 * p.standard_error / p.estimate < 0.03);
    }
    // The noise estimate from second differences finds the noise that was added, and the
    // model explains the trace to it: reduced chi-square ~ 1 (n ~ 4800: +-0.02 at 1 sigma,
    // plus the MAD estimate's ~2 % scatter).
    CHECK(f.reduced_chi_square == Approx(1.0).margin(0.1));
    CHECK(f.identifiable);
  }
}

TEST_CASE("fit: the onset on the trace's clock is found, a shifted trace gives the same estimates", "[fit]") {
  // From a trigger 37 us early to a clock started a second before the contact: the fit starts
  // the onset where the trace departs from free fall, so the shift is found to a fraction of
  // the model's step (6e-7 s) and the estimates are those of the unshifted trace (1e-5, as above).
  MeasurementChain chain;
  const MeasuredTrace original = virtual_trace(truth_options(), chain);
  for (double shift_s : {37e-6, 3e-3, 1.0}) {
    MeasuredTrace m = original;
    for (double& t : m.t_s) t += shift_s;
    const FitResult f = fit_trace(m, RunOptions{}, load_paper_parameters(), {});
    INFO("shift " << shift_s);
    CHECK(f.parameter("onset-time").estimate == Approx(shift_s).margin(1e-8));
    CHECK(f.parameter("ball-E").estimate == Approx(1.7e9).epsilon(1e-5));
    CHECK(f.converged);
  }
}

TEST_CASE("fit: a parameter the trace does not see has an infinite standard error", "[fit]") {
  // Against a rigid flat (rod-E = inf) the flat's Poisson ratio changes nothing: 1/E* =
  // (1 - nu_b^2)/E_b + (1 - nu_r^2)/E_r loses its second term, so the column of J for rod-nu is
  // zero and its variance infinite (not the zero GSL's pivoted covariance would give it).
  MeasurementChain chain;
  chain.noise_fraction = 0.01;
  RunOptions start;
  start.rod_E_Pa = std::numeric_limits<double>::infinity();
  TraceFitSettings s;
  s.parameters = parse_fit_parameters("rod-nu,ball-E");
  const FitResult f = fit_trace(virtual_trace(truth_options(), chain), start, load_paper_parameters(), s);
  CHECK(std::isinf(f.parameter("rod-nu").standard_error));
  CHECK(std::isfinite(f.parameter("ball-E").standard_error));
  CHECK_FALSE(f.identifiable);
}

TEST_CASE("fit: a degenerate pair is flagged: ball-E and ball-radius enter only through K", "[fit]") {
  // K = (4/3) E* sqrt(R) and nothing else in the rigid model sees E or R: the Jacobian's two
  // columns are proportional, its smallest singular value is the differencing error.
  MeasurementChain chain;
  chain.noise_fraction = 0.01;
  TraceFitSettings s;
  s.parameters = parse_fit_parameters("ball-E,ball-radius");
  const FitResult f = fit_trace(virtual_trace(truth_options(), chain), RunOptions{}, load_paper_parameters(), s);
  CHECK_FALSE(f.identifiable);
  CHECK(std::abs(f.correlation[0][1]) > identifiable_correlation_limit);
  // Among other parameters the pair still shows, by its correlation.
  s.parameters = parse_fit_parameters("mass,ball-E,restitution,ball-radius");
  const FitResult g = fit_trace(virtual_trace(truth_options(), chain), RunOptions{}, load_paper_parameters(), s);
  CHECK_FALSE(g.identifiable);
}

TEST_CASE("fit: the paper's law and Kuwabara-Kono are one law at one speed, the x^{3/2} xdot family is not", "[fit]") {
  // The paper's dashpot c_e x^{1/2} xdot and Kuwabara-Kono's K A x^{1/2} xdot have the same form;
  // with e fitted, both fit a trace made by the paper's law equally (their chi^2 agree to the
  // fit's convergence), while a Hunt-Crossley force (x^{3/2} xdot) cannot match its shape:
  // a higher AIC by far more than the 2 per parameter the criterion charges.
  MeasurementChain chain;
  chain.noise_fraction = 0.01;
  const MeasuredTrace m = virtual_trace(truth_options(), chain);
  const PaperParameters paper = load_paper_parameters();
  RunOptions kk, hc;
  kk.damping = "kuwabara-kono";
  hc.damping = "hunt-crossley";
  const FitResult paper_law = fit_trace(m, RunOptions{}, paper, {});
  const FitResult kuwabara = fit_trace(m, kk, paper, {});
  const FitResult hunt = fit_trace(m, hc, paper, {});
  CHECK(kuwabara.chi_square == Approx(paper_law.chi_square).epsilon(1e-6));
  CHECK(hunt.aic > paper_law.aic + 100);
}

TEST_CASE("fit: columns in other units are read into SI and give the same fit", "[fit][measured_trace]") {
  const fs::path dir = fs::temp_directory_path() / ("hertzdash_fit_units_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  MeasurementChain chain;
  chain.noise_fraction = 0.01;
  chain.channels = {"force_N"};
  const MeasuredTrace m = virtual_trace(truth_options(), chain);
  write_measured_trace(dir / "si.csv", m, "test", {});
  {
    std::ofstream out(dir / "units.csv");
    out << "# source: SYNTHETIC, tests/test_trace_fit.cpp\n# rod: steel\n# height_m: 0.02\n# synthetic: true\n"
        << "t_us,force_kN\n";
    out.precision(17);
    for (std::size_t i = 0; i < m.t_s.size(); ++i) out << m.t_s[i] * 1e6 << "," << m.force_N[i] / 1e3 << "\n";
  }
  const PaperParameters paper = load_paper_parameters();
  const FitResult a = fit_trace(read_measured_trace(dir / "si.csv"), {}, paper, {});
  const FitResult b = fit_trace(read_measured_trace(dir / "units.csv"), {}, paper, {});
  // Unit conversion rounds each sample once (1e-16 relative), far below the estimates' errors.
  CHECK(b.parameters[0].estimate == Approx(a.parameters[0].estimate).epsilon(1e-9));
  CHECK(b.parameters[1].estimate == Approx(a.parameters[1].estimate).epsilon(1e-9));
  fs::remove_all(dir);
}

TEST_CASE("fit: the anti-alias filter's delay is absorbed by the onset time", "[fit]") {
  // A second-order Butterworth low-pass delays a slow signal by its group delay at zero
  // frequency, sqrt(2) / (2 pi f_c) (= 2.25 us at 100 kHz). The contact's force is slow against
  // f_c (its spectrum lies below ~1/t_c ~ 1 kHz), so the fit's onset moves by that delay, to
  // the filter's second-order term (omega t_d)^2 ~ 1e-4, and the estimates barely move.
  MeasurementChain chain;
  chain.anti_alias_cutoff_Hz = 1e5;
  const FitResult f = fit_trace(virtual_trace(truth_options(), chain), {}, load_paper_parameters(), {});
  const double delay_s = std::numbers::sqrt2 / (2 * std::numbers::pi * 1e5);
  INFO("onset " << f.parameter("onset-time").estimate << " delay " << delay_s);
  CHECK(f.parameter("onset-time").estimate == Approx(delay_s).epsilon(0.02));
  CHECK(f.parameter("ball-E").estimate == Approx(1.7e9).epsilon(1e-3));
  CHECK(f.parameter("restitution").estimate == Approx(0.80).epsilon(1e-3));
}

TEST_CASE("fit: traces unfit for fitting are refused with the file and the reason", "[fit][measured_trace]") {
  const fs::path dir = fs::temp_directory_path() / ("hertzdash_fit_bad_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string header = "# source: SYNTHETIC, tests/test_trace_fit.cpp\n# rod: steel\n# height_m: 0.02\n# synthetic: true\n";
  auto write = [&](const std::string& name, const std::string& body) {
    std::ofstream(dir / name) << header << body;
    return dir / name;
  };
  const PaperParameters paper = load_paper_parameters();
  auto error_of = [&](const fs::path& file, const TraceFitSettings& s = {}) -> std::string {
    try {
      fit_trace(read_measured_trace(file), {}, paper, s);
    } catch (const DataError& e) {
      return e.what();
    }
    return "no error";
  };

  SECTION("no contact: the force stays in its noise") {
    std::string body = "t_s,force_N\n";
    for (int i = 0; i < 2000; ++i) body += std::to_string(i * 1e-6) + "," + (i % 2 ? "0.1" : "-0.1") + "\n";
    const std::string e = error_of(write("flat.csv", body));
    CHECK(e.find("flat.csv: no contact") != std::string::npos);
  }
  SECTION("too coarse: the message says the least sampling rate") {
    // t_c = 1.24 ms for the paper's steel rod: ten samples need 8.0 kHz.
    std::string body = "t_s,force_N\n";
    for (int i = 0; i < 20; ++i) body += std::to_string(i * 2e-4) + "," + std::to_string(1000 * std::sin(i * 0.3)) + "\n";
    const std::string e = error_of(write("coarse.csv", body));
    CHECK(e.find("coarse.csv: sampled every 0.0002 s") != std::string::npos);
    CHECK(e.find("a sampling rate of at least 80") != std::string::npos);
  }
  SECTION("a channel that never changes") {
    std::string body = "t_s,force_N,displacement_m\n";
    for (int i = 0; i < 2000; ++i)
      body += std::to_string(i * 1e-6) + "," + std::to_string(1000 * std::sin(3.14159 * i / 1240.0)) + ",0\n";
    CHECK(error_of(write("constant.csv", body)).find("the displacement_m column never changes") != std::string::npos);
  }
  SECTION("free fall without a contact in the displacement alone") {
    // x = v0 t + g t^2 / 2 keeps rising: no return from a largest value.
    std::string body = "t_s,displacement_m\n";
    for (int i = 0; i < 2000; ++i) {
      const double t = i * 1e-6;
      body += std::to_string(t) + "," + fmt::format("{:.17g}", 0.626 * t + 0.5 * 9.81 * t * t) + "\n";
    }
    CHECK(error_of(write("falling.csv", body)).find("no contact in the trace") != std::string::npos);
  }
  SECTION("a channel asked for that the trace lacks") {
    TraceFitSettings s;
    s.channels = {"accel_mps2"};
    CHECK(error_of(write("force_only.csv", "t_s,force_N\n0,0\n1e-6,1\n"), s).find("no accel_mps2 column") !=
          std::string::npos);
  }
  SECTION("the reader refuses nan, inf and time running backwards, naming the sample") {
    CHECK_THROWS_WITH(read_measured_trace(write("nan.csv", "t_s,force_N\n0,0\n1e-6,nan\n")),
                      Catch::Contains("nan.csv") && Catch::Contains("'nan' is not a decimal number"));
    CHECK_THROWS_WITH(read_measured_trace(write("inf.csv", "t_s,force_N\n0,0\n1e-6,inf\n")),
                      Catch::Contains("inf.csv:") && Catch::Contains("column 'force_N'") &&
                          Catch::Contains("'inf' is not a decimal number"));
    CHECK_THROWS_WITH(read_measured_trace(write("back.csv", "t_s,force_N\n0,0\n2e-6,1\n1e-6,2\n")),
                      Catch::Contains("back.csv: the time must increase strictly (sample 3)"));
    CHECK_THROWS_WITH(read_measured_trace(write("two.csv", "t_s,force_N,force_kN\n0,0,0\n1e-6,1,0.001\n")),
                      Catch::Contains("columns 'force_N' and 'force_kN' are the same quantity"));
  }
  fs::remove_all(dir);
}

TEST_CASE("CLI fit: the issue's recipe, simulate --trace-format measured then fit, recovers E and e", "[fit][cli]") {
  // Issue 16's done-when, through the command line: 1 % noise; with simulate's default solver
  // (CVODE, whose steps of up to 26 us the virtual measurement interpolates linearly, an error of
  // (pi 26 us / 1.25 ms)^2 / 8 = 5e-4 of the peak, below the noise) and with a fine fixed step.
  const fs::path trace = fs::temp_directory_path() / ("hertzdash_fit_cli_" + std::to_string(::getpid()) + ".csv");
  for (const std::string solver : {"", " --integrator rk4 --dt 2e-7"}) {
    INFO("solver:" << solver);
    const auto made = run_cli("simulate --ball-E 1.7e9 --restitution 0.80 --trace " + trace.string() +
                              " --trace-format measured --noise 0.01" + solver);
    REQUIRE(made.exit_code == 0);
    const MeasuredTrace m = read_measured_trace(trace);
    CHECK(m.synthetic);
    CHECK(m.source.find("SYNTHETIC") == 0);
    const auto r = run_cli("fit --trace " + trace.string() + " --json");
    REQUIRE(r.exit_code == 0);
    CHECK(r.err.find("'synthetic: true': it is not a measurement") != std::string::npos);
    const auto j = nlohmann::json::parse(r.out);
    const auto& p = j["fits"][0]["parameters"];
    CHECK(p[0]["name"] == "ball-E");
    CHECK(std::abs(p[0]["estimate"].get<double>() - 1.7e9) < 2 * p[0]["standard_error"].get<double>());
    CHECK(std::abs(p[1]["estimate"].get<double>() - 0.80) < 2 * p[1]["standard_error"].get<double>());
    CHECK(j["trace"]["synthetic"] == true);
    CHECK(j["fits"][0]["converged"] == true);
    CHECK(4 * p[0]["standard_error"].get<double>() / 1.7e9 < 0.03);
  }
  fs::remove(trace);
}

TEST_CASE("CLI fit --curves and --compare-laws", "[fit][cli]") {
  const fs::path dir = fs::temp_directory_path() / ("hertzdash_fit_curves_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path trace = dir / "t.csv", curves = dir / "curves.csv";
  REQUIRE(run_cli("simulate --trace " + trace.string() + " --trace-format measured --noise 0.01 --channels force_N")
              .exit_code == 0);
  SECTION("the curves hold the trace, the model and their difference") {
    REQUIRE(run_cli("fit --trace " + trace.string() + " --curves " + curves.string()).exit_code == 0);
    const CsvTable t = CsvTable::read(curves);
    REQUIRE(t.columns() == std::vector<std::string>{"t_s", "force_N_measured", "force_N_model", "force_N_residual"});
    const MeasuredTrace m = read_measured_trace(trace);
    REQUIRE(t.rows() == m.t_s.size());
    for (std::size_t r = 0; r < t.rows(); r += 97) {
      CHECK(t.number(r, "force_N_measured") == m.force_N[r]);
      CHECK(t.number(r, "force_N_residual") == t.number(r, "force_N_measured") - t.number(r, "force_N_model"));
    }
  }
  SECTION("a failing fit leaves no curves file") {
    CHECK(run_cli("fit --trace " + trace.string() + " --fit ball-colour --curves " + curves.string()).exit_code == 2);
    CHECK_FALSE(fs::exists(curves));
  }
  SECTION("--compare-laws ranks every law, names the tie of the paper's law with Kuwabara-Kono") {
    const auto r = run_cli("fit --trace " + trace.string() + " --compare-laws --json");
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["fits"].size() + j["failures"].size() == registered_laws().size());
    for (std::size_t i = 1; i < j["fits"].size(); ++i) CHECK(j["fits"][i]["aic"] >= j["fits"][i - 1]["aic"]);
    const auto text = run_cli("fit --trace " + trace.string() + " --compare-laws");
    CHECK((text.out.find("best: 'hongo' (not preferred by AIC over: kuwabara-kono, within dAIC < 2)") != std::string::npos ||
           text.out.find("best: 'kuwabara-kono' (not preferred by AIC over: hongo, within dAIC < 2)") != std::string::npos));
  }
  SECTION("--compare-laws with a --fit the start lies outside of is the user's error") {
    const auto r = run_cli("fit --trace " + trace.string() + " --compare-laws --fit restitution:0.9:1");
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("bounds around the starting value") != std::string::npos);
  }
  fs::remove_all(dir);
}

TEST_CASE("CLI fit and the virtual measurement: bad options exit 2 naming the option", "[fit][cli]") {
  const fs::path trace = fs::temp_directory_path() / ("hertzdash_fit_opts_" + std::to_string(::getpid()) + ".csv");
  REQUIRE(run_cli("simulate --trace " + trace.string() + " --trace-format measured").exit_code == 0);
  const std::pair<std::string, std::string> cases[] = {
      {"fit --trace " + trace.string() + " --fit ball-colour", "--fit"},
      {"fit --trace " + trace.string() + " --fit restitution:0.5:1.5", "within --restitution's range"},
      {"fit --trace " + trace.string() + " --fit ball-E:3e9:4e9", "bounds around the starting value"},
      {"fit --trace " + trace.string() + " --fit ball-E,ball-E", "each parameter once"},
      {"fit --trace " + trace.string() + " --channels force", "--channels"},
      {"fit --trace " + trace.string() + " --resample 1e7", "below the trace's sampling rate"},
      {"fit --trace " + trace.string() + " --mass -1", "--mass"},
      {"fit --trace " + trace.string() + " --fit viscous-time-constant --damping kuwabara-kono", "given a starting value"},
      {"simulate --noise 0.01", "given only with --trace-format measured"},
      {"simulate --trace-format measured", "given with --trace FILE"},
      {"simulate --trace x.csv --trace-format measured --sample-rate 0", "--sample-rate"},
      {"simulate --trace x.csv --trace-format measured --anti-alias 6e5", "half the sampling rate"},
      {"simulate --trace x.csv --trace-format measured --noise -0.1", "in [0, 1]"},
      {"simulate --trace x.csv --trace-format measured --noise 2", "in [0, 1]"},
      {"simulate --trace x.csv --trace-format measured --sample-rate 1e12", "1e+07 samples over this contact's window"},
      {"simulate --trace x.csv --trace-format wav", "one of: model, measured"},
  };
  for (const auto& [args, expected] : cases) {
    const auto r = run_cli(args);
    INFO(args << "\n  stderr: " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(expected) != std::string::npos);
    CHECK_FALSE(fs::exists("x.csv"));
  }
  fs::remove(trace);
}

namespace {

// A trace file for the tests of issue 31: the virtual experiment of `o` through `chain`, at `path`.
fs::path written_trace(const fs::path& path, const RunOptions& o, const MeasurementChain& chain) {
  write_measured_trace(path, virtual_trace(o, chain), "tests/test_trace_fit.cpp (issue 31)", {});
  return path;
}

// `file` with every line passed through `edit(line, sample index, or -1 for a header line and the column row)`.
void edit_trace(const fs::path& file, const std::function<std::string(const std::string&, int)>& edit) {
  std::istringstream in(hertzdash::test::slurp(file));
  std::string line, out;
  bool columns_seen = false;
  int sample = 0;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || !columns_seen) {
      columns_seen = columns_seen || !(line.empty() || line[0] == '#');
      out += edit(line, -1) + "\n";
    } else {
      out += edit(line, sample++) + "\n";
    }
  }
  std::ofstream(file) << out;
}

// A CSV row's fields.
std::vector<std::string> fields(const std::string& row) {
  std::vector<std::string> out;
  std::istringstream in(row);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("hertzdash_fit31_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

}  // namespace

TEST_CASE("fit: the trace's header sets the rod and height, validated, a conflicting option refused", "[fit]") {
  // Issue 31: a duralumin-b trace from 50 mm fitted with default options was fitted as the
  // steel rod from 20 mm (E = 3.88e9, e = 0.27). Noise-free, the header's set-up gives back the
  // truth (2.0e9 Pa and Table 2's e = 0.846) to the discretisation error of the first test.
  RunOptions truth;
  truth.rod = "duralumin-b";
  truth.height_m = 0.05;
  truth.integrator = "rk4";
  truth.dt_s = 2e-7;
  const fs::path file = written_trace(scratch("dur.csv"), truth, MeasurementChain{});
  const PaperParameters paper = load_paper_parameters();
  const FitRun r = run_fit(file.string(), RunOptions{}, paper, TraceFitSettings{}, false);
  CHECK(r.fits[0].parameter("ball-E").estimate == Approx(2.0e9).epsilon(1e-4));
  CHECK(r.fits[0].parameter("restitution").estimate == Approx(0.846).epsilon(1e-4));
  CHECK(r.fits[0].fitted_options.rod == "duralumin-b");
  CHECK(r.fits[0].identifiable);

  auto refusal = [&](const RunOptions& o, const std::vector<std::string>& given = {}) -> InvalidParameter {
    try {
      run_fit(file.string(), o, paper, TraceFitSettings{}, false, given);
    } catch (const InvalidParameter& e) {
      return e;
    }
    return InvalidParameter("none", "", "");
  };
  SECTION("an option that says the same is no conflict: the height within 0.5 mm") {
    RunOptions o;
    o.height_m = 0.0503;
    o.rod = "duralumin-b";
    CHECK(run_fit(file.string(), o, paper, TraceFitSettings{}, false).fits[0].identifiable);
  }
  SECTION("a conflict names the option and both values") {
    RunOptions o;
    o.height_m = 0.02;
    const InvalidParameter e = refusal(o);
    CHECK(e.key == "height");
    CHECK(e.value == "0.02");
    CHECK(e.valid_range.find("0.05 m") != std::string::npos);
    CHECK(e.valid_range.find("dur.csv") != std::string::npos);
    // --rod steel is the default's value, given: a front end says so (`given`).
    const InvalidParameter rod = refusal(RunOptions{}, {"rod"});
    CHECK(rod.key == "rod");
    CHECK(rod.value == "steel");
    CHECK(rod.valid_range.find("duralumin-b") != std::string::npos);
  }
  SECTION("a given approach speed replaces the header's height") {
    RunOptions o;
    o.impact_velocity_mps = std::sqrt(2 * 9.80665 * 0.05);  // the same drop
    CHECK(run_fit(file.string(), o, paper, TraceFitSettings{}, false).fits[0].identifiable);
  }
  SECTION("header values are validated like the options, the file named") {
    edit_trace(file, [](const std::string& line, int) { return line == "# rod: duralumin-b" ? "# rod: wood" : line; });
    const InvalidParameter wood = refusal(RunOptions{});
    CHECK(wood.key == "rod");
    CHECK(wood.value == "wood");
    CHECK(wood.valid_range.find("one of: steel") != std::string::npos);
    CHECK(wood.valid_range.find("dur.csv") != std::string::npos);
    edit_trace(file, [](const std::string& line, int) {
      return line == "# rod: wood" ? "# rod: duralumin-b" : line.rfind("# height_m:", 0) == 0 ? "# height_m: 1e300" : line;
    });
    // From 1e300 m the Hertz deformation would exceed the ball's radius: the set-up's own check.
    const InvalidParameter high = refusal(RunOptions{});
    CHECK(high.key == "height");
    CHECK(high.valid_range.find("height_m: 1e+300") != std::string::npos);
  }
  fs::remove_all(file.parent_path());
}

TEST_CASE("fit: nonsense traces are refused, or their fit fails and says so", "[fit]") {
  // Issue 31. The 1 % noise trace of the steel rod (truth 1.7 GPa, e = 0.80), spoilt three ways.
  MeasurementChain chain;
  chain.noise_fraction = 0.01;
  chain.sample_rate_Hz = 2e5;  // 300 samples: a fast fit, ample for the contact of 1.3 ms
  const fs::path file = written_trace(scratch("steel.csv"), truth_options(), chain);
  const PaperParameters paper = load_paper_parameters();
  auto fitted = [&](const TraceFitSettings& s = {}) { return run_fit(file.string(), {}, paper, s, false).fits[0]; };
  auto data_error = [&](const TraceFitSettings& s = {}) -> std::string {
    try {
      fitted(s);
    } catch (const DataError& e) {
      return e.what();
    }
    return "no error";
  };

  SECTION("force in kN read as N: the model cannot reach it, restitution ends at its bound") {
    // 1000 times the force needs 1000 times the impulse m (1 + e) v0, beyond any e <= 1.
    edit_trace(file, [](const std::string& line, int sample) {
      if (sample < 0) return line == "t_s,force_N,accel_mps2,displacement_m" ? std::string("t_s,force_N") : line;
      const auto f = fields(line);
      return f[0] + "," + fmt::format("{:.17g}", 1000 * std::stod(f[1]));
    });
    const FitResult f = fitted();
    CHECK(f.failed);
    CHECK(f.failure.find("restitution ended at its bound") != std::string::npos);
    CHECK_FALSE(f.identifiable);
  }
  SECTION("one row of 1e300 is an outlier, named by its sample") {
    edit_trace(file, [](const std::string& line, int sample) {
      return sample == 150 ? fields(line)[0] + ",1e300,1e300,1e300" : line;
    });
    const std::string e = data_error();
    INFO(e);
    CHECK(e.find("steel.csv: sample 151") != std::string::npos);
    CHECK(e.find("is an outlier") != std::string::npos);
  }
  SECTION("time steps of 1e-300 s are not resolved against the contact's time scale") {
    edit_trace(file, [](const std::string& line, int sample) {
      if (sample < 0) return line;
      const std::string rest = line.substr(line.find(','));
      return fmt::format("{:.17g}", sample * 1e-300) + rest;
    });
    CHECK(data_error().find("finer than the model resolves") != std::string::npos);
  }
  SECTION("a time axis compressed tenfold: the fit stops at its work bound and has failed") {
    // The trace's contact is 10 times shorter than the model's at the start (E 316 times the
    // start's would be needed, t_c ~ E^(-2/5)); the fit wanders towards e -> 0, where each model
    // run lasts its whole window of 20 t_H. A bound of 2e6 stops it after a few iterations; its
    // work overshoots the bound by at most one iteration (16 trial runs and 2p = 6 Jacobian runs
    // of at most 20 t_H / (t_H / 2000) = 4e4 steps and 300 x 3 observations each).
    edit_trace(file, [](const std::string& line, int sample) {
      if (sample < 0) return line;
      const std::string rest = line.substr(line.find(','));
      return fmt::format("{:.17g}", 0.1 * std::stod(fields(line)[0])) + rest;
    });
    TraceFitSettings s;
    s.max_work = 2e6;
    const FitResult f = fitted(s);
    CHECK(f.failed);
    CHECK_FALSE(f.identifiable);
    CHECK(f.work <= s.max_work + 22 * (4e4 + 900));
  }
  SECTION("a work bound below the first iterations' predicted work is refused before iterating") {
    // One run at the start: about 2000 steps and 900 observations; 5 iterations of 8 runs.
    TraceFitSettings s;
    s.max_work = 1e4;
    CHECK(data_error(s).find("the fit would exceed its work limit") != std::string::npos);
  }
  fs::remove_all(file.parent_path());
}

TEST_CASE("CLI fit: a failed fit exits 3 and prints no identifiable, refusals exit 2", "[fit][cli]") {
  const fs::path file = scratch("cli.csv");
  REQUIRE(run_cli("simulate --ball-E 1.7e9 --restitution 0.80 --trace " + file.string() +
                  " --trace-format measured --noise 0.01 --sample-rate 2e5")
              .exit_code == 0);
  const auto rod = run_cli("fit --trace " + file.string() + " --rod duralumin-a");
  CHECK(rod.exit_code == 2);
  const auto steel = run_cli("fit --trace " + file.string() + " --rod steel");  // the header's rod, given: fine
  CHECK(steel.exit_code == 0);
  CHECK(steel.out.find("(identifiable)") != std::string::npos);
  const auto other = run_cli("fit --trace " + file.string() + " --height 0.03");
  CHECK(other.exit_code == 2);
  CHECK(other.err.find("--height = 0.03") != std::string::npos);
  CHECK(other.err.find("0.02 m") != std::string::npos);

  edit_trace(file, [](const std::string& line, int sample) {  // force in kN read as N
    if (sample < 0) return line == "t_s,force_N,accel_mps2,displacement_m" ? std::string("t_s,force_N") : line;
    const auto f = fields(line);
    return f[0] + "," + fmt::format("{:.17g}", 1000 * std::stod(f[1]));
  });
  const auto failed = run_cli("fit --trace " + file.string());
  CHECK(failed.exit_code == 3);
  CHECK(failed.out.find("identifiable") == std::string::npos);
  CHECK(failed.out.find("FIT FAILED: ") != std::string::npos);
  CHECK(failed.err.find("the fit failed") != std::string::npos);
  const auto json = run_cli("fit --json --trace " + file.string());
  CHECK(json.exit_code == 3);
  const auto j = nlohmann::json::parse(json.out);
  CHECK(j["fits"][0]["failed"] == true);
  CHECK(j["fits"][0]["identifiable"] == false);
  fs::remove_all(file.parent_path());
}

// Cross-validation of a trace (`--cross-validate`, the fit engine's: five interleaved folds, each
// predicted from a fit of the other four with its own onset re-fitted). The force of the truth
// above with white noise of 1 % of its peak: the law that made it predicts the left-out samples
// to that noise, so the RMS prediction error is the noise sigma, which the fit's weight estimates
// (the channel's noise_sigma): scored in standardized residuals (each divided by its channel's
// noise sigma, so that channels of different units add up), the scatter is 1 and the RMS
// prediction error, the ratio, is 1 within the spread
// of an RMS over the n samples (1 / sqrt(2 n), n about 1300 at 1 MHz: 2 %) and of the weight's
// robust estimate (a median absolute deviation: about 3 %); [0.85, 1.15] is about 4 of those.
// The undamped law cannot make the rebound (e = 1 against 0.80): with only E and the onset to
// move, its best force pulse misses the measured one by several noise levels (asserted: 3).
TEST_CASE("fit --trace --cross-validate: the law that made a trace predicts left-out samples to its noise",
          "[fit][cli]") {
  MeasurementChain chain;
  chain.noise_fraction = 0.01;
  chain.seed = 4;
  chain.channels = {"force_N"};
  const MeasuredTrace m = virtual_trace(truth_options(), chain);
  TraceFitSettings s;
  s.cross_validate = true;
  const FitResult f = fit_trace(m, RunOptions{}, load_paper_parameters(), s);
  REQUIRE(f.cross_validation);
  const CrossValidation& cv = *f.cross_validation;
  INFO("rms " << cv.rms_prediction_error << " scatter " << cv.scatter << " failure " << cv.failure);
  CHECK(cv.folds == trace_folds);
  CHECK(cv.failure.empty());
  CHECK(cv.scatter == 1);  // standardized residuals (was the channel's noise sigma in N)
  CHECK(cv.rms_prediction_error == Approx(cv.ratio).epsilon(1e-12));
  CHECK(cv.ratio > 0.85);
  CHECK(cv.ratio < 1.15);

  RunOptions undamped;
  undamped.damping = "none";
  s.parameters = parse_fit_parameters("ball-E");
  const FitResult g = fit_trace(m, undamped, load_paper_parameters(), s);
  REQUIRE(g.cross_validation);
  CHECK(g.cross_validation->ratio > 3);

  ScratchDir dir;
  const auto file = dir.path / "cv.csv";
  write_measured_trace(file, m, "tests/test_trace_fit.cpp: a SYNTHETIC trace", {});
  const auto text = run_cli("fit --trace " + file.string() + " --cross-validate");
  CHECK(text.exit_code == 0);
  CHECK(text.out.find("cross-validation (5 sets of interleaved samples left out in turn)") != std::string::npos);
}
