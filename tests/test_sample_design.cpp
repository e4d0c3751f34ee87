// Input distributions (quantile functions) and unit-cube designs of the sweep and uncertainty
// studies, against closed forms and the defining properties of each design.
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/uncertainty/input_distribution.hpp"
#include "hertzdash/simulation/uncertainty/sample_design.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace hertzdash;

TEST_CASE("Distribution quantiles equal their closed forms", "[sample]") {
  // Uniform: F^-1(u) = min + u (max - min), exact in floating point for u = 1/4.
  CHECK(uniform_distribution(2.0, 6.0).quantile(0.25) == 3.0);
  // Normal: Phi^-1(0.975) = 1.959963984540054 (Abramowitz & Stegun 26.2; to 16 digits).
  CHECK(normal_distribution(0.83, 0.003).quantile(0.975) == Approx(0.83 + 0.003 * 1.959963984540054).epsilon(1e-14));
  CHECK(normal_distribution(5.0, 2.0).quantile(0.5) == Approx(5.0).margin(1e-14));
  // Lognormal: median exp(log_mean); the 97.5 % point exp(mu + 1.95996 sigma).
  const auto ln = lognormal_distribution(std::log(2e9), 0.2);
  CHECK(ln.quantile(0.5) == Approx(2e9).epsilon(1e-14));
  CHECK(ln.quantile(0.975) == Approx(2e9 * std::exp(0.2 * 1.959963984540054)).epsilon(1e-13));
}

TEST_CASE("Truncated distributions keep their bounds and their shape", "[sample]") {
  // A normal truncated symmetrically about its mean keeps its median at the mean.
  const auto sym = normal_distribution(1.0, 0.5, 0.2, 1.8);
  CHECK(sym.quantile(0.5) == Approx(1.0).margin(1e-14));
  for (double u : {1e-12, 0.01, 0.3, 0.99, 1 - 1e-12}) {
    CHECK(sym.quantile(u) >= 0.2);
    CHECK(sym.quantile(u) <= 1.8);
  }
  // Truncated to [a, 1.0] (a = -0.2 sd) the lower end is reached as u -> 0: F^-1(F(a)) = a.
  CHECK(normal_distribution(0.0, 1.0, -0.2, 1.0).quantile(0.0) == Approx(-0.2).epsilon(1e-14));
  // Deep in the upper tail: the median of N(0, 1) truncated to [8, inf) solves Q(x) = Q(8)/2.
  // With x = 8 + d and Q(x) ~ phi(x)/x: 8 d + d^2/2 + ln(1 + d/8) = ln 2, d = 0.0849; solved
  // to 30 digits with mpmath's erfc: x = 8.084911007391544. Without the upper-tail form
  // 1 - F(8) = 6.2e-16 keeps one digit and the quantile would be off by percent.
  const double m = normal_distribution(0.0, 1.0, 8.0).quantile(0.5);
  CHECK(m == Approx(8.084911007391544).epsilon(1e-10));
  // Lognormal truncated to [1, 3] around median 2: stays inside, median within.
  const auto lt = lognormal_distribution(std::log(2.0), 0.5, 1.0, 3.0);
  CHECK(lt.quantile(1e-9) >= 1.0);
  CHECK(lt.quantile(1 - 1e-9) <= 3.0);
}

TEST_CASE("Bad distributions are refused naming the parameter", "[sample]") {
  auto message = [](const InputDistribution& d) {
    try {
      validate(d, "ball-E");
    } catch (const InvalidParameter& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  CHECK(message(uniform_distribution(2.0, 1.0)).find("ball-E.max") != std::string::npos);
  CHECK(message(normal_distribution(1.0, -1.0)).find("ball-E.sd") != std::string::npos);
  CHECK(message(normal_distribution(NAN, 1.0)).find("ball-E.mean") != std::string::npos);
  CHECK(message(lognormal_distribution(0.0, 0.0)).find("ball-E.log_sd") != std::string::npos);
  CHECK(message(lognormal_distribution(0.0, 1.0, -1.0)).find("ball-E.min") != std::string::npos);
  // 40 sd above the mean no double holds any probability.
  CHECK(message(normal_distribution(0.0, 1.0, 40.0, 41.0)).find("probability") != std::string::npos);
  CHECK(message(normal_distribution(0.0, 1.0, 1.0, 1.0)).find("ball-E.max") != std::string::npos);
  CHECK(message(normal_distribution(0.0, 1.0, 1.0, 2.0)) == "accepted");
  CHECK_THROWS_AS(parse_distribution_kind("gaussian", "x"), InvalidParameter);
  CHECK_THROWS_AS(parse_sample_method("halton", "sample.method"), InvalidParameter);
}

TEST_CASE("A Latin hypercube puts one point in each stratum of every coordinate", "[sample]") {
  const std::size_t n = 97, d = 5;
  const std::vector<double> u = unit_sample(SampleMethod::latin_hypercube, n, d, 7);
  REQUIRE(u.size() == n * d);
  for (std::size_t j = 0; j < d; ++j) {
    std::vector<int> hits(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      const double v = u[i * d + j];
      REQUIRE(v > 0.0);
      REQUIRE(v < 1.0);
      ++hits[static_cast<std::size_t>(v * static_cast<double>(n))];
    }
    for (int h : hits) CHECK(h == 1);
  }
  // The same seed gives the same design; another seed another one.
  CHECK(unit_sample(SampleMethod::latin_hypercube, n, d, 7) == u);
  CHECK(unit_sample(SampleMethod::latin_hypercube, n, d, 8) != u);
}

TEST_CASE("Monte Carlo points are uniform: sample mean within 4 standard errors", "[sample]") {
  // Mean of n uniforms: 1/2 with standard error 1/sqrt(12 n) = 9.1e-4 for n = 1e5; the seed is
  // fixed, so this is deterministic, and a correct generator passes with probability 1 - 6e-5.
  const std::size_t n = 100000;
  const std::vector<double> u = unit_sample(SampleMethod::monte_carlo, n, 2, 42);
  for (std::size_t j = 0; j < 2; ++j) {
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) sum += u[i * 2 + j];
    CHECK(std::abs(sum / static_cast<double>(n) - 0.5) < 4.0 / std::sqrt(12.0 * static_cast<double>(n)));
  }
  CHECK(unit_sample(SampleMethod::monte_carlo, 10, 2, 1) != unit_sample(SampleMethod::monte_carlo, 10, 2, 2));
}

TEST_CASE("Sobol points are a (0, m, 1)-net in each coordinate and integrate smooth functions at O(1/n)", "[sample]") {
  // With the zero point the first 2^m Sobol points put exactly one point in each interval
  // [k/2^m, (k+1)/2^m) of every coordinate; GSL starts after the zero point, so its first
  // 2^m - 1 points fill every interval but the first.
  const std::size_t m = 10, n = (std::size_t{1} << m) - 1, d = 6;
  const std::vector<double> u = unit_sample(SampleMethod::sobol, n, d, 0);
  for (std::size_t j = 0; j < d; ++j) {
    std::vector<int> hits(n + 1, 0);
    for (std::size_t i = 0; i < n; ++i) ++hits[static_cast<std::size_t>(u[i * d + j] * static_cast<double>(n + 1))];
    CHECK(hits[0] == 0);
    for (std::size_t k = 1; k <= n; ++k) CHECK(hits[k] == 1);
  }
  // E[u_1 u_2 ... u_6] = 2^-6 over 2^14 points (the zero point, missing, adds 0 to the sum).
  // Monte Carlo's standard error is sqrt((3^-6 - 4^-6) / n) = 2.6e-4 at this n; a quasi-Monte
  // Carlo rule converges as (log n)^d / n and must do at least 10 times better.
  const std::size_t big = (std::size_t{1} << 14) - 1;
  const std::vector<double> w = unit_sample(SampleMethod::sobol, big, d, 0);
  double sum = 0;
  for (std::size_t i = 0; i < big; ++i) {
    double p = 1;
    for (std::size_t j = 0; j < d; ++j) p *= w[i * d + j];
    sum += p;
  }
  CHECK(std::abs(sum / static_cast<double>(big + 1) - 1.0 / 64.0) < 2.6e-5);
  CHECK_THROWS_AS(unit_sample(SampleMethod::sobol, 4, max_sobol_dimension + 1, 0), InvalidParameter);
  CHECK_THROWS_AS(unit_sample(SampleMethod::monte_carlo, 4, 0, 0), InvalidParameter);
}
