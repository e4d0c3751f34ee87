#include "hertzdash/simulation/calibrate_restitution.hpp"

#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace hertzdash {

DropTestSetup contact_phase_setup(const DropTestSetup& s) {
  DropTestSetup c = s;
  c.impact_velocity_mps = approach_speed(s);
  c.gravity_mps2 = 0.0;
  c.rod.E_Pa = std::numeric_limits<double>::infinity();
  validate(c);
  return c;
}

double effective_restitution(ImpactSimulator& simulator, const DropTestSetup& s, std::string_view law) {
  return simulator.run(contact_phase_setup(s), law).e_effective;
}

namespace {

struct Residual {
  ImpactSimulator* simulator;
  DropTestSetup setup;  // contact phase
  std::string_view law;
  double target;
  std::exception_ptr error;  // thrown by a run inside GSL's solver; rethrown once GSL has returned
  double operator()(double e_input) {
    setup.restitution = e_input;
    return simulator->run(setup, law).e_effective - target;
  }
};

// GSL calls this from C: no exception may cross it. A failed run stores its exception and
// returns NaN, which makes GSL return GSL_EBADFUNC; check_gsl then rethrows the exception.
double residual_thunk(double e_input, void* params) noexcept {
  auto* r = static_cast<Residual*>(params);
  try {
    return (*r)(e_input);
  } catch (...) {
    r->error = std::current_exception();
    return std::numeric_limits<double>::quiet_NaN();
  }
}

void check_gsl(int status, const char* what, const Residual& r) {
  if (r.error) std::rethrow_exception(r.error);
  if (status != GSL_SUCCESS) throw std::runtime_error(fmt::format("GSL {} failed: {}", what, gsl_strerror(status)));
}

// GSL's default error handler aborts the process (a Python session included); hertzdash
// checks every GSL return code instead, so the handler is turned off before the first call.
void use_gsl_return_codes() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

}  // namespace

RestitutionCalibration calibrate_restitution(ImpactSimulator& simulator, const DropTestSetup& s, std::string_view law,
                                             double target) {
  require_in_open_closed("--target-restitution", target, 0.0, 1.0);
  Residual residual{&simulator, contact_phase_setup(s), law, target, {}};
  // A target within the runs' accuracy of an end of the range is met at that end.
  const double f_hi = residual(1.0);
  if (std::abs(f_hi) <= calibration_end_tolerance) return {1.0, f_hi + target, 0};
  const double f_lo = residual(calibration_e_min);
  if (std::abs(f_lo) <= calibration_end_tolerance) return {calibration_e_min, f_lo + target, 0};
  if (f_lo > 0 || f_hi < 0)
    throw InvalidParameter("--target-restitution", format_value(target),
                           fmt::format("within [{:.6g}, {:.6g}], the effective restitutions law '{}' reaches for "
                                       "input e in [{}, 1]",
                                       f_lo + target, f_hi + target, law, calibration_e_min));

  use_gsl_return_codes();
  gsl_function F{&residual_thunk, &residual};
  const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  if (!solver) throw std::runtime_error("GSL gsl_root_fsolver_alloc failed");
  check_gsl(gsl_root_fsolver_set(solver.get(), &F, calibration_e_min, 1.0), "gsl_root_fsolver_set", residual);
  constexpr int max_iterations = 200;
  for (int i = 1; i <= max_iterations; ++i) {
    check_gsl(gsl_root_fsolver_iterate(solver.get()), "gsl_root_fsolver_iterate", residual);
    const double lo = gsl_root_fsolver_x_lower(solver.get()), hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, 1e-10, 0.0) == GSL_SUCCESS) {
      const double e = gsl_root_fsolver_root(solver.get());
      return {e, residual(e) + target, i};
    }
  }
  throw std::runtime_error(fmt::format("restitution calibration of '{}' did not converge in {} iterations", law,
                                       max_iterations));
}

}  // namespace hertzdash
