#pragma once
// Internal to the trace fit (simulation/fit/trace_fit.cpp; not installed, cmake/install.cmake): the
// weighted least-squares problem GSL's multifit_nlinear solves, in the unbounded variables
// z = (transformed parameters, t0 / t_H) (simulation/fit/trace_fit.hpp, "Residuals" and
// "Uncertainty"): its residuals, which the Jacobian and the thunks of least_squares.hpp
// differentiate and pass to GSL, and the scaled condition number of a solution.
#include "hertzdash/simulation/fit/fit_parameters.hpp"
#include "hertzdash/simulation/fit/trace_fit_model.hpp"

#include <gsl/gsl_matrix.h>
#include <gsl/gsl_vector.h>

#include <cstddef>
#include <exception>
#include <string>
#include <vector>

namespace hertzdash::trace_fit_detail {

/// One sample of one channel, with its weight 1 / sigma_c.
struct Observation {
  std::size_t channel;
  double t_s, y, inv_sigma;
};

class FitProblem {
 public:
  FitProblem(std::vector<Observation> obs, TraceModel& model, std::vector<Transform> transforms,
             std::vector<std::string> channels)
      : obs_(std::move(obs)), model_(&model), transforms_(std::move(transforms)), channels_(std::move(channels)) {}

  std::size_t n() const { return obs_.size(); }
  std::size_t p() const { return transforms_.size() + 1; }

  /// The fitted parameters' values at z (the onset, last in z, left out).
  std::vector<double> physical(const double* z) const;
  double onset_s(const double* z) const { return z[transforms_.size()] * model_->time_scale_s(); }

  /// The model's value of each observation's channel at z; empty outside the model's domain.
  std::vector<double> model_values(const double* z);

  /// Outside the model's domain every residual is `outside` (1e30): the trust region rejects the
  /// step and shrinks, as it does for any step that raises the cost.
  void residuals(const double* z, double* r);
  static constexpr double outside = 1e30;

  /// The work so far: the model's RK4 steps plus the observations interpolated (trace_fit.hpp, "Work").
  double work() const { return model_->steps() + evaluations_ * static_cast<double>(n()); }

  const std::vector<Observation>& observations() const { return obs_; }
  const std::vector<Transform>& transforms() const { return transforms_; }
  std::exception_ptr error;  ///< thrown inside a thunk: rethrown once GSL has returned

 private:
  std::vector<Observation> obs_;
  TraceModel* model_;
  std::vector<Transform> transforms_;
  std::vector<std::string> channels_;
  double evaluations_ = 0;  // model_values at a point inside the domain
};

/// Condition number of J with columns scaled to relative changes of the parameters.
double scaled_condition_number(const gsl_matrix* J, const FitProblem& problem, const double* z);

}  // namespace hertzdash::trace_fit_detail
