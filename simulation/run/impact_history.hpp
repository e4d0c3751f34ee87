#pragma once
// One impact as a function of time since contact onset, so runs with different
// contact times (a band over a parameter) can be sampled on one common time grid.
//   tau < 0:          free fall towards the ball:  x = v0 tau + g tau^2 / 2   (exact)
//   0 <= tau <= tc:   the integrator's contact trace, linear between its steps
//                     (run with a bounded step so the interpolation error is below
//                     plotting resolution: O(dt^2 max|x''|)).
//   tau > tc:         free flight after separation: x = x_s + v_s s + g s^2 / 2   (exact)
// x is the deformation = rod displacement since contact onset, downward positive.
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

namespace hertzdash {

/// The rod's state at one instant [SI]: displacement since onset, velocity and
/// acceleration downward positive, contact force compressive positive.
struct ImpactState {
  double displacement_m, velocity_mps, accel_mps2, force_N;
};

/// What the instruments of the drop test read at one instant [SI], in the measured-trace
/// conventions (data/measurements/README.md): the load cell's force (rigid base: the contact
/// force), the accelerometer, the rod's velocity and its displacement since contact onset.
struct InstrumentReading {
  double force_N, accel_mps2, velocity_mps, displacement_m;
};

/// The reading of one channel by its measured-trace name (force_N, accel_mps2, velocity_mps,
/// displacement_m; io/measured_trace.hpp).
inline double instrument_channel(const InstrumentReading& r, const std::string& channel) {
  if (channel == "force_N") return r.force_N;
  if (channel == "accel_mps2") return r.accel_mps2;
  if (channel == "velocity_mps") return r.velocity_mps;
  if (channel == "displacement_m") return r.displacement_m;
  throw std::invalid_argument("instrument_channel: no channel " + channel);
}

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
    const Bracket b = bracket(tau);
    if (b.before_onset) {
      const TraceSample& a = trace_.front();
      return {a.xdot_mps * tau + 0.5 * g_ * tau * tau, a.xdot_mps + g_ * tau, g_, 0.0};
    }
    if (b.after_contact) {
      const TraceSample& e = trace_.back();
      const double s = tau - contact_time_s();
      return {e.x_m + e.xdot_mps * s + 0.5 * g_ * s * s, e.xdot_mps + g_ * s, g_, 0.0};
    }
    auto lerp = [&](double TraceSample::*f) { return b.lo->*f + b.w * (b.hi->*f - b.lo->*f); };
    return {lerp(&TraceSample::x_m), lerp(&TraceSample::xdot_mps), lerp(&TraceSample::accel_mps2),
            lerp(&TraceSample::force_N)};
  }

  /// The instruments at time tau [s] since contact onset. Outside the contact trace the rod is in
  /// free flight and the instruments read no force and g (for the elastic rod this neglects the
  /// ringing after separation).
  InstrumentReading instruments_at(double tau) const {
    const TraceSample& a = trace_.front();
    const Bracket b = bracket(tau);
    if (b.before_onset) return {0.0, g_, a.rod_velocity_mps + g_ * tau, a.rod_velocity_mps * tau + 0.5 * g_ * tau * tau};
    if (b.after_contact) {
      const TraceSample& e = trace_.back();
      const double s = tau - contact_time_s();
      return {0.0, g_, e.rod_velocity_mps + g_ * s,
              e.rod_displacement_m - a.rod_displacement_m + e.rod_velocity_mps * s + 0.5 * g_ * s * s};
    }
    auto lerp = [&](double TraceSample::*f) { return b.lo->*f + b.w * (b.hi->*f - b.lo->*f); };
    return {lerp(&TraceSample::load_cell_force_N), lerp(&TraceSample::accelerometer_mps2),
            lerp(&TraceSample::rod_velocity_mps), lerp(&TraceSample::rod_displacement_m) - a.rod_displacement_m};
  }

 private:
  // Where tau lies: before onset, after the contact, or between two samples (weight w of hi).
  struct Bracket {
    bool before_onset = false, after_contact = false;
    const TraceSample *lo = nullptr, *hi = nullptr;
    double w = 0;
  };
  Bracket bracket(double tau) const {
    if (tau <= 0) return {.before_onset = true};
    if (tau >= contact_time_s()) return {.after_contact = true};
    const double t = t0_ + tau;
    const auto hi = std::upper_bound(trace_.begin(), trace_.end(), t,
                                     [](double v, const TraceSample& r) { return v < r.t_s; });
    return {.lo = &*(hi - 1), .hi = &*hi, .w = (t - (hi - 1)->t_s) / (hi->t_s - (hi - 1)->t_s)};
  }

  std::vector<TraceSample> trace_;
  double g_;
  double t0_;
};

}  // namespace hertzdash
