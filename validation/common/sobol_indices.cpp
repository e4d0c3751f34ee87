#include "validation/common/sobol_indices.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/uncertainty/sample_quantile.hpp"

#include <gsl/gsl_rng.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>

namespace hertzdash {

std::vector<double> saltelli_unit_points(SampleMethod method, std::size_t n, std::size_t d, std::uint64_t seed) {
  if (n < 2) throw InvalidParameter("sample size N", std::to_string(n), "at least 2 rows of A and B");
  if (d == 0) throw InvalidParameter("input count d", "0", "at least 1");
  const std::vector<double> ab = unit_sample(method, n, 2 * d, seed);  // row j: A_j | B_j
  std::vector<double> points(n * (d + 2) * d);
  auto row = [&](std::size_t block, std::size_t j) { return points.data() + (block * n + j) * d; };
  for (std::size_t j = 0; j < n; ++j) {
    const double* a = ab.data() + j * 2 * d;
    const double* b = a + d;
    for (std::size_t k = 0; k < d; ++k) {
      row(0, j)[k] = a[k];
      row(1, j)[k] = b[k];
      for (std::size_t i = 0; i < d; ++i) row(2 + i, j)[k] = k == i ? b[k] : a[k];
    }
  }
  return points;
}

namespace {

// The estimators on the rows `rows` (indices into 0 .. N-1, repeats allowed).
struct Estimate {
  std::vector<double> first, total;
  double variance, mean;
};

Estimate estimate(std::span<const double> f, std::size_t n, std::size_t d, const std::vector<std::size_t>& rows) {
  const double* fa = f.data();
  const double* fb = fa + n;
  const double m = static_cast<double>(rows.size());
  double sum = 0;
  for (std::size_t j : rows) sum += fa[j] + fb[j];
  const double mean = sum / (2 * m);
  double ss = 0;
  for (std::size_t j : rows) ss += (fa[j] - mean) * (fa[j] - mean) + (fb[j] - mean) * (fb[j] - mean);
  const double variance = ss / (2 * m - 1);
  Estimate e{std::vector<double>(d), std::vector<double>(d), variance, mean};
  for (std::size_t i = 0; i < d; ++i) {
    const double* fi = fa + (2 + i) * n;
    double vi = 0, vti = 0;
    for (std::size_t j : rows) {
      vi += (fb[j] - mean) * (fi[j] - fa[j]);  // centred: see the header
      vti += (fa[j] - fi[j]) * (fa[j] - fi[j]);
    }
    e.first[i] = vi / m / variance;
    e.total[i] = vti / (2 * m) / variance;
  }
  return e;
}

struct RngDeleter {
  void operator()(gsl_rng* r) const { gsl_rng_free(r); }
};

}  // namespace

SobolIndices sobol_indices(std::span<const double> f, std::size_t n, std::size_t d, const SobolOptions& options) {
  if (n < 2 || d == 0) throw std::invalid_argument("sobol_indices: the design needs N >= 2 rows and d >= 1 inputs");
  if (f.size() != n * (d + 2))
    throw std::invalid_argument("sobol_indices: " + std::to_string(f.size()) + " outputs for a design of N (d + 2) = " +
                                std::to_string(n * (d + 2)) + " runs");
  for (std::size_t k = 0; k < f.size(); ++k)
    if (!std::isfinite(f[k])) throw std::invalid_argument("sobol_indices: output " + std::to_string(k) + " is not finite");
  if (!(options.confidence > 0 && options.confidence < 1))
    throw std::invalid_argument("sobol_indices: the confidence level must lie in (0, 1)");

  std::vector<std::size_t> rows(n);
  for (std::size_t j = 0; j < n; ++j) rows[j] = j;
  const Estimate point = estimate(f, n, d, rows);
  if (!(point.variance > 0)) throw std::invalid_argument("sobol_indices: the output has no variance");

  SobolIndices out;
  out.variance = point.variance;
  out.mean = point.mean;
  out.first.resize(d);
  out.total.resize(d);
  for (std::size_t i = 0; i < d; ++i) {
    out.first[i] = {point.first[i], point.first[i], point.first[i]};
    out.total[i] = {point.total[i], point.total[i], point.total[i]};
  }
  if (options.replicates == 0) return out;

  std::unique_ptr<gsl_rng, RngDeleter> rng(gsl_rng_alloc(gsl_rng_mt19937));
  if (!rng) throw std::runtime_error("GSL could not allocate a random number generator");
  gsl_rng_set(rng.get(), static_cast<unsigned long>(options.seed));
  std::vector<std::vector<double>> first(d), total(d);
  for (std::size_t r = 0; r < options.replicates; ++r) {
    for (std::size_t& j : rows) j = gsl_rng_uniform_int(rng.get(), n);
    const Estimate e = estimate(f, n, d, rows);
    if (!(e.variance > 0)) continue;  // a resample of identical rows has no indices
    for (std::size_t i = 0; i < d; ++i) {
      first[i].push_back(e.first[i]);
      total[i].push_back(e.total[i]);
    }
  }
  if (first[0].empty()) throw std::invalid_argument("sobol_indices: no bootstrap resample has any variance");
  const double lo = (1 - options.confidence) / 2, hi = (1 + options.confidence) / 2;
  for (std::size_t i = 0; i < d; ++i) {
    out.first[i].lower = sample_quantile(first[i], lo);
    out.first[i].upper = sample_quantile(first[i], hi);
    out.total[i].lower = sample_quantile(total[i], lo);
    out.total[i].upper = sample_quantile(total[i], hi);
  }
  return out;
}

}  // namespace hertzdash
