#pragma once
// The work an integration may take, checked before it starts: a run that would exceed it does
// not start (std::runtime_error "did not finish: ..."), instead of running for minutes.
//   fixed step h over [t0, t_end] with n state components: ceil((t_end - t0) / h) steps, each
//     touching all n components, at most max_work_component_steps of work in all;
//   an adaptive method with a largest step h_max: at least (t_end - t0) / h_max steps, which
//     must fit in its step budget (max_steps).
// The bound is on component-steps (steps x n), so that a large system (the elastic rod's 804
// components at 400 elements) gets proportionally fewer steps than the rigid model's 2.
#include "hertzdash/integrators/format_message.hpp"

#include <cmath>
#include <stdexcept>

namespace hertzdash {

/// Steps x state components of one fixed-step run: 1e10, about 10 s of RK4 on the elastic rod
/// (0.6 to 1 ns per component-step measured at 400 elements, 806 components) and, for the rigid
/// model's 2 components, more than its 1e9 steps.
inline constexpr double max_work_component_steps = 1e10;

namespace detail {

/// Throws unless a fixed step `dt` takes [t0, t_end] with n components within both bounds.
inline void require_fixed_step_work(double t0, double t_end, double dt, long n, double max_steps) {
  const double steps = std::ceil((t_end - t0) / dt);
  const double limit = std::min(max_steps, max_work_component_steps / static_cast<double>(n));
  if (steps > limit)
    throw std::runtime_error(format_g("did not finish: a fixed step of %.3g s would need %.3g steps of a %ld-component "
                                      "state to reach t = %.6g s, more than the limit of %.3g (%.3g component-steps; "
                                      "take a larger step)",
                                      dt, steps, n, t_end, limit, max_work_component_steps));
}

/// Throws when a largest step `max_step` (> 0) alone needs more steps than `max_steps` to take
/// [t0, t_end]: the run would end at its step budget anyway, after all that work.
inline void require_max_step_reach(const char* method, double t0, double t_end, double max_step, double max_steps) {
  if (!(max_step > 0)) return;
  const double steps = std::ceil((t_end - t0) / max_step);
  if (steps > max_steps)
    throw std::runtime_error(format_g("did not finish: %s with a largest step of %.3g s would need at least %.3g steps "
                                      "to reach t = %.6g s, more than its limit of %.3g (take a larger largest step)",
                                      method, max_step, steps, t_end, max_steps));
}

}  // namespace detail
}  // namespace hertzdash
