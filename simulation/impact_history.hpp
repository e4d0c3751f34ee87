#pragma once
// One impact as a function of time since contact onset, so runs with different
// contact times (a band over a parameter) can be sampled on one common time grid.
//   tau < 0:          free fall towards the ball:  x = v0 tau + g tau^2 / 2   (exact)
//   0 <= tau <= tc:   the integrator's contact trace, linear between its steps
//                     (run with a bounded step so the interpolation error is below
//                     plotting resolution: O(dt^2 max|x''|)).
//   tau > tc:         free flight after separation: x = x_s + v_s s + g s^2 / 2   (exact)
// x is the deformation = rod displacement since contact onset, downward positive.
#include "hertzdash/simulation/impact_simulator.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace hertzdash {

/// The rod's state at one instant [SI]: displacement since onset, velocity and
/// acceleration downward positive, contact force compressive positive.
struct ImpactState {
  double displacement_m, velocity_mps, accel_mps2, force_N;
};

class ImpactHistory {
 public:
  /// `trace` is the contact phase of one run (ImpactSimulator::run with a trace) that separated.
  ImpactHistory(std::vector<TraceSample> trace, double gravity_mps2)
      : trace_(std::move(trace)), g_(gravity_mps2) {
    if (trace_.size() < 2) throw std::invalid_argument("ImpactHistory: a contact trace needs two samples");
    t0_ = trace_.front().t_s;
  }

  double contact_time_s() const { return trace_.back().t_s - t0_; }

  /// State at time tau [s] since contact onset.
  ImpactState at(double tau) const {
    if (tau <= 0) {
      const TraceSample& a = trace_.front();
      return {a.xdot_mps * tau + 0.5 * g_ * tau * tau, a.xdot_mps + g_ * tau, g_, 0.0};
    }
    if (tau >= contact_time_s()) {
      const TraceSample& b = trace_.back();
      const double s = tau - contact_time_s();
      return {b.x_m + b.xdot_mps * s + 0.5 * g_ * s * s, b.xdot_mps + g_ * s, g_, 0.0};
    }
    const double t = t0_ + tau;
    const auto hi = std::upper_bound(trace_.begin(), trace_.end(), t,
                                     [](double v, const TraceSample& r) { return v < r.t_s; });
    const TraceSample& b = *hi;
    const TraceSample& a = *(hi - 1);
    const double w = (t - a.t_s) / (b.t_s - a.t_s);
    auto lerp = [w](double p, double q) { return p + w * (q - p); };
    return {lerp(a.x_m, b.x_m), lerp(a.xdot_mps, b.xdot_mps), lerp(a.accel_mps2, b.accel_mps2),
            lerp(a.force_N, b.force_N)};
  }

 private:
  std::vector<TraceSample> trace_;
  double g_;
  double t0_;
};

}  // namespace hertzdash
