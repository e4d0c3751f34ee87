#pragma once
// The work an integration may take, checked before it starts: a run that would exceed it does
// not start (std::runtime_error "did not finish: ..."), instead of running for minutes.
//   fixed step h over [t0, t_end] with n state components: ceil((t_end - t0) / h) steps, each
//     touching all n components, at most max_work_component_steps of work in all (and at most
//     the method's max_steps);
//   an adaptive method with a largest step h_max: a run may end early at an event (a drop's
//     contact ends at separation, one or two contact times into a horizon of twenty), so it is
//     refused only when even horizon_share of [t0, t_end] needs more steps than its budget.
// The fixed-step bound is on component-steps (steps x n), so that a large system (the elastic
// rod's 806 components at 400 elements) gets proportionally fewer steps than the rigid model's 2.
#include "hertzdash/integrators/format_message.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hertzdash {

/// Steps x state components of one fixed-step run, up to its horizon: 1e10. A drop test ends at
/// separation, within about a twentieth of its horizon, so the work done is some 5e8
/// component-steps at most, seconds of RK4 on the elastic rod (10 to 15 ns per component-step
/// measured at 400 elements); for the rigid model's 2 components the method's 1e9 steps bind.
inline constexpr double max_work_component_steps = 1e10;

/// The share of an adaptive run's horizon it must be able to reach within its step budget.
inline constexpr double horizon_share = 1.0 / 20.0;

namespace detail {

/// Throws unless a fixed step `dt` takes [t0, t_end] with n components within both bounds.
inline void require_fixed_step_work(double t0, double t_end, double dt, long n, double max_steps) {
  const double steps = std::ceil((t_end - t0) / dt);
  const double by_work = max_work_component_steps / static_cast<double>(n);
  if (steps > max_steps)
    throw std::runtime_error(format_g("did not finish: a fixed step of %.3g s would need %.3g steps to reach t = %.6g "
                                      "s, more than the limit of %.3g (take a larger step)",
                                      dt, steps, t_end, max_steps));
  if (steps > by_work)
    throw std::runtime_error(format_g("did not finish: a fixed step of %.3g s would need %.3g steps of a %ld-component "
                                      "state to reach t = %.6g s, more than the limit of %.3g component-steps (%.3g "
                                      "steps; take a larger step)",
                                      dt, steps, n, t_end, max_work_component_steps, by_work));
}

/// Throws when, with a largest step `max_step` (> 0), even horizon_share of [t0, t_end] needs
/// more steps than `max_steps`: the run would spend its whole budget and stop unfinished.
inline void require_max_step_reach(const char* method, double t0, double t_end, double max_step, double max_steps) {
  if (!(max_step > 0)) return;
  const double steps = std::ceil(horizon_share * (t_end - t0) / max_step);
  if (steps > max_steps)
    throw std::runtime_error(format_g("did not finish: %s with a largest step of %.3g s would need %.3g steps to reach "
                                      "even t = %.6g s, a twentieth of its horizon, more than its limit of %.3g (take a "
                                      "larger largest step)",
                                      method, max_step, steps, t0 + horizon_share * (t_end - t0), max_steps));
}

}  // namespace detail
}  // namespace hertzdash
