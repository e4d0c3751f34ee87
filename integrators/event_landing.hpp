#pragma once
// Event handling shared by the adaptive integrators that land steps on events
// (dormand_prince.hpp, extrapolation.hpp): which event functions crossed zero in a
// step, where on the step's continuous extension, and the firing of the events at
// the landing point.
//
// A g_i fires when it goes from > 0 to <= 0. Crossings are located on a dense output
// `at(theta)`, theta in [0, 1] across the step [t, t + h], by Illinois regula falsi (no
// right-hand-side evaluation); the integrator then re-takes the step to end exactly
// on the earliest crossing and calls fire_landed_events there.
#include "hertzdash/integrators/fixed_step.hpp"  // detail::illinois_root, event_location_tolerance
#include "hertzdash/ode/ode_system.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace hertzdash::detail {

/// True if some g_i went from > 0 (g_start) to <= 0 (g_end).
template <class Events>
bool any_event_crossed(const Events& g_start, const Events& g_end) {
  bool any = false;
  for (std::size_t i = 0; i < g_start.size(); ++i) any |= (g_start[i] > 0 && g_end[i] <= 0);
  return any;
}

/// The crossings of one step located on its dense output.
template <int N>
struct EventCrossings {
  std::array<double, N> theta;  ///< crossing of g_i as a fraction of the step; 2 if none
  double earliest = 1.0;        ///< the smallest theta
  double theta_tol = 0.0;       ///< resolution of the location, as a fraction of the step
};

/// Locates every crossing in the step [t, t + h] on `dense` (dense.at(theta) -> state).
template <OdeSystem S, class Dense>
EventCrossings<S::event_count> locate_event_crossings(const S& sys, double t, double h,
                                                      const typename S::Events& g_start,
                                                      const typename S::Events& g_end, const Dense& dense) {
  EventCrossings<S::event_count> c;
  c.theta_tol = event_location_tolerance(t, h) / h;
  for (int i = 0; i < S::event_count; ++i) {
    c.theta[i] = 2.0;
    if (!(g_start[i] > 0 && g_end[i] <= 0)) continue;
    auto phi = [&](double th) {
      typename S::Events g;
      sys.events(t + th * h, dense.at(th), g);
      return g[i];
    };
    c.theta[i] = illinois_root(phi, 0.0, g_start[i], 1.0, g_end[i], c.theta_tol);
    c.earliest = std::min(c.earliest, c.theta[i]);
  }
  return c;
}

/// At the landing point (t, y) of a step that began at t_start with event values
/// g_start and length h: fires, in index order, the events located there and any other
/// that has already crossed, updating g (the event values at (t, y), on return with
/// the fired ones clamped to <= 0 so they must rise again before they fire again; after
/// a restart, the system's new event functions at (t, y)), stats and the observer.
/// Returns the strongest action: stop, restart, or continue.
template <OdeSystem S, class Observer, int N = S::event_count>
EventAction fire_landed_events(S& sys, double t, const typename S::State& y, typename S::Events& g,
                               const typename S::Events& g_start, double t_start, double h,
                               const EventCrossings<N>& c, IntegrationStats& stats, Observer& observer) {
  sys.events(t, y, g);
  EventAction result = EventAction::continue_integration;
  for (int i = 0; i < S::event_count; ++i) {
    const bool located_here = t_start + c.theta[i] * h <= t + c.theta_tol * h;
    if (!(g_start[i] > 0 && (located_here || g[i] <= 0))) continue;
    const EventAction action = fire_event(sys, i, t, y, stats, observer);
    if (action == EventAction::stop) return EventAction::stop;
    if (action == EventAction::restart) result = EventAction::restart;
    g[i] = std::min(g[i], 0.0);
  }
  if (result == EventAction::restart) sys.events(t, y, g);  // the system changed mode
  return result;
}

}  // namespace hertzdash::detail
