// `hertzdash fit --restitution-table` (simulation/fit/restitution_fit.hpp) on SYNTHETIC tables
// made by the suite itself: a law's e_effective at several speeds, computed through
// run_restitution (CVODE at rtol 1e-12: another integrator than the fit's gbs8), written as a
// table labelled `synthetic: true`. No measured table ships.
#include "cli_runner.hpp"
#include "restitution_at_speeds.hpp"
#include "scratch_dir.hpp"
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/restitution_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace hertzdash;
using hertzdash::test::run_cli;
using hertzdash::test::ScratchDir;

namespace {

// The truths: the paper's law at input e = 0.80; Kuwabara-Kono's at A = 7.7e-5 s (about what
// its calibration gives for the steel rod, docs/bounce.md), both with the steel rod's set-up.
RunOptions hongo_truth() {
  RunOptions o;
  o.restitution = 0.80;
  return o;
}

RunOptions kuwabara_kono_truth() {
  RunOptions o;
  o.damping = "kuwabara-kono";
  o.viscous_time_constant_s = 7.7e-5;
  return o;
}

RestitutionTable synthetic_table(const RunOptions& truth, const std::vector<double>& speeds, double sd = 0,
                                 unsigned seed = 0) {
  RestitutionTable t;
  t.path = "synthetic.csv";
  t.source = "SYNTHETIC: written by tests/test_restitution_table_fit.cpp, law " + truth.damping;
  t.synthetic = true;
  t.impact_speed_mps = speeds;
  t.e = test::restitution_at_speeds(truth, speeds);
  if (sd > 0) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, sd);
    for (double& e : t.e) e += noise(rng);
    t.e_sd.assign(speeds.size(), sd);
  }
  return t;
}

const std::vector<double> six_speeds{0.2, 0.4, 0.6, 0.8, 1.0, 1.2};

// 8 speeds x 5 trials.
std::vector<double> repeated_speeds() {
  std::vector<double> v;
  for (int s = 1; s <= 8; ++s)
    for (int trial = 0; trial < 5; ++trial) v.push_back(0.15 * s);
  return v;
}

FitResult fit(const RestitutionTable& t, const std::string& law, bool cross_validate = false) {
  RunOptions o;
  o.damping = law;
  FitSettings s;
  s.cross_validate = cross_validate;
  const PaperParameters paper = load_paper_parameters();
  FitResult f = fit_restitution_table(t, o, paper, s);
  return f;
}

}  // namespace

// Accuracy. A table value is e_effective from CVODE at rtol 1e-12, the model's from gbs8 at
// rtol = atol = 1e-12: each accurate to about 1e-10 (the noise-free fits' residuals are 1e-10).
// The estimate errs by the residual over de/dp: for the paper's law de_eff/de_in is about 1, so
// the input e is recovered to ~1e-10; for Kuwabara-Kono e = 1 - C1 beta + ..., beta proportional
// to A, so de/d(ln A) is about -(1 - e) = -0.2 and ln A errs by ~1e-10 / 0.2 = 5e-10. The
// assertions allow a hundred times that (GSL stops at xtol 1e-10 relative in the variables).
TEST_CASE("restitution table: the law that made a noise-free table gives back its parameter", "[restitution_fit]") {
  const FitResult h = fit(synthetic_table(hongo_truth(), six_speeds), "hongo");
  CHECK_FALSE(h.failed);
  CHECK(h.parameters.size() == 1);
  CHECK(h.parameter("restitution").estimate == Approx(0.80).margin(1e-8));
  CHECK(h.sigma_estimated);

  const FitResult k = fit(synthetic_table(kuwabara_kono_truth(), six_speeds), "kuwabara-kono");
  CHECK_FALSE(k.failed);
  CHECK(k.parameter("viscous-time-constant").estimate == Approx(7.7e-5).epsilon(5e-8));
}

TEST_CASE("restitution table: a speed-independent table is the paper's law's, a falling one Kuwabara-Kono's",
          "[restitution_fit]") {
  // The paper's dashpot scales with the impact (tau = 2 zeta / omega_n(v0)), so its e does not
  // depend on the speed: the fitted model's range over the table's speeds is the model's accuracy.
  const RestitutionTable flat = synthetic_table(hongo_truth(), six_speeds);
  const FitResult h = fit(flat, "hongo");
  CHECK(h.e_effective.max - h.e_effective.min < 1e-8);
  // Kuwabara-Kono's e rises towards 1 as the speed falls: its own law fits its table far better.
  const RestitutionTable falling = synthetic_table(kuwabara_kono_truth(), six_speeds);
  CHECK(falling.e.front() - falling.e.back() > 0.05);
  const FitResult kk = fit(falling, "kuwabara-kono"), hk = fit(falling, "hongo");
  CHECK(kk.aic < hk.aic - 10);
  CHECK(hk.e_effective.max - hk.e_effective.min < 1e-8);  // hongo cannot follow it: flat at the table's mean
  CHECK(kk.e_effective.max - kk.e_effective.min > 0.05);
}

// Known e_sd: chi^2 of the true law's fit follows the chi-square distribution with n - p
// degrees of freedom (40 rows, 1 parameter: 39); chi^2 / 39 lies in [0.44, 1.85] with
// probability 0.998 (Wilson-Hilferty: 39 (1 - 2/351 +- 3.09 sqrt(2/351))^3 / 39).
TEST_CASE("restitution table: noise of known e_sd gives a reduced chi-square near 1", "[restitution_fit]") {
  const double sd = 0.005;
  for (unsigned seed : {1u, 2u, 3u}) {
    const RestitutionTable t = synthetic_table(kuwabara_kono_truth(), repeated_speeds(), sd, seed);
    const FitResult k = fit(t, "kuwabara-kono");
    CAPTURE(seed, k.reduced_chi_square);
    CHECK_FALSE(k.sigma_estimated);
    CHECK(k.reduced_chi_square > 0.44);
    CHECK(k.reduced_chi_square < 1.85);
    // The truth within 3 standard errors.
    const FittedParameter& A = k.parameter("viscous-time-constant");
    CHECK(std::abs(A.estimate - 7.7e-5) < 3 * A.standard_error);
  }
}

TEST_CASE("restitution table: cross-validation prefers the true law", "[restitution_fit]") {
  const RestitutionTable t = synthetic_table(kuwabara_kono_truth(), repeated_speeds(), 0.005, 7);
  const FitResult k = fit(t, "kuwabara-kono", true), h = fit(t, "hongo", true);
  REQUIRE(k.cross_validation);
  REQUIRE(h.cross_validation);
  CHECK(k.cross_validation->failure.empty());
  CHECK(k.cross_validation->folds == 8);
  CHECK(k.cross_validation->rms_prediction_error < h.cross_validation->rms_prediction_error);
  // The true law predicts left-out speeds to about the scatter (the e_sd): the ratio near 1.
  CHECK(k.cross_validation->ratio < 1.5);
  CHECK(h.cross_validation->ratio > 2);
}

TEST_CASE("restitution table: every law compared, ranked by AIC, the undamped law among the failures",
          "[restitution_fit]") {
  const RestitutionTable t = synthetic_table(kuwabara_kono_truth(), six_speeds, 0.005, 11);
  FitSettings s;
  const LawComparison c = compare_laws_on_restitution(t, RunOptions{}, load_paper_parameters(), s);
  REQUIRE_FALSE(c.fits.empty());
  CHECK(c.fits.front().law == "kuwabara-kono");
  for (std::size_t i = 1; i < c.fits.size(); ++i) CHECK(c.fits[i - 1].aic <= c.fits[i].aic);
  bool none_failed = false;
  for (const auto& [law, why] : c.failures) none_failed = none_failed || (law == "none" && why.find("nothing to fit") != std::string::npos);
  CHECK(none_failed);
  CHECK(c.fits.size() + c.failures.size() == registered_laws().size());
}

TEST_CASE("fit --restitution-table: JSON keys, the synthetic label, refusals with exit 2", "[restitution_fit][cli]") {
  ScratchDir dir;
  RestitutionTable t = synthetic_table(kuwabara_kono_truth(), {0.3, 0.6, 0.9, 1.2}, 0.005, 3);
  const auto file = dir.path / "kk.csv";
  write_restitution_table(file, t, "tests/test_restitution_table_fit.cpp", {});

  const auto r = run_cli("fit --restitution-table " + file.string() + " --damping kuwabara-kono --cross-validate --json");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("synthetic") != std::string::npos);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["table"]["path"] == file.string());
  CHECK(j["table"]["synthetic"] == true);
  CHECK(j["table"]["rows"] == 4);
  CHECK(j["table"].contains("source"));
  REQUIRE(j["fits"].size() == 1);
  const auto& f = j["fits"][0];
  CHECK(f["law"] == "kuwabara-kono");
  for (const char* key : {"name", "estimate", "standard_error", "lower", "upper"}) CHECK(f["parameters"][0].contains(key));
  CHECK(f["parameters"][0]["name"] == "viscous-time-constant");
  for (const char* key : {"reduced_chi_square", "aic", "bic", "warnings", "e_effective", "points", "cross_validation"})
    CHECK(f.contains(key));
  CHECK(f["e_effective"]["range"].size() == 2);
  REQUIRE(f["points"].size() == 4);
  for (const char* key : {"impact_speed_mps", "measured", "model", "residual"}) CHECK(f["points"][0].contains(key));
  CHECK(f["cross_validation"].contains("rms_prediction_error"));
  CHECK(f["cross_validation"].contains("ratio_to_scatter"));
  bool synthetic = false;
  for (const auto& w : f["warnings"]) synthetic = synthetic || w["code"] == "synthetic_table";
  CHECK(synthetic);
  CHECK(j.contains("failures"));

  // A bad file: exit 2, the file and its line named, nothing on stdout.
  const auto bad = dir.write("bad.csv", "impact_speed_m_per_s,e\n# source: x\n0.2,0.9\n0.4,1.5\n");
  const auto b = run_cli("fit --restitution-table " + bad.string());
  CHECK(b.exit_code == 2);
  CHECK(b.err.find(bad.string() + ":4:") != std::string::npos);
  CHECK(b.out.empty());

  // Meaningless combinations: refused naming both options.
  for (const std::string& extra : {std::string("--channels force_N"), std::string("--resample 1e5"),
                                   std::string("--impact-velocity 0.5"), std::string("--trace ") + file.string()}) {
    const auto x = run_cli("fit --restitution-table " + file.string() + " " + extra);
    CAPTURE(extra, x.err);
    CHECK(x.exit_code == 2);
    CHECK(x.err.find("--restitution-table") != std::string::npos);
    CHECK(x.err.find(extra.substr(0, extra.find(' '))) != std::string::npos);
    CHECK(x.out.empty());
  }
  const auto none = run_cli("fit");
  CHECK(none.exit_code == 2);
  CHECK(none.err.find("--restitution-table") != std::string::npos);
}

// A fold too small to fit does not throw the full fit away. Three rows at the speeds 0.5, 0.5,
// 3 m/s: the folds are the two distinct speeds; without 0.5 m/s one row is left for the one
// parameter (restitution), n = 1 <= p = 1, which cannot determine it. The full fit (n = 3 > 1)
// stands: exit 0 (as without --cross-validate), the fold's reason in cross_validation.failure and
// its numbers null.
TEST_CASE("fit --restitution-table --cross-validate: a fold too small is that fold's failure, not bad data",
          "[restitution_fit][cli]") {
  ScratchDir dir;
  const RestitutionTable t = synthetic_table(hongo_truth(), {0.5, 0.5, 3.0}, 0.005, 5);
  const auto file = dir.path / "three.csv";
  write_restitution_table(file, t, "tests/test_restitution_table_fit.cpp", {});
  const std::string plain = "fit --restitution-table " + file.string() + " --json";
  REQUIRE(run_cli(plain).exit_code == 0);
  const auto r = run_cli(plain + " --cross-validate");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto cv = nlohmann::json::parse(r.out)["fits"][0]["cross_validation"];
  CHECK(cv["folds"] == 2);
  const std::string why = cv["failure"];
  CHECK(why.find("the fit without speed 0.5 m/s") != std::string::npos);
  CHECK(why.find("1 rows cannot determine 1 parameters") != std::string::npos);
  CHECK(cv["rms_prediction_error"].is_null());
}

// A parameter the data cannot see is not identifiable. The undamped Hertz contact conserves
// energy, so its e is 1 at every speed whatever the ball's modulus: the residuals do not depend
// on ball-E, and its Jacobian column is only the model's rounding over the step (below
// fit_engine.cpp's difference_noise), not a derivative. Its standard error is then infinite (not
// the ~1e17 Pa that noise over s^2 gives), the fit failed and not identifiable.
TEST_CASE("restitution table: a parameter the law's e does not depend on is not identifiable", "[restitution_fit]") {
  RunOptions o;
  o.damping = "none";
  FitSettings s;
  s.parameters = parse_fit_parameters("ball-E");
  const FitResult f =
      fit_restitution_table(synthetic_table(hongo_truth(), six_speeds), o, load_paper_parameters(), s);
  CHECK(f.e_effective.max == Approx(1.0).margin(1e-9));
  CHECK(f.e_effective.min == Approx(1.0).margin(1e-9));
  CHECK(std::isinf(f.parameter("ball-E").standard_error));
  CHECK_FALSE(f.identifiable);
  CHECK(f.failed);
  CHECK(f.failure.find("no fitted parameter has a finite standard error") != std::string::npos);
}

// Laws that make the same e share a cv_rank. The laws whose coefficient follows from the input e
// and v0 at each impact make e equal to their input e at every speed: on any table each fold's
// fit is the same constant (the rest's mean), so their cv_rms agree to the model's accuracy (on
// this table without e_sd, RMS ~0.01, within the relative 1e-9 of a tie; a table with e_sd 0.005
// can put them further apart, ~1e-8, and split them) and they all share one rank;
// the one law that differs gets 1 + their number after them, or 1 before them (then they share
// rank 2: competition ranking).
TEST_CASE("fit --restitution-table --compare-laws --cross-validate: tied laws share a cv_rank",
          "[restitution_fit][cli]") {
  ScratchDir dir;
  const auto file = dir.write("flat.csv", "impact_speed_m_per_s,e\n# source: tests/test_restitution_table_fit.cpp\n"
                                           "0.2,0.81\n0.4,0.80\n0.6,0.79\n0.8,0.80\n1.0,0.78\n");
  const auto r = run_cli("fit --restitution-table " + file.string() + " --compare-laws --cross-validate");
  REQUIRE(r.exit_code == 0);
  // Rows: rank, law, AIC, dAIC, BIC, "e_min-e_max", cv_rms, cv_rank.
  std::map<std::string, int> flat_rank, other_rank;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream in(line);
    std::string rank, law, aic, daic, bic, range, cv_rms, cv_rank, extra;
    if (!(in >> rank >> law >> aic >> daic >> bic >> range >> cv_rms >> cv_rank) || (in >> extra) ||
        range.find('-') == std::string::npos || law == "law")
      continue;
    const std::size_t dash = range.find('-');
    (range.substr(0, dash) == range.substr(dash + 1) ? flat_rank : other_rank)[law] = std::stoi(cv_rank);
  }
  CAPTURE(r.out);
  REQUIRE(flat_rank.size() >= 2);
  REQUIRE(other_rank.count("kuwabara-kono") == 1);
  const int tied = static_cast<int>(flat_rank.size()), kk = other_rank["kuwabara-kono"];
  const int shared = kk == 1 ? 2 : 1;  // kuwabara-kono first (noise made a trend) or after them
  if (kk != 1) CHECK(kk == tied + 1);
  for (const auto& [law, rank] : flat_rank) CHECK(rank == shared);
}

// Issue 45: a table of 1,000 speeds cross-validated took 224 s without a word, 1e5 rows compared
// over every law gave no answer. The prediction (restitution_fit.cpp: 17 units a contact, 10
// iterations of 2 p + 2 evaluations of every distinct speed, one fit per fold, 15 laws): 1,000
// speeds, p = 1, left out one by one: 17 x 1000 x 40 x 1001 = 6.8e8; 1e5 speeds, every law:
// 17 x 1e5 x 40 x 15 = 1.0e9; both above 6e7 and refused at once (exit 2, the file named, nothing
// on stdout). The same table fitted once (6.8e5) runs.
TEST_CASE("fit --restitution-table: a request predicted beyond its work bound is refused before it runs",
          "[restitution_fit][cli]") {
  const hertzdash::test::ScratchDir dir;
  auto table = [&](const std::string& name, int rows) {
    std::ostringstream text;
    text << "impact_speed_m_per_s,e,e_sd\n# source: SYNTHETIC, tests/test_restitution_table_fit.cpp\n";
    for (int i = 0; i < rows; ++i) text << 0.2 + 2.0 * i / rows << "," << 0.8 - 0.01 * (i % 3) << ",0.01\n";
    return dir.write(name, text.str()).string();
  };
  const std::string thousand = table("thousand.csv", 1000), huge = table("huge.csv", 100000);
  for (const std::string& args : {"--restitution-table " + thousand + " --cross-validate",
                                  "--restitution-table " + huge + " --compare-laws"}) {
    const auto r = hertzdash::test::run_cli("fit " + args);
    CAPTURE(args, r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find("above the 6e+07 (about a minute) a fit may take") != std::string::npos);
    CHECK(r.out.empty());
  }
  const auto once = hertzdash::test::run_cli("fit --restitution-table " + thousand + " --json");
  CHECK(once.exit_code == 0);
}

// Issue 45: six identical rows (speed 0.5 m/s, e 0.78, e_sd 0.01) gave a standard error of 3e-15,
// `identifiable`, and a profile interval [nan, nan]: the reduced chi-square (4e-25: the law fits
// the one value exactly) scaled the stated e_sd away. The scale is now max(1, chi^2 / (n - p)), so
// with sd known the standard error is the stated one propagated: sigma_e = 0.01 / sqrt(6) in the
// table's e, over de_eff/de_in at 0.5 m/s in the input e (by central differences of the truth's
// runs, step 1e-4: error O(1e-8) relative). A model linear over one standard error (4e-3 in e:
// the curvature of e_eff(e_in) moves it by far under 1 %) gives a profile interval of estimate
// +- standard error; 5 % allows the Jacobian's central differences and Brent's tolerance.
TEST_CASE("restitution table: identical rows keep their stated e_sd, and their profile interval is finite",
          "[restitution_fit]") {
  RestitutionTable t;
  t.path = "identical.csv";
  t.source = "SYNTHETIC: tests/test_restitution_table_fit.cpp";
  t.impact_speed_mps.assign(6, 0.5);
  t.e.assign(6, 0.78);
  t.e_sd.assign(6, 0.01);
  RunOptions o;
  FitSettings s;
  s.profile_intervals = true;
  const FitResult f = fit_restitution_table(t, o, load_paper_parameters(), s);
  REQUIRE_FALSE(f.failed);
  const FittedParameter& e = f.parameter("restitution");
  RunOptions above = o, below = o;
  above.restitution = e.estimate + 1e-4, below.restitution = e.estimate - 1e-4;
  const double slope = (test::restitution_at_speeds(above, {0.5})[0] - test::restitution_at_speeds(below, {0.5})[0]) / 2e-4;
  CAPTURE(e.estimate, e.standard_error, slope, f.reduced_chi_square);
  CHECK(f.reduced_chi_square < 1e-6);
  CHECK(e.standard_error == Approx(0.01 / std::sqrt(6.0) / slope).epsilon(0.01));
  REQUIRE(e.profile);
  CHECK(e.profile->lower == Approx(e.estimate - e.standard_error).epsilon(0.05 * e.standard_error / e.estimate));
  CHECK(e.profile->upper == Approx(e.estimate + e.standard_error).epsilon(0.05 * e.standard_error / e.estimate));
}
