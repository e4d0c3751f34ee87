#pragma once
// What both GSL peers hold: the odeiv2 step (rk8pd), y_new(atol, rtol) control and evolve
// objects of one system size, allocated once with the peer and freed with it; every
// evolve_apply checked.
#include "bench/impact_solvers.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <cstddef>
#include <stdexcept>
#include <string>

namespace hertzdash::bench {

class GslRk8pdObjects {
 public:
  /// For `dimension` state components at tolerance `tol` (tolerances_for).
  GslRk8pdObjects(std::size_t dimension, double tol) {
    const Tolerances t = tolerances_for(tol);
    step_ = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, dimension);
    control_ = gsl_odeiv2_control_y_new(t.atol, t.rtol);
    evolve_ = gsl_odeiv2_evolve_alloc(dimension);
    if (!step_ || !control_ || !evolve_) throw std::runtime_error("GSL: odeiv2 allocation failed");
  }
  ~GslRk8pdObjects() {
    gsl_odeiv2_evolve_free(evolve_);
    gsl_odeiv2_control_free(control_);
    gsl_odeiv2_step_free(step_);
  }
  GslRk8pdObjects(const GslRk8pdObjects&) = delete;
  GslRk8pdObjects& operator=(const GslRk8pdObjects&) = delete;

  /// Forgets the last step and its error (a new integration; the step size h is the caller's).
  void reset() {
    gsl_odeiv2_evolve_reset(evolve_);
    gsl_odeiv2_step_reset(step_);
  }
  /// Forgets the evolve object's history only (the same integration re-taken from a point).
  void reset_evolve() { gsl_odeiv2_evolve_reset(evolve_); }

  /// One adaptive step of `ode` from t towards t1 (t, h and y updated); throws on failure.
  void apply(gsl_odeiv2_system& ode, double& t, double t1, double& h, double y[]) {
    const int status = gsl_odeiv2_evolve_apply(evolve_, control_, step_, &ode, &t, t1, &h, y);
    if (status != GSL_SUCCESS) throw std::runtime_error(std::string("GSL: evolve_apply: ") + gsl_strerror(status));
  }

 private:
  gsl_odeiv2_step* step_ = nullptr;
  gsl_odeiv2_control* control_ = nullptr;
  gsl_odeiv2_evolve* evolve_ = nullptr;
};

}  // namespace hertzdash::bench
