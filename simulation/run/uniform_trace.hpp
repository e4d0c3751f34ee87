#pragma once
// A recorded contact phase on a uniform time grid, for plotting and for comparison with
// sampled measurements. The recorded samples sit at the integrator's accepted steps; between
// two of them the deformation x and the rod displacement are interpolated by cubic Hermite
// polynomials with their recorded derivatives (xdot, rod velocity), and xdot and the rod
// velocity likewise with the recorded accelerations (x'', the rod's) as derivatives, so they
// are O(h^4) and O(h^3) accurate in the step h; forces and accelerations are interpolated
// linearly, O(h^2), and stay consistent with each other (a = g - F/m).
#include "hertzdash/simulation/run/impact_summary.hpp"

#include <cmath>
#include <cstddef>
#include <vector>

namespace hertzdash {

/// Samples of `trace` at t_0, t_0 + dt, ... up to its last time (dt [s] > 0).
inline std::vector<TraceSample> uniform_trace(const std::vector<TraceSample>& trace, double dt_s) {
  std::vector<TraceSample> out;
  if (trace.empty()) return out;
  const double t0 = trace.front().t_s, t1 = trace.back().t_s;
  const std::size_t n = static_cast<std::size_t>(std::floor((t1 - t0) / dt_s * (1 + 1e-12))) + 1;
  out.reserve(n);
  std::size_t k = 0;  // trace[k].t_s <= t < trace[k + 1].t_s
  for (std::size_t i = 0; i < n; ++i) {
    const double t = t0 + static_cast<double>(i) * dt_s;
    while (k + 2 < trace.size() && trace[k + 1].t_s <= t) ++k;
    const TraceSample& a = trace[k];
    const TraceSample& b = trace[std::min(k + 1, trace.size() - 1)];
    const double h = b.t_s - a.t_s;
    if (h <= 0) {
      out.push_back(a);
      out.back().t_s = t;
      continue;
    }
    const double s = std::min(std::max((t - a.t_s) / h, 0.0), 1.0);
    // Cubic Hermite basis on [0, 1].
    const double h00 = (1 + 2 * s) * (1 - s) * (1 - s), h10 = s * (1 - s) * (1 - s);
    const double h01 = s * s * (3 - 2 * s), h11 = s * s * (s - 1);
    auto hermite = [&](double ya, double dya, double yb, double dyb) {
      return h00 * ya + h10 * h * dya + h01 * yb + h11 * h * dyb;
    };
    auto linear = [&](double ya, double yb) { return ya + s * (yb - ya); };
    TraceSample& r = out.emplace_back();
    r.t_s = t;
    r.x_m = hermite(a.x_m, a.xdot_mps, b.x_m, b.xdot_mps);
    r.xdot_mps = hermite(a.xdot_mps, a.xddot_mps2, b.xdot_mps, b.xddot_mps2);
    r.force_N = linear(a.force_N, b.force_N);
    r.accel_mps2 = linear(a.accel_mps2, b.accel_mps2);
    r.rod_displacement_m = hermite(a.rod_displacement_m, a.rod_velocity_mps, b.rod_displacement_m, b.rod_velocity_mps);
    r.rod_velocity_mps = hermite(a.rod_velocity_mps, a.accel_mps2, b.rod_velocity_mps, b.accel_mps2);
    r.load_cell_force_N = linear(a.load_cell_force_N, b.load_cell_force_N);
    r.accelerometer_mps2 = linear(a.accelerometer_mps2, b.accelerometer_mps2);
    r.xddot_mps2 = linear(a.xddot_mps2, b.xddot_mps2);
  }
  return out;
}

}  // namespace hertzdash
