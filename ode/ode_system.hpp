#pragma once
// What an integrator needs from a system, and what it reports back.
//
// A system offers a right-hand side y' = f(t, y) of compile-time size and a
// fixed number of event (gap) functions g_i(t, y). An event fires when g_i
// decreases through zero (from > 0 to <= 0); the system then decides whether
// integration continues, restarts (its right-hand side changed form, so the
// integrator must not carry information across the event) or stops.
// Integrators know nothing else about the system.
//
// The state is an Eigen column vector of doubles. Its size is fixed at compile time
// (dimension = n, State = Eigen::Matrix<double, n, 1>) or chosen per run (dimension =
// Eigen::Dynamic, State = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, max, 1>: a runtime
// size up to a compile-time capacity, stored inline, so a step allocates nothing). A
// system of runtime size sizes the derivative it writes: rhs() starts with
// dy.resize(y.size()); integrators size their work vectors from the state they are given.
//
// Scales. A system may also offer `State state_scale() const`: the characteristic
// magnitude of each state component in its own units (say X [m] for a deformation, v0
// [m/s] for a speed), all > 0 and finite. An adaptive integrator's absolute tolerance
// for component i is then atol x scale_i, so its `atol` is dimensionless and the same
// run written in other units (or at another impact speed or mass with the same
// dimensionless motion) takes the same steps. Integrators read the scales at the start
// and after every restart (a new impact may bring new scales); a system without them
// gets scale 1 (atol in the state's own units).
#include <Eigen/Core>

#include <array>
#include <concepts>
#include <cstddef>
#include <stdexcept>
#include <type_traits>

namespace hertzdash {

enum class EventAction {
  continue_integration,  ///< an observation only; the right-hand side is unchanged
  restart,               ///< the right-hand side changed form: restart the method here
  stop,                  ///< end the integration at this event
};

template <class S>
concept OdeSystem = requires(S& s, const S& cs, double t, const typename S::State& y,
                             typename S::State& dy, typename S::Events& g) {
  { S::dimension } -> std::convertible_to<int>;
  { S::event_count } -> std::convertible_to<int>;
  requires std::same_as<typename S::State::Scalar, double>;
  requires S::State::ColsAtCompileTime == 1 && S::State::RowsAtCompileTime == S::dimension;
  requires S::dimension > 0 || S::State::MaxRowsAtCompileTime > 0;  // no heap-allocated states
  requires std::same_as<typename S::Events, std::array<double, S::event_count>>;
  cs.rhs(t, y, dy);
  cs.events(t, y, g);
  { s.handle_event(0, t, y) } -> std::same_as<EventAction>;
};

/// The index of an event named by a system's scoped enum (its enumerators in event order).
template <class E>
  requires std::is_enum_v<E>
constexpr int event_index(E e) {
  return static_cast<int>(e);
}

/// The absolute tolerance of each component of the state y of `sys`: atol x the system's
/// state_scale() (see "Scales" above), or atol for a system without scales.
template <OdeSystem S>
typename S::State absolute_tolerance(const S& sys, const typename S::State& y, double atol) {
  if constexpr (requires { { sys.state_scale() } -> std::convertible_to<typename S::State>; }) {
    const typename S::State scale = sys.state_scale();
    if (scale.size() != y.size() || !(scale.array() > 0).all() || !scale.allFinite())
      throw std::invalid_argument("state_scale: every component's scale must be positive and finite");
    return atol * scale;
  } else {
    return S::State::Constant(y.size(), atol);
  }
}

/// Receives every accepted step and every fired event (after the system handled it).
template <class O, class State>
concept IntegrationObserver = requires(O& o, double t, const State& y, int event, EventAction a) {
  o.on_step(t, y);
  o.on_event(event, t, y, a);
};

/// An observer that ignores everything.
struct NullObserver {
  template <class State> void on_step(double, const State&) noexcept {}
  template <class State> void on_event(int, double, const State&, EventAction) noexcept {}
};

/// The work one integration did.
struct IntegrationStats {
  long steps = 0;            ///< accepted steps (event-cut steps included)
  long rhs_evaluations = 0;  ///< right-hand-side evaluations, event location included
  long events = 0;           ///< events fired
  double t_final = 0.0;      ///< time reached [s]
  bool stopped_by_event = false;

  /// Add the steps and evaluations of another piece of the same integration.
  void add_work(const IntegrationStats& o) {
    steps += o.steps;
    rhs_evaluations += o.rhs_evaluations;
  }
};

/// Let the system handle event i at (t, y), tell the observer, and count it; on `stop`
/// record that the integration ended there. Every integrator fires events through this.
template <OdeSystem S, class Observer>
EventAction fire_event(S& sys, int i, double t, const typename S::State& y, IntegrationStats& stats,
                       Observer& observer) {
  const EventAction action = sys.handle_event(i, t, y);
  ++stats.events;
  observer.on_event(i, t, y, action);
  if (action == EventAction::stop) {
    stats.t_final = t;
    stats.stopped_by_event = true;
  }
  return action;
}

}  // namespace hertzdash
