#pragma once
// A test system with a closed form: q' = p, p' = -q from (q, p) = (1, 0) gives
// q = cos t, p = -sin t. One event, g = q, which first falls through zero at
// t = pi/2 (where p = -1) and stops the run; with stop_at_quarter = false the
// event never fires.
#include "hertzdash/ode/ode_system.hpp"

#include <Eigen/Core>

#include <array>

namespace hertzdash::test {

struct HarmonicOscillator {
  static constexpr int dimension = 2;
  static constexpr int event_count = 1;
  using State = Eigen::Matrix<double, 2, 1>;
  using Events = std::array<double, 1>;
  void rhs(double, const State& y, State& dy) const { dy << y[1], -y[0]; }
  void events(double, const State& y, Events& g) const { g[0] = stop_at_quarter ? y[0] : 1.0; }
  EventAction handle_event(int, double, const State&) { return EventAction::stop; }
  bool stop_at_quarter = true;
};

}  // namespace hertzdash::test
