// The least-squares problem of a trace fit (simulation/fit/trace_fit_problem.hpp): residuals
// weighted by the channels' noise and the scaled condition number of a solution.
#include "hertzdash/simulation/fit/trace_fit_problem.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>

#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

namespace hertzdash::trace_fit_detail {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

}  // namespace

std::vector<double> FitProblem::physical(const double* z) const {
  std::vector<double> v;
  for (std::size_t j = 0; j < transforms_.size(); ++j) v.push_back(transforms_[j].p(z[j]));
  return v;
}

std::vector<double> FitProblem::model_values(const double* z) {
  const ImpactHistory* h = model_->history(physical(z));
  if (!h) return {};
  ++evaluations_;
  const double t0 = onset_s(z);
  std::vector<double> m(obs_.size());
  for (std::size_t i = 0; i < obs_.size(); ++i)
    m[i] = instrument_channel(h->instruments_at(obs_[i].t_s - t0), channels_[obs_[i].channel]);
  return m;
}

void FitProblem::residuals(const double* z, double* r) {
  const std::vector<double> m = model_values(z);
  for (std::size_t i = 0; i < obs_.size(); ++i) r[i] = m.empty() ? outside : (obs_[i].y - m[i]) * obs_[i].inv_sigma;
}

// Condition number of J with columns scaled to relative changes of the parameters.
double scaled_condition_number(const gsl_matrix* J, const FitProblem& problem, const double* z) {
  const std::size_t n = J->size1, p = J->size2;
  const std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> A(gsl_matrix_alloc(n, p), &gsl_matrix_free);
  gsl_matrix_memcpy(A.get(), J);
  for (std::size_t j = 0; j + 1 < p; ++j) {
    const Transform& t = problem.transforms()[j];
    const double value = t.p(z[j]), scale = value != 0 ? std::abs(value) : 1.0;
    gsl_vector_view column = gsl_matrix_column(A.get(), j);
    gsl_vector_scale(&column.vector, scale / t.dp_dz(z[j]));
  }
  const std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> V(gsl_matrix_alloc(p, p), &gsl_matrix_free);
  const std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> S(gsl_vector_alloc(p), &gsl_vector_free),
      work(gsl_vector_alloc(p), &gsl_vector_free);
  if (const int status = gsl_linalg_SV_decomp(A.get(), V.get(), S.get(), work.get()); status != GSL_SUCCESS)
    throw std::runtime_error(std::string("fit: GSL gsl_linalg_SV_decomp failed: ") + gsl_strerror(status));
  const double smallest = gsl_vector_min(S.get()), largest = gsl_vector_max(S.get());
  return smallest > 0 ? largest / smallest : inf;
}


}  // namespace hertzdash::trace_fit_detail
