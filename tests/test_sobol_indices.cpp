// The Sobol index estimators (validation/common/sobol_indices.hpp) on functions whose indices are
// known in closed form: the Ishigami function and a linear additive function; the design's
// layout; the sample quantile they use for their intervals.
#include "hertzdash/simulation/uncertainty/input_distribution.hpp"
#include "hertzdash/simulation/uncertainty/sample_quantile.hpp"
#include "validation/common/sobol_indices.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

using namespace hertzdash;

namespace {

constexpr double pi = std::numbers::pi;

// Ishigami & Homma (1990): f = sin x1 + a sin^2 x2 + b x3^4 sin x1, x_i ~ U(-pi, pi).
// With E[sin^2] = 1/2, E[sin^4] = 3/8, E[x^4] = pi^4/5, E[x^8] = pi^8/9 for x ~ U(-pi, pi):
//   V1 = Var(sin x1 (1 + b E[x3^4]))  = (1 + b pi^4/5)^2 / 2
//   V2 = a^2 Var(sin^2 x2)            = a^2 (3/8 - 1/4) = a^2/8
//   V3 = 0                            (E[y | x3] does not depend on x3: E[sin x1] = 0)
//   V13 = b^2 Var(x3^4) E[sin^2 x1]   = b^2 (pi^8/9 - pi^8/25)/2 = 8 b^2 pi^8/225
//   V = V1 + V2 + V13 = a^2/8 + b pi^4/5 + b^2 pi^8/18 + 1/2
// and ST1 = (V1 + V13)/V, ST2 = V2/V, ST3 = V13/V. For a = 7, b = 0.1:
//   S = (0.3139, 0.4424, 0), ST = (0.5576, 0.4424, 0.2437).
constexpr double ishigami_a = 7, ishigami_b = 0.1;
double ishigami(const double* x) {
  return std::sin(x[0]) + ishigami_a * std::sin(x[1]) * std::sin(x[1]) +
         ishigami_b * std::pow(x[2], 4) * std::sin(x[0]);
}
struct Exact {
  std::array<double, 3> first, total;
};
Exact ishigami_exact() {
  const double a = ishigami_a, b = ishigami_b, pi4 = std::pow(pi, 4), pi8 = std::pow(pi, 8);
  const double V1 = 0.5 * (1 + b * pi4 / 5) * (1 + b * pi4 / 5), V2 = a * a / 8, V13 = 8 * b * b * pi8 / 225;
  const double V = a * a / 8 + b * pi4 / 5 + b * b * pi8 / 18 + 0.5;
  return {{V1 / V, V2 / V, 0.0}, {(V1 + V13) / V, V2 / V, V13 / V}};
}

// The model run on every row of the Saltelli design, its inputs mapped from the unit cube.
template <class F>
SobolIndices indices_of(F f, const std::vector<InputDistribution>& inputs, std::size_t n, const SobolOptions& options = {}) {
  const std::size_t d = inputs.size();
  const std::vector<double> u = saltelli_unit_points(SampleMethod::sobol, n, d, 0);
  std::vector<double> y(n * (d + 2)), x(d);
  for (std::size_t r = 0; r < y.size(); ++r) {
    for (std::size_t k = 0; k < d; ++k) x[k] = inputs[k].quantile(u[r * d + k]);
    y[r] = f(x.data());
  }
  return sobol_indices(y, n, d, options);
}

double worst_error(const SobolIndices& s, const Exact& exact) {
  double worst = 0;
  for (std::size_t i = 0; i < 3; ++i)
    worst = std::max({worst, std::abs(s.first[i].value - exact.first[i]), std::abs(s.total[i].value - exact.total[i])});
  return worst;
}

}  // namespace

TEST_CASE("Ishigami: the closed-form indices are the published ones", "[sobol]") {
  // Saltelli et al. 2010, sec. 5 (and Ishigami & Homma 1990), to the four printed digits.
  const Exact e = ishigami_exact();
  CHECK(e.first[0] == Approx(0.3139).margin(5e-5));
  CHECK(e.first[1] == Approx(0.4424).margin(5e-5));
  CHECK(e.total[0] == Approx(0.5576).margin(5e-5));
  CHECK(e.total[2] == Approx(0.2437).margin(5e-5));
}

TEST_CASE("Ishigami: the estimates' intervals cover the exact indices and the error falls with N", "[sobol]") {
  const std::vector<InputDistribution> inputs(3, uniform_distribution(-pi, pi));
  const Exact exact = ishigami_exact();
  // At N = 2^13 (N (d + 2) = 40960 runs): each 95 % bootstrap interval covers its exact value.
  // The estimators' standard error is ~ sd(f_B (f_i - f_A))/(V sqrt N) ~ 1e-2 here, so the check
  // is not trivially loose: the intervals are ~4 standard errors wide, not the unit interval.
  const SobolIndices s = indices_of(ishigami, inputs, 8192);
  for (std::size_t i = 0; i < 3; ++i) {
    INFO("input " << i + 1);
    CHECK(s.first[i].lower <= exact.first[i]);
    CHECK(exact.first[i] <= s.first[i].upper);
    CHECK(s.total[i].lower <= exact.total[i]);
    CHECK(exact.total[i] <= s.total[i].upper);
    CHECK(s.first[i].upper - s.first[i].lower < 0.1);
    CHECK(s.total[i].upper - s.total[i].lower < 0.1);
  }
  // The variance estimate: V = 13.845 (closed form above) within its sampling error, which for
  // 2N = 16384 values is ~ V sqrt((kurtosis - 1)/2N) ~ 2 %.
  const double V = ishigami_a * ishigami_a / 8 + ishigami_b * std::pow(pi, 4) / 5 +
                   ishigami_b * ishigami_b * std::pow(pi, 8) / 18 + 0.5;
  CHECK(s.variance == Approx(V).epsilon(0.03));

  // The error is O(N^{-1/2}) (Monte Carlo; a Sobol design does at least as well): 16 times the
  // rows must at least halve the worst error (N^{-1/2} predicts a quarter; half leaves room for
  // the errors' own scatter), and the intervals shrink by sqrt(16) = 4, each width being an
  // estimate with a relative scatter of ~10 %, so by 3 to 5.3.
  const SobolIndices small = indices_of(ishigami, inputs, 1024), large = indices_of(ishigami, inputs, 16384);
  CHECK(worst_error(large, exact) < 0.5 * worst_error(small, exact));
  for (std::size_t i = 0; i < 3; ++i) {
    INFO("input " << i + 1);
    const double ratio = (small.total[i].upper - small.total[i].lower) / (large.total[i].upper - large.total[i].lower);
    CHECK(ratio > 3.0);
    CHECK(ratio < 5.3);
  }
}

TEST_CASE("Sobol indices do not change when a constant is added to the output", "[sobol]") {
  // Indices are ratios of variances, so y + c has those of y. The estimators are too, in exact
  // arithmetic: V and VT_i see only differences, and V_i is centred by the mean of [f(A), f(B)]
  // (without the centring, V_i would carry a variance ~ c^2 Var(f_i - f_A)/N: for c = 1e4 here
  // intervals hundreds wide). With |y| ~ 1e4 about 4 of the 16 digits go, so agreement to 1e-9.
  const std::vector<InputDistribution> inputs(3, uniform_distribution(-pi, pi));
  const SobolIndices plain = indices_of(ishigami, inputs, 1024);
  const SobolIndices shifted = indices_of([](const double* x) { return ishigami(x) + 1e4; }, inputs, 1024);
  for (std::size_t i = 0; i < 3; ++i) {
    INFO("input " << i + 1);
    CHECK(shifted.first[i].value == Approx(plain.first[i].value).margin(1e-9));
    CHECK(shifted.first[i].lower == Approx(plain.first[i].lower).margin(1e-9));
    CHECK(shifted.first[i].upper == Approx(plain.first[i].upper).margin(1e-9));
    CHECK(shifted.total[i].value == Approx(plain.total[i].value).margin(1e-9));
  }
}

TEST_CASE("A linear additive function: S_i = ST_i = a_i^2 var_i / sum, an unused input gets exactly 0", "[sobol]") {
  // f = sum a_i x_i with independent x_i: V_i = a_i^2 var_i, no interactions, so
  // S_i = ST_i = a_i^2 var_i / sum_k a_k^2 var_k. Inputs: U(0, 1) (var 1/12), N(0, 2)
  // (var 4), U(-3, 3) (var 3), and a fourth that f ignores; a = (1, 0.5, 2, 0):
  // a^2 var = (1/12, 1, 12, 0), sum 157/12, S = (1/157, 12/157, 144/157, 0).
  const std::array<double, 4> a{1.0, 0.5, 2.0, 0.0};
  const std::vector<InputDistribution> inputs{uniform_distribution(0, 1), normal_distribution(0, 2),
                                              uniform_distribution(-3, 3), uniform_distribution(5, 6)};
  auto linear = [&](const double* x) { return a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + a[3] * x[3]; };
  const std::array<double, 4> exact{1.0 / 157, 12.0 / 157, 144.0 / 157, 0.0};
  const SobolIndices s = indices_of(linear, inputs, 4096);
  for (std::size_t i = 0; i < 3; ++i) {
    INFO("input " << i + 1);
    CHECK(s.first[i].lower <= exact[i]);
    CHECK(exact[i] <= s.first[i].upper);
    CHECK(s.total[i].lower <= exact[i]);
    CHECK(exact[i] <= s.total[i].upper);
  }
  // The ignored input: f(A_B^(4)) = f(A) row by row, so V_4 and VT_4 are sums of exact zeros,
  // and so is every bootstrap replicate.
  CHECK(s.first[3].value == 0.0);
  CHECK(s.total[3].value == 0.0);
  CHECK(s.first[3].lower == 0.0);
  CHECK(s.total[3].upper == 0.0);
}

TEST_CASE("The Saltelli design: A, B, and A with one column of B", "[sobol]") {
  const std::size_t n = 8, d = 3;
  const std::vector<double> ab = unit_sample(SampleMethod::sobol, n, 2 * d, 0);
  const std::vector<double> p = saltelli_unit_points(SampleMethod::sobol, n, d, 0);
  REQUIRE(p.size() == n * (d + 2) * d);
  for (std::size_t j = 0; j < n; ++j)
    for (std::size_t k = 0; k < d; ++k) {
      const double a = ab[j * 2 * d + k], b = ab[j * 2 * d + d + k];
      CHECK(p[(0 * n + j) * d + k] == a);
      CHECK(p[(1 * n + j) * d + k] == b);
      for (std::size_t i = 0; i < d; ++i) CHECK(p[((2 + i) * n + j) * d + k] == (k == i ? b : a));
    }
}

TEST_CASE("Sobol indices refuse outputs that do not fit the design", "[sobol]") {
  std::vector<double> f(10 * 5, 1.0);
  CHECK_THROWS_AS(sobol_indices(f, 10, 4), std::invalid_argument);  // 50 != 10 (4 + 2)
  CHECK_THROWS_AS(sobol_indices(f, 10, 3), std::invalid_argument);  // constant: no variance
  f[3] = NAN;
  f[4] = 2.0;
  CHECK_THROWS_AS(sobol_indices(f, 10, 3), std::invalid_argument);  // not finite
}

TEST_CASE("Sample quantiles: Hyndman-Fan definition 7", "[sobol]") {
  // {1, 2, 3, 4}: h = 3 p; p = 0.25 -> h = 0.75 -> 1 + 0.75 (2 - 1) = 1.75 (R's quantile()).
  CHECK(sample_quantile({4, 1, 3, 2}, 0.25) == 1.75);
  CHECK(sample_quantile({4, 1, 3, 2}, 0.5) == 2.5);
  CHECK(sample_quantile({4, 1, 3, 2}, 0.0) == 1.0);
  CHECK(sample_quantile({4, 1, 3, 2}, 1.0) == 4.0);
  CHECK_THROWS_AS(sample_quantile({}, 0.5), std::invalid_argument);
}
