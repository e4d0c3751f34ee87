#pragma once
// Fixed-step integration with event location, for any one-step method
// (ExplicitEuler, ClassicalRk4, ...).
//
// Event location: when some g_i changes from > 0 to <= 0 over a step of size h,
// the crossing time theta in (0, h] is found by the Illinois variant of regula
// falsi on theta -> g_i(Method::step(y, theta)), the step is cut at the earliest
// crossing, and the event is handled there. Each trial step is counted in the
// right-hand-side evaluations. With location off, events are handled at the end
// of the step in which the sign change is seen; convergence studies use this to
// show what an unlocated kink costs.
#include "hertzdash/integrators/format_message.hpp"
#include "hertzdash/integrators/work_bound.hpp"
#include "hertzdash/ode/ode_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace hertzdash {

struct FixedStepOptions {
  double dt = 1e-6;            ///< step size [s], > 0
  bool locate_events = true;   ///< cut steps at located event crossings
  double max_steps = 1e9;      ///< a run needing more steps (or more work: work_bound.hpp) does not start
};

namespace detail {

/// How finely an event is located in a step of length h at time t: a few roundings of
/// the larger of the two, below which the step's own time points cannot be told apart.
inline double event_location_tolerance(double t, double h) {
  return 4 * std::numeric_limits<double>::epsilon() * std::max(std::abs(t), h);
}

/// Root of phi(theta) on (lo, hi] with phi(lo) > 0 >= phi(hi), by Illinois regula falsi.
/// Stops when the bracket is below `tol` or phi hits zero; returns the right end
/// (where phi <= 0), so the event has happened at the returned time.
template <class Phi>
double illinois_root(Phi&& phi, double lo, double f_lo, double hi, double f_hi, double tol) {
  int side = 0;
  for (int it = 0; it < 100 && hi - lo > tol; ++it) {
    const double mid = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    const double m = std::clamp(mid, lo + 0.01 * (hi - lo), hi - 0.01 * (hi - lo));
    const double f_m = phi(m);
    if (f_m > 0) {
      lo = m, f_lo = f_m;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = m, f_hi = f_m;
      if (side == +1) f_lo *= 0.5;
      side = +1;
    }
  }
  return hi;
}

}  // namespace detail

/// Integrate `sys` from (t0, y) towards t_end with a fixed step; y is updated in place.
template <class Method, OdeSystem S, IntegrationObserver<typename S::State> Observer>
IntegrationStats integrate_fixed_step(S& sys, typename S::State& y, double t0, double t_end,
                                      const FixedStepOptions& opt, Observer& observer) {
  if (!(opt.dt > 0)) throw std::invalid_argument("integrate_fixed_step: dt must be > 0");
  // A bound on the work instead of a hang (a step so small that t + dt == t included).
  detail::require_fixed_step_work(t0, t_end, opt.dt, static_cast<long>(y.size()), opt.max_steps);
  using State = typename S::State;
  using Events = typename S::Events;
  IntegrationStats stats;
  double t = t0;
  Events g, g_new;
  sys.events(t, y, g);
  observer.on_step(t, y);
  State y_new;
  while (t < t_end) {
    double h = std::min(opt.dt, t_end - t);
    Method::step(sys, t, y, h, y_new);
    stats.rhs_evaluations += Method::stages;
    sys.events(t + h, y_new, g_new);

    bool crossed = false;
    for (int i = 0; i < S::event_count; ++i) crossed |= (g[i] > 0 && g_new[i] <= 0);
    if (crossed && opt.locate_events) {
      // Earliest crossing among the components that changed sign.
      double h_cut = h;
      for (int i = 0; i < S::event_count; ++i) {
        if (!(g[i] > 0 && g_new[i] <= 0)) continue;
        auto phi = [&](double theta) {
          State y_trial;
          Events g_trial;
          Method::step(sys, t, y, theta, y_trial);
          stats.rhs_evaluations += Method::stages;
          sys.events(t + theta, y_trial, g_trial);
          return g_trial[i];
        };
        const double tol = detail::event_location_tolerance(t, h);
        h_cut = std::min(h_cut, detail::illinois_root(phi, 0.0, g[i], h, g_new[i], tol));
      }
      if (h_cut < h) {
        h = h_cut;
        Method::step(sys, t, y, h, y_new);
        stats.rhs_evaluations += Method::stages;
        sys.events(t + h, y_new, g_new);
      }
    }
    t += h;
    y = y_new;
    ++stats.steps;
    observer.on_step(t, y);
    if (crossed) {
      bool restart = false;
      for (int i = 0; i < S::event_count; ++i) {
        if (!(g[i] > 0 && g_new[i] <= 0)) continue;
        const EventAction action = fire_event(sys, i, t, y, stats, observer);
        if (action == EventAction::stop) return stats;
        restart |= action == EventAction::restart;
      }
      if (restart) sys.events(t, y, g_new);  // the system changed mode: new event functions
    }
    g = g_new;
  }
  stats.t_final = t;
  return stats;
}

}  // namespace hertzdash
