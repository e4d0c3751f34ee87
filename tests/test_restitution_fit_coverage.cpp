// Coverage of the 1-sigma intervals of `fit --restitution-table` (simulation/fit/restitution_fit.hpp)
// over many SYNTHETIC tables: a known law and parameter (the paper's law `hongo` at input e =
// 0.80; `kuwabara-kono` at A = 7.7e-5 s, both on the steel rod's set-up), its e_effective at
// eight speeds computed once (run_restitution, CVODE at rtol 1e-12: another integrator than the
// fit's gbs8), plus Gaussian noise of known e_sd drawn with a seeded generator, 500 draws per case.
// Each table is fitted and we count how often estimate +- standard_error contains the truth.
//
// Expected fraction. Without e_sd the fits scale the covariance by s^2 = chi^2 / (n - p)
// (restitution_fit.hpp, "Residuals and uncertainty"). For a model linear in its parameter with
// Gaussian noise (the fitted models are very nearly so over a standard error: the standard error
// is a few percent of the parameter at most here), (estimate - truth) / standard_error then
// follows Student's t with n - p = 8 - 1 = 7 degrees of freedom, so the interval covers the truth
// with probability P_t = P(|T_7| <= 1) = 0.6494 (gsl_cdf_tdist_P), not 0.683: the price of
// estimating the scale from seven degrees of freedom. With e_sd the scale is max(1, chi^2 / 7)
// (fit_engine.hpp: the stated scatter is inflated, never deflated), and chi^2 ~ chi^2_7 is
// independent of the estimate, whose error is sigma Z with the stated sigma: the interval covers
// the truth with probability P_sd = E[P(|Z| <= max(1, sqrt(chi^2_7 / 7)))] = F_7(7) (2 Phi(1) - 1)
// + int_7^inf (2 Phi(sqrt(q / 7)) - 1) f_7(q) dq = 0.7187 (the integral by the midpoint rule
// below, 2e5 points on [7, 200]: its error is far below 1e-6, the tail beyond 200 about 1e-39).
//
// Tolerance. The count of covering intervals over N independent draws is binomial(N, P): its
// fraction has standard deviation sqrt(P (1 - P) / N), about 0.021 for N = 500; the pool of all
// four cases (1000 draws at each P, each case with its own seeds, so independent) has mean
// (P_sd + P_t) / 2 and standard deviation sqrt(1000 (P_sd (1 - P_sd) + P_t (1 - P_t))) / 2000,
// about 0.010. Each case must lie within 3 of its standard deviations of its P, and so must the
// pool (a correct fit fails one of these five checks with probability about 5 x 0.0027).
// The with-e_sd cases draw each row's noise with its own e_sd (0.005 to 0.02, so the weights
// matter); the without-e_sd cases with one common sd = 0.01, the model the fit then assumes.
//
// Run time: 2000 fits of 8 speeds, about 6 s of CPU (a fit of one parameter takes a few
// iterations of 3 x 8 gbs8 impacts).
#include "restitution_at_speeds.hpp"
#include "hertzdash/io/restitution_table.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <catch2/catch.hpp>
#include <gsl/gsl_cdf.h>
#include <gsl/gsl_randist.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace hertzdash;

namespace {

constexpr int draws = 500;
const std::vector<double> speeds{0.15, 0.30, 0.45, 0.60, 0.75, 0.90, 1.05, 1.20};

struct Truth {
  RunOptions options;
  std::string parameter;
  double value;
};

Truth hongo_truth() {
  RunOptions o;
  o.restitution = 0.80;
  return {o, "restitution", 0.80};
}

Truth kuwabara_kono_truth() {
  RunOptions o;
  o.damping = "kuwabara-kono";
  o.viscous_time_constant_s = 7.7e-5;
  return {o, "viscous-time-constant", 7.7e-5};
}

// The per-row e_sd of the weighted cases: 0.005 to 0.02.
double row_sd(std::size_t i) { return 0.005 + 0.015 * static_cast<double>(i) / static_cast<double>(speeds.size() - 1); }

RestitutionTable noisy_table(const std::vector<double>& e_true, bool with_sd, unsigned seed) {
  RestitutionTable t;
  t.path = "synthetic.csv";
  t.source = "SYNTHETIC: tests/test_restitution_fit_coverage.cpp";
  t.synthetic = true;
  t.impact_speed_mps = speeds;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const double sd = with_sd ? row_sd(i) : 0.01;
    t.e.push_back(e_true[i] + sd * unit(rng));
    if (with_sd) t.e_sd.push_back(sd);
  }
  return t;
}

// The draws whose 1-sigma interval contains the truth: the law's parameter's, and the physical
// e's (FitResult::e_effective, the fitted model's mean e over the table's speeds, whose truth is
// the mean of e_true). With one parameter e_effective is a smooth monotone function of it, so
// its delta-method interval covers the truth as often, to first order in the error.
struct Covered {
  int parameter = 0, e_effective = 0;
};
Covered covered(const Truth& truth, bool with_sd, unsigned first_seed) {
  const PaperParameters paper = load_paper_parameters();
  const std::vector<double> e_true = test::restitution_at_speeds(truth.options, speeds);
  double e_effective_true = 0;
  for (double e : e_true) e_effective_true += e / static_cast<double>(e_true.size());
  RunOptions base;
  base.damping = truth.options.damping;
  Covered inside;
  for (int d = 0; d < draws; ++d) {
    const FitResult f = fit_restitution_table(noisy_table(e_true, with_sd, first_seed + d), base, paper, {});
    REQUIRE_FALSE(f.failed);
    CHECK(f.sigma_estimated == !with_sd);
    const FittedParameter& p = f.parameter(truth.parameter);
    inside.parameter += std::abs(p.estimate - truth.value) <= p.standard_error;
    inside.e_effective += std::abs(f.e_effective.value - e_effective_true) <= f.e_effective.standard_error;
  }
  return inside;
}

}  // namespace

// P_sd above: the coverage of estimate +- standard error with the scale max(1, chi^2_7 / 7).
double coverage_with_stated_sd(int dof) {
  const double k = dof, below = gsl_cdf_chisq_P(k, k) * (2 * gsl_cdf_ugaussian_P(1.0) - 1);
  constexpr int points = 200000;
  const double lo = k, hi = 200, h = (hi - lo) / points;
  double above = 0;
  for (int i = 0; i < points; ++i) {
    const double q = lo + (i + 0.5) * h;
    above += (2 * gsl_cdf_ugaussian_P(std::sqrt(q / k)) - 1) * gsl_ran_chisq_pdf(q, k) * h;
  }
  return below + above;
}

TEST_CASE("restitution table fits: the 1-sigma intervals cover the truth as often as Student's t says",
          "[restitution_fit][coverage]") {
  const int dof = static_cast<int>(speeds.size()) - 1;
  const double P_t = 2 * gsl_cdf_tdist_P(1.0, dof) - 1, P_sd = coverage_with_stated_sd(dof);
  REQUIRE(P_t == Approx(0.6494).margin(1e-4));
  REQUIRE(P_sd == Approx(0.7187).margin(1e-4));
  auto sd = [](double P) { return std::sqrt(P * (1 - P) / draws); };
  const Covered hs = covered(hongo_truth(), true, 1000), he = covered(hongo_truth(), false, 2000);
  const Covered ks = covered(kuwabara_kono_truth(), true, 3000), ke = covered(kuwabara_kono_truth(), false, 4000);
  const int h_sd = hs.parameter, h_est = he.parameter, k_sd = ks.parameter, k_est = ke.parameter;
  CAPTURE(h_sd, h_est, k_sd, k_est, draws, P_t, P_sd);
  CAPTURE(hs.e_effective, he.e_effective, ks.e_effective, ke.e_effective);
  for (int c : {h_sd, k_sd, hs.e_effective, ks.e_effective}) CHECK(std::abs(static_cast<double>(c) / draws - P_sd) <= 3 * sd(P_sd));
  for (int c : {h_est, k_est, he.e_effective, ke.e_effective}) CHECK(std::abs(static_cast<double>(c) / draws - P_t) <= 3 * sd(P_t));
  const double pooled = static_cast<double>(h_sd + h_est + k_sd + k_est) / (4 * draws);
  const double pooled_sd = std::sqrt(2.0 * draws * (P_sd * (1 - P_sd) + P_t * (1 - P_t))) / (4.0 * draws);
  CAPTURE(pooled);
  CHECK(std::abs(pooled - (P_sd + P_t) / 2) <= 3 * pooled_sd);
}
