// Profile-likelihood intervals (simulation/fit/profile_interval.hpp) on least-squares problems
// whose profiles are known in closed form, and on a restitution table whose estimate lies near
// the bound of its range (simulation/fit/restitution_fit.hpp, "Profile intervals").
#include "cli_runner.hpp"
#include "profile_interval_checks.hpp"
#include "restitution_at_speeds.hpp"
#include "scratch_dir.hpp"
#include "hertzdash/io/restitution_table.hpp"
#include "hertzdash/simulation/fit/profile_interval.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <random>
#include <vector>

using namespace hertzdash;
using hertzdash::test::check_nearly_wald_interval;
using hertzdash::test::run_cli;
using hertzdash::test::ScratchDir;

namespace {

double identity(double z) { return z; }

}  // namespace

// A straight line y = a + b x (x = 0..9) with Gaussian noise, the intercept a profiled (b
// re-optimised in closed form). RSS(a, b) = RSS_min + (t - t^)^T X^T X (t - t^), t = (a, b);
// minimising over b leaves the Schur complement, RSS_a(a) = RSS_min + (a - a^)^2 / C_aa with
// C = (X^T X)^-1. So RSS_a - RSS_min = s^2 at a = a^ +- s sqrt(C_aa) = a^ +- the standard
// error: the profile interval is the Wald interval. Brent stops within 1e-3 standard errors.
TEST_CASE("profile interval: a model linear in its parameters gets estimate +- standard error", "[profile_interval]") {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> noise(0.0, 0.3);
  std::vector<double> x, y;
  for (int i = 0; i < 10; ++i) x.push_back(i), y.push_back(1.5 + 0.7 * i + noise(rng));
  const double n = static_cast<double>(x.size());
  double sx = 0, sxx = 0, sy = 0, sxy = 0;
  for (std::size_t i = 0; i < x.size(); ++i) sx += x[i], sxx += x[i] * x[i], sy += y[i], sxy += x[i] * y[i];
  const double det = n * sxx - sx * sx;
  const double b_hat = (n * sxy - sx * sy) / det, a_hat = (sy - b_hat * sx) / n;
  auto rss = [&](double a, double b) {
    double r = 0;
    for (std::size_t i = 0; i < x.size(); ++i) r += (y[i] - a - b * x[i]) * (y[i] - a - b * x[i]);
    return r;
  };
  const double rss_min = rss(a_hat, b_hat), s2 = rss_min / (n - 2);
  const double C_aa = sxx / det, se_a = std::sqrt(s2 * C_aa);
  auto rise = [&](double a) -> std::optional<double> {
    double num = 0;  // b*(a) = sum x (y - a) / sum x^2
    for (std::size_t i = 0; i < x.size(); ++i) num += x[i] * (y[i] - a);
    return rss(a, num / sxx) - rss_min;
  };
  const ProfileInterval pi = profile_interval(rise, s2, a_hat, se_a, identity);
  CHECK(pi.failure.empty());
  CHECK_FALSE(pi.lower_open);
  CHECK_FALSE(pi.upper_open);
  CHECK(pi.lower == Approx(a_hat - se_a).margin(1e-3 * se_a));
  CHECK(pi.upper == Approx(a_hat + se_a).margin(1e-3 * se_a));
}

// Observations y_i = c + noise (sigma known, n = 10) of a parameter theta = tanh(c) in (-1, 1): the
// data are linear in the unbounded variable c, the parameter saturates. With sigma known the rise
// is chi^2 - chi^2_min = n (c - c^)^2 / sigma^2 and the threshold 1 (Venzon and Moolgavkar), so
// the profile interval is exactly [tanh(c^ - se_c), tanh(c^ + se_c)], se_c = sigma / sqrt(n),
// asymmetric about theta^ = tanh(c^); it covers the truth exactly when c^ +- se_c covers c, with
// probability 0.683 (c^ is Gaussian). The Wald interval theta^ +- se_c (1 - theta^2) (the delta
// method) is narrower than the profile's wherever tanh flattens away from c^, so at se_c = 1 and
// truth c = 0 it covers P(|tanh Z| <= sech^2 Z) = P(|Z| <= asinh(2) / 2 = 0.7218) = 0.530 (Z
// standard normal; sinh(2Z) = 2 at the crossing). Over 400 draws the binomial standard deviation of a fraction near
// 0.683 is sqrt(0.683 0.317 / 400) = 0.023, so the profile's is checked within 3 of it of 0.683
// and the Wald interval's 3 of them below (it is 0.153 below, 6.6 of them).
TEST_CASE("profile interval: a saturating parameter, profile covers at 0.683 where Wald does not",
          "[profile_interval][coverage]") {
  const int n = 10, draws = 400;
  const double sigma = std::sqrt(static_cast<double>(n)), se_c = sigma / std::sqrt(static_cast<double>(n));
  std::mt19937_64 rng(17);
  std::normal_distribution<double> noise(0.0, sigma);
  int profile_inside = 0, wald_inside = 0;
  double asymmetry = 0;
  for (int d = 0; d < draws; ++d) {
    std::vector<double> y;
    double c_hat = 0;
    for (int i = 0; i < n; ++i) y.push_back(noise(rng)), c_hat += y.back() / n;
    auto chi2 = [&](double c) {
      double r = 0;
      for (double v : y) r += (v - c) * (v - c) / (sigma * sigma);
      return r;
    };
    const double chi2_min = chi2(c_hat);
    const ProfileInterval pi = profile_interval([&](double c) -> std::optional<double> { return chi2(c) - chi2_min; },
                                                1.0, c_hat, se_c, [](double c) { return std::tanh(c); });
    REQUIRE(pi.failure.empty());
    CHECK(pi.lower == Approx(std::tanh(c_hat - se_c)).margin(2e-3 * se_c));
    CHECK(pi.upper == Approx(std::tanh(c_hat + se_c)).margin(2e-3 * se_c));
    const double theta = std::tanh(c_hat), se_theta = se_c * (1 - theta * theta);
    profile_inside += pi.lower <= 0 && 0 <= pi.upper;
    wald_inside += std::abs(theta) <= se_theta;
    asymmetry = std::max(asymmetry, std::abs((pi.upper - theta) - (theta - pi.lower)) / se_theta);
  }
  const double binomial = std::sqrt(0.683 * 0.317 / draws);
  const double profile = static_cast<double>(profile_inside) / draws, wald = static_cast<double>(wald_inside) / draws;
  CAPTURE(profile, wald, binomial);
  CHECK(std::abs(profile - 0.683) <= 3 * binomial);
  CHECK(wald < 0.683 - 3 * binomial);
  CHECK(asymmetry > 0.1);  // the ends are not estimate +- anything
}

// A side where the profile never rises by the threshold is open, ending at the bound; one where
// it cannot be evaluated has no end and says why.
TEST_CASE("profile interval: a flat side is open at the bound, an unevaluable one says so", "[profile_interval]") {
  // rise = (z - 0)^2 for z < 0, 0 above: open upwards; the parameter logistic in z, bound 1.
  auto half = [](double z) -> std::optional<double> { return z < 0 ? z * z : 0.0; };
  auto logistic = [](double z) { return 1.0 / (1.0 + std::exp(-z)); };
  const ProfileInterval open = profile_interval(half, 1.0, 0.0, 1.0, logistic);
  CHECK(open.lower == Approx(logistic(-1.0)).margin(1e-3));
  CHECK(open.upper_open);
  CHECK(open.upper == 1.0);
  const ProfileInterval broken =
      profile_interval([](double z) -> std::optional<double> { if (z > 0.5) return std::nullopt; return z * z; }, 1.0,
                       0.0, 1.0, identity);
  CHECK(broken.lower == Approx(-1.0).margin(1e-3));
  CHECK(std::isnan(broken.upper));
  CHECK_FALSE(broken.failure.empty());
}

namespace {

const std::vector<double> eight_speeds{0.15, 0.30, 0.45, 0.60, 0.75, 0.90, 1.05, 1.20};

// e_effective of Kuwabara-Kono at time constant A at each speed, as `hertzdash restitution
// --damping kuwabara-kono --viscous-time-constant A --impact-velocity v --rtol 1e-12` (CVODE:
// another integrator than the fit's gbs8).
std::vector<double> kuwabara_kono_e(double A_s) {
  RunOptions o;
  o.damping = "kuwabara-kono";
  o.viscous_time_constant_s = A_s;
  return test::restitution_at_speeds(o, eight_speeds);
}

// SYNTHETIC: Kuwabara-Kono at A = 7.7e-5 s, Gaussian noise of sd 0.004 (seed 3), no e_sd.
RestitutionTable noisy_kuwabara_kono_table() {
  RestitutionTable t;
  t.path = "synthetic.csv";
  t.source = "SYNTHETIC: tests/test_profile_interval.cpp";
  t.synthetic = true;
  t.impact_speed_mps = eight_speeds;
  t.e = kuwabara_kono_e(7.7e-5);
  std::mt19937_64 rng(3);
  std::normal_distribution<double> noise(0.0, 0.004);
  for (double& e : t.e) e += noise(rng);
  return t;
}

double rss(const RestitutionTable& t, const std::vector<double>& model) {
  double r = 0;
  for (std::size_t i = 0; i < t.rows(); ++i) r += (t.e[i] - model[i]) * (t.e[i] - model[i]);
  return r;
}

}  // namespace

// The defining property, checked independently: at each end of A's profile interval the RSS of
// the table against CVODE's e_effective (not the fit's gbs8 model) exceeds the fit's minimum by
// s^2 = RSS_min / (n - 1). Error budget: Brent stops within 1e-3 se_z of the crossing, where the
// rise has slope 2 s^2 / se_z, so the rise errs by at most 2e-3 s^2; the two integrators' e agree
// to ~1e-10 (test_restitution_table_fit.cpp), an RSS error of ~2 sum|r| 1e-10 = 1e-11, below 1e-6
// of s^2 (~2e-5). Checked to 5e-3 s^2. Over one standard error the model is nearly linear in A
// (the standard error is 0.9 % of A), so the ends are the Wald ends to within a few percent of
// the standard error (the quadratic term's share: of order se / A); checked to 5 %.
TEST_CASE("restitution table: the profile interval's ends are where the RSS rises by s^2", "[profile_interval]") {
  const RestitutionTable t = noisy_kuwabara_kono_table();
  RunOptions base;
  base.damping = "kuwabara-kono";
  FitSettings s;
  s.profile_intervals = true;
  const FitResult f = fit_restitution_table(t, base, load_paper_parameters(), s);
  REQUIRE_FALSE(f.failed);
  const FittedParameter& A = f.parameter("viscous-time-constant");
  check_nearly_wald_interval(A, 0.05);
  const double s2 = f.chi_square / static_cast<double>(f.n - 1);
  for (double end : {A.profile->lower, A.profile->upper}) {
    CAPTURE(end, A.estimate, A.standard_error);
    CHECK((rss(t, kuwabara_kono_e(end)) - f.chi_square) / s2 == Approx(1.0).margin(5e-3));
  }
}

TEST_CASE("fit --restitution-table --profile-intervals: the JSON's profile_interval and the text's line",
          "[profile_interval][cli]") {
  ScratchDir dir;
  const auto file = dir.path / "kk.csv";
  write_restitution_table(file, noisy_kuwabara_kono_table(), "tests/test_profile_interval.cpp", {});
  const auto r = run_cli("fit --restitution-table " + file.string() + " --damping kuwabara-kono --profile-intervals --json");
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto& p = j["fits"][0]["parameters"][0];
  REQUIRE(p.contains("profile_interval"));
  CHECK(p["profile_interval"].size() == 2);
  CHECK(p["profile_interval"][0].get<double>() < p["estimate"].get<double>());
  CHECK(p["profile_interval"][1].get<double>() > p["estimate"].get<double>());
  CHECK(p["profile_interval_open"] == nlohmann::json::array({false, false}));
  const auto plain = run_cli("fit --restitution-table " + file.string() + " --damping kuwabara-kono --json");
  CHECK_FALSE(nlohmann::json::parse(plain.out)["fits"][0]["parameters"][0].contains("profile_interval"));
  const auto text = run_cli("fit --restitution-table " + file.string() + " --damping kuwabara-kono --profile-intervals");
  CHECK(text.out.find("profile interval (1 sigma)") != std::string::npos);
  CHECK(text.out.find("speed_mps") != std::string::npos);  // the table of points follows
}

// A trace's fit (trace_fit.hpp, "Profile intervals"): a SYNTHETIC force-only trace sampled at
// 10 kHz, about 13 samples per contact, near the least rate the fit accepts. Each fitted
// parameter gets an interval around its estimate, the onset none; over one standard error
// (about 1 % of E and of e here) the model is nearly linear, so the ends lie within 10 % of a
// standard error of estimate +- standard error (the quadratic term's share, of order the
// relative standard error, well inside).
TEST_CASE("fit --trace --profile-intervals: intervals for the fitted parameters, not the onset",
          "[profile_interval][cli]") {
  ScratchDir dir;
  const auto trace = dir.path / "low.csv";
  REQUIRE(run_cli("simulate --ball-E 1.7e9 --restitution 0.80 --integrator rk4 --dt 2e-7 --trace " + trace.string() +
                  " --trace-format measured --noise 0.01 --sample-rate 1e4 --channels force_N --seed 3")
              .exit_code == 0);
  const auto r = run_cli("fit --trace " + trace.string() + " --profile-intervals --json");
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  const auto& parameters = j["fits"][0]["parameters"];
  REQUIRE(parameters.size() == 3);
  for (int i = 0; i < 2; ++i) {
    const auto& p = parameters[i];
    CAPTURE(p.dump());
    REQUIRE(p.contains("profile_interval"));
    const double est = p["estimate"], se = p["standard_error"];
    CHECK(p["profile_interval"][0].get<double>() == Approx(est - se).margin(0.1 * se));
    CHECK(p["profile_interval"][1].get<double>() == Approx(est + se).margin(0.1 * se));
  }
  CHECK(parameters[2]["name"] == "onset-time");
  CHECK_FALSE(parameters[2].contains("profile_interval"));
}
