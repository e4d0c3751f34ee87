#pragma once
// Internal to the fits (simulation/fit/trace_fit.cpp, restitution_fit.cpp; not installed,
// cmake/install.cmake): what GSL's multifit_nlinear needs of any problem with
//   std::size_t n() const, p() const;  void residuals(const double* z, double* r);
//   std::exception_ptr error;
// its Jacobian by central differences, the thunks GSL calls it through, and why the solver stopped.
#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

#include <exception>
#include <string>
#include <vector>

namespace hertzdash::fit_detail {

/// Central differences of the residuals, step 1e-6 in every (unbounded, transformed) variable z.
template <class Problem> void central_difference_jacobian(Problem& problem, const double* z, gsl_matrix* J) {
  const std::size_t n = problem.n(), p = problem.p();
  std::vector<double> zz(z, z + p), plus(n), minus(n);
  for (std::size_t j = 0; j < p; ++j) {
    const double h = 1e-6;
    zz[j] = z[j] + h;
    problem.residuals(zz.data(), plus.data());
    zz[j] = z[j] - h;
    problem.residuals(zz.data(), minus.data());
    zz[j] = z[j];
    for (std::size_t i = 0; i < n; ++i) gsl_matrix_set(J, i, j, (plus[i] - minus[i]) / (2.0 * h));
  }
}

/// gsl_multifit_nlinear_fdf's f and df, `params` a Problem: an exception is stored in its `error`
/// (rethrown once GSL has returned) and GSL told GSL_EBADFUNC.
template <class Problem> int residuals_thunk(const gsl_vector* z, void* params, gsl_vector* f) {
  auto* problem = static_cast<Problem*>(params);
  try {
    problem->residuals(z->data, f->data);
    return GSL_SUCCESS;
  } catch (...) {
    problem->error = std::current_exception();
    return GSL_EBADFUNC;
  }
}
template <class Problem> int jacobian_thunk(const gsl_vector* z, void* params, gsl_matrix* J) {
  auto* problem = static_cast<Problem*>(params);
  try {
    central_difference_jacobian(*problem, z->data, J);
    return GSL_SUCCESS;
  } catch (...) {
    problem->error = std::current_exception();
    return GSL_EBADFUNC;
  }
}

/// Why GSL's driver stopped, from its status and `info`.
inline std::string stop_reason(int status, int info) {
  if (status == GSL_EMAXITER) return "maximum number of iterations reached";
  if (status == GSL_ENOPROG) return "no further decrease of the cost within its resolution";
  return info == 1 ? "small step (xtol)" : "small gradient (gtol)";
}

}  // namespace hertzdash::fit_detail
