#include "hertzdash/simulation/run/gsl_root.hpp"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace hertzdash {

namespace {

struct Callable {
  const std::function<double(double)>* f;
  std::exception_ptr error;  // thrown inside GSL's solver; rethrown once GSL has returned
};

// GSL calls this from C: no exception may cross it. A failed evaluation stores its exception
// and returns NaN, which makes GSL return GSL_EBADFUNC; check() then rethrows the exception.
double thunk(double x, void* params) noexcept {
  auto* c = static_cast<Callable*>(params);
  try {
    return (*c->f)(x);
  } catch (...) {
    c->error = std::current_exception();
    return std::numeric_limits<double>::quiet_NaN();
  }
}

void check(int status, const char* call, const char* what, const Callable& c) {
  if (c.error) std::rethrow_exception(c.error);
  if (status != GSL_SUCCESS) throw std::runtime_error(fmt::format("{}: GSL {} failed: {}", what, call, gsl_strerror(status)));
}

}  // namespace

void use_gsl_return_codes() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

double brent_root(const std::function<double(double)>& f, double lo, double hi, double abs_tol, double rel_tol,
                  const char* what, int* iterations) {
  use_gsl_return_codes();
  Callable c{&f, {}};
  gsl_function F{&thunk, &c};
  const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  if (!solver) throw std::runtime_error(fmt::format("{}: GSL gsl_root_fsolver_alloc failed", what));
  check(gsl_root_fsolver_set(solver.get(), &F, lo, hi), "gsl_root_fsolver_set", what, c);
  constexpr int max_iterations = 200;
  for (int i = 1; i <= max_iterations; ++i) {
    check(gsl_root_fsolver_iterate(solver.get()), "gsl_root_fsolver_iterate", what, c);
    const double a = gsl_root_fsolver_x_lower(solver.get()), b = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(a, b, abs_tol, rel_tol) == GSL_SUCCESS) {
      if (iterations) *iterations = i;
      return gsl_root_fsolver_root(solver.get());
    }
  }
  throw std::runtime_error(fmt::format("{} did not converge in {} iterations", what, max_iterations));
}

}  // namespace hertzdash
