#pragma once
// Classical fourth-order Runge-Kutta:
//   k1 = f(t, y), k2 = f(t + h/2, y + h k1/2), k3 = f(t + h/2, y + h k2/2),
//   k4 = f(t + h, y + h k3),  y_{n+1} = y + h (k1 + 2 k2 + 2 k3 + k4) / 6.
// Order 4 for a right-hand side with four continuous derivatives.
#include "hertzdash/ode/ode_system.hpp"

namespace hertzdash {

struct ClassicalRk4 {
  static constexpr const char* name = "rk4";
  static constexpr int order = 4;
  static constexpr int stages = 4;

  template <OdeSystem S>
  static void step(const S& sys, double t, const typename S::State& y, double h, typename S::State& y_out) {
    typename S::State k1, k2, k3, k4;
    sys.rhs(t, y, k1);
    sys.rhs(t + 0.5 * h, y + (0.5 * h) * k1, k2);
    sys.rhs(t + 0.5 * h, y + (0.5 * h) * k2, k3);
    sys.rhs(t + h, y + h * k3, k4);
    y_out = y + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
};

}  // namespace hertzdash
