#pragma once
// Explicit Euler: y_{n+1} = y_n + h f(t_n, y_n). Order 1, one evaluation per step.
#include "hertzdash/ode/ode_system.hpp"

namespace hertzdash {

struct ExplicitEuler {
  static constexpr const char* name = "euler";
  static constexpr int order = 1;
  static constexpr int stages = 1;

  template <OdeSystem S>
  static void step(const S& sys, double t, const typename S::State& y, double h, typename S::State& y_out) {
    typename S::State k;
    sys.rhs(t, y, k);
    y_out = y + h * k;
  }
};

}  // namespace hertzdash
