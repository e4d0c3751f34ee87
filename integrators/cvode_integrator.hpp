#pragma once
// SUNDIALS CVODE(S) 6.4 behind the OdeSystem interface.
//
// Method: variable-order, variable-step Adams-Moulton (orders 1-12, fixed-point
// corrector) or BDF (orders 1-5, Newton with a difference-quotient Jacobian: dense,
// or banded for a system that declares `static constexpr int jacobian_half_bandwidth`,
// the largest |i - j| of a non-zero df_i/dy_j that matters for convergence). Local error
// control: ||e_i|| <= rtol |y_i| + atol_i in the WRMS norm, atol_i = atol x the system's
// scale of component i (ode/ode_system.hpp, absolute_tolerance), set with
// CVodeSVtolerances at the start and at every restart (no allocation after the first).
// Events: CVODE's root finding on the system's event functions with direction
// -1 (g decreasing through zero). After an event whose action is `restart`,
// the integrator restarts with CVodeReInit at the event point, so no step
// straddles a change of force law.
//
// One CvodeIntegrator owns its SUNContext, vectors and solver memory; integrate()
// may be called any number of times and reuses them (CVodeReInit), so a sweep
// over many impacts pays for the set-up once. Not thread-safe: one per thread.
#include "hertzdash/integrators/format_message.hpp"
#include "hertzdash/integrators/work_bound.hpp"
#include "hertzdash/ode/ode_system.hpp"

#include <memory>
#include <stdexcept>
#include <string>

namespace hertzdash {

enum class CvodeMethod { adams, bdf };
const char* to_string(CvodeMethod m);

struct CvodeOptions {
  CvodeMethod method = CvodeMethod::adams;
  double rtol = 1e-8;          ///< relative tolerance, > 0
  double atol = 1e-12;         ///< absolute tolerance relative to the system's state scales, > 0
  double max_step = 0.0;       ///< largest step [s]; 0 means no limit
  long max_num_steps = 1000000;  ///< steps of one integrate() call, over its restarts; more: std::runtime_error
  int band_half_width = -1;    ///< BDF: banded Jacobian with this half-bandwidth; < 0: dense
};

/// The Jacobian half-bandwidth a system declares, or -1 (dense).
template <class S>
constexpr int jacobian_half_bandwidth() {
  if constexpr (requires { S::jacobian_half_bandwidth; }) return S::jacobian_half_bandwidth;
  else return -1;
}

/// Type-erased view of a system, so the CVODE callbacks are plain functions.
struct CvodeCallbacks {
  void* system = nullptr;
  int dimension = 0;
  void (*rhs)(void* system, int n, double t, const double* y, double* dy) = nullptr;
  void (*events)(void* system, int n, double t, const double* y, double* g) = nullptr;
};

class CvodeIntegrator {
 public:
  CvodeIntegrator(int dimension, int event_count, const CvodeOptions& options);
  ~CvodeIntegrator();
  CvodeIntegrator(const CvodeIntegrator&) = delete;
  CvodeIntegrator& operator=(const CvodeIntegrator&) = delete;

  /// Integrate `sys` from (t0, y) towards t_end; y is updated in place.
  template <OdeSystem S, IntegrationObserver<typename S::State> Observer>
  IntegrationStats integrate(S& sys, typename S::State& y, double t0, double t_end, Observer& observer);

 private:
  // Non-template core: restart at (t, y) with absolute tolerances atol (one per
  // component), take one step towards t_end.
  void restart(double t, const double* y, const double* atol);
  /// Returns +1 on a root return, 0 on an ordinary step, and 2 at the stop time.
  int step(double t_end, double& t, double* y);
  const int* roots_found();
  /// Steps and right-hand-side evaluations since the last restart (CVODE's counters).
  IntegrationStats work_since_restart() const;
  void check_dimensions(int dimension, int event_count) const;

  struct Impl;
  std::unique_ptr<Impl> impl_;
  CvodeOptions options_;
  CvodeCallbacks callbacks_;
};

template <OdeSystem S, IntegrationObserver<typename S::State> Observer>
IntegrationStats CvodeIntegrator::integrate(S& sys, typename S::State& y, double t0, double t_end,
                                            Observer& observer) {
  check_dimensions(static_cast<int>(y.size()), S::event_count);
  callbacks_.system = &sys;
  callbacks_.dimension = static_cast<int>(y.size());
  callbacks_.rhs = [](void* s, int n, double t, const double* yp, double* dy) {
    Eigen::Map<typename S::State> out(dy, n);
    typename S::State d;
    static_cast<const S*>(s)->rhs(t, Eigen::Map<const typename S::State>(yp, n), d);
    out = d;
  };
  callbacks_.events = [](void* s, int n, double t, const double* yp, double* g) {
    typename S::Events e;
    static_cast<const S*>(s)->events(t, Eigen::Map<const typename S::State>(yp, n), e);
    for (int i = 0; i < S::event_count; ++i) g[i] = e[i];
  };

  detail::require_max_step_reach("CVODE", t0, t_end, options_.max_step, static_cast<double>(options_.max_num_steps));
  IntegrationStats total;
  double t = t0;
  restart(t, y.data(), absolute_tolerance(sys, y, options_.atol).data());
  observer.on_step(t, y);
  long steps = 0;
  while (t < t_end) {
    // CV_ONE_STEP takes one step per call, so CVodeSetMaxNumSteps never trips: the bound is here.
    if (++steps > options_.max_num_steps)
      throw std::runtime_error(detail::format_g("did not finish: CVODE took %ld steps and reached t = %.6g s of %.6g s "
                                                "(a largest step or tolerance too small for the run?)",
                                                options_.max_num_steps, t, t_end));
    const int kind = step(t_end, t, y.data());
    observer.on_step(t, y);
    if (kind == 2) break;
    if (kind != 1) continue;
    const int* found = roots_found();
    bool restart_needed = false;
    for (int i = 0; i < S::event_count; ++i) {
      if (found[i] == 0) continue;
      const EventAction action = fire_event(sys, i, t, y, total, observer);
      if (action == EventAction::stop) {
        total.add_work(work_since_restart());
        return total;
      }
      restart_needed |= action == EventAction::restart;
    }
    if (restart_needed) {
      total.add_work(work_since_restart());
      restart(t, y.data(), absolute_tolerance(sys, y, options_.atol).data());
    }
  }
  total.add_work(work_since_restart());
  total.t_final = t;
  return total;
}

}  // namespace hertzdash
