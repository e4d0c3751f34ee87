#include "hertzdash/simulation/uncertainty/sample_design.hpp"

#include "hertzdash/model/invalid_parameter.hpp"

#include <gsl/gsl_qrng.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include <fmt/format.h>

#include <memory>
#include <numeric>
#include <stdexcept>

namespace hertzdash {

namespace {

struct RngDeleter {
  void operator()(gsl_rng* r) const { gsl_rng_free(r); }
};
struct QrngDeleter {
  void operator()(gsl_qrng* q) const { gsl_qrng_free(q); }
};

std::unique_ptr<gsl_rng, RngDeleter> seeded_rng(std::uint64_t seed) {
  std::unique_ptr<gsl_rng, RngDeleter> rng(gsl_rng_alloc(gsl_rng_mt19937));
  if (!rng) throw std::runtime_error("GSL could not allocate a random number generator");
  gsl_rng_set(rng.get(), static_cast<unsigned long>(seed));
  return rng;
}

std::vector<double> monte_carlo(std::size_t count, std::size_t dims, std::uint64_t seed) {
  auto rng = seeded_rng(seed);
  std::vector<double> u(count * dims);
  for (double& v : u) v = gsl_rng_uniform_pos(rng.get());  // (0, 1)
  return u;
}

std::vector<double> latin_hypercube(std::size_t count, std::size_t dims, std::uint64_t seed) {
  auto rng = seeded_rng(seed);
  std::vector<double> u(count * dims);
  std::vector<std::size_t> stratum(count);
  const double n = static_cast<double>(count);
  for (std::size_t j = 0; j < dims; ++j) {
    std::iota(stratum.begin(), stratum.end(), std::size_t{0});
    gsl_ran_shuffle(rng.get(), stratum.data(), count, sizeof(std::size_t));
    for (std::size_t i = 0; i < count; ++i)
      u[i * dims + j] = (static_cast<double>(stratum[i]) + gsl_rng_uniform_pos(rng.get())) / n;
  }
  return u;
}

std::vector<double> sobol(std::size_t count, std::size_t dims) {
  if (dims > max_sobol_dimension)
    throw InvalidParameter("sample dimension", std::to_string(dims),
                           fmt::format("at most {} for a Sobol design (GSL's table)", max_sobol_dimension));
  std::unique_ptr<gsl_qrng, QrngDeleter> q(gsl_qrng_alloc(gsl_qrng_sobol, static_cast<unsigned>(dims)));
  if (!q) throw std::runtime_error("GSL could not allocate a Sobol sequence");
  std::vector<double> u(count * dims);
  for (std::size_t i = 0; i < count; ++i)
    if (gsl_qrng_get(q.get(), u.data() + i * dims) != 0) throw std::runtime_error("GSL's Sobol sequence failed");
  return u;
}

}  // namespace

SampleMethod parse_sample_method(std::string_view method, const std::string& name) {
  for (SampleMethod m : {SampleMethod::monte_carlo, SampleMethod::latin_hypercube, SampleMethod::sobol})
    if (method == to_string(m)) return m;
  throw InvalidParameter(name, std::string(method), "one of: monte-carlo, latin-hypercube, sobol");
}

std::string to_string(SampleMethod method) {
  switch (method) {
    case SampleMethod::monte_carlo: return "monte-carlo";
    case SampleMethod::latin_hypercube: return "latin-hypercube";
    case SampleMethod::sobol: return "sobol";
  }
  return "?";
}

std::vector<double> unit_sample(SampleMethod method, std::size_t count, std::size_t dims, std::uint64_t seed) {
  if (dims == 0) throw InvalidParameter("sample dimension", "0", "at least 1 (a sample needs a distribution)");
  switch (method) {
    case SampleMethod::monte_carlo: return monte_carlo(count, dims, seed);
    case SampleMethod::latin_hypercube: return latin_hypercube(count, dims, seed);
    case SampleMethod::sobol: return sobol(count, dims);
  }
  return {};
}

}  // namespace hertzdash
