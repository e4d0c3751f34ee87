#pragma once
// One-dimensional root finding for the calibrations (restitution, viscous time constant,
// interval restitution): GSL's Brent solver (gsl_root_fsolver_brent) behind a C++ callable.
// Every GSL return code is checked, GSL's abort-on-error handler is turned off, and an
// exception thrown by the callable (a failed run) crosses GSL's C frames safely: it is stored,
// GSL is handed a NaN, and the exception is rethrown once GSL has returned.
#include <functional>

namespace hertzdash {

/// GSL's default error handler aborts the process (a Python session included); hertzdash
/// checks every GSL return code instead. Call before the first GSL call (once is enough).
void use_gsl_return_codes();

/// Root of f in [lo, hi], where f(lo) and f(hi) have opposite signs; converged when the
/// bracket is narrower than abs_tol + rel_tol |root| (gsl_root_test_interval). `what` names the
/// calibration in errors (std::runtime_error: no convergence in 200 iterations, a GSL failure);
/// `iterations` (if given) receives the Brent iterations.
double brent_root(const std::function<double(double)>& f, double lo, double hi, double abs_tol, double rel_tol,
                  const char* what, int* iterations = nullptr);

/// The same with a relative tolerance only.
inline double brent_root(const std::function<double(double)>& f, double lo, double hi, double rel_tol,
                         const char* what, int* iterations = nullptr) {
  return brent_root(f, lo, hi, 0.0, rel_tol, what, iterations);
}

}  // namespace hertzdash
