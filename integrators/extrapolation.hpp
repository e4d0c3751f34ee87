#pragma once
// Adaptive Gragg-Bulirsch-Stoer extrapolation of order 8 ("gbs8") with events landed
// on, for smooth right-hand sides.
//
// Method (Hairer, Norsett, Wanner, Solving ODEs I, sec. II.9): one step of size H from
// (t, y) runs the explicit midpoint rule with n_j = 2, 4, 6, 8 substeps of h_j = H/n_j,
//   z_0 = y, z_1 = y + h_j f(t, y), z_{m+1} = z_{m-1} + 2 h_j f(t + m h_j, z_m),
// whose end value T_j1 = z_{n_j} has an error expansion in even powers of h_j (Gragg;
// no smoothing step). Aitken-Neville extrapolation in h^2,
//   T_{j,k+1} = T_jk + (T_jk - T_{j-1,k}) / ((n_j / n_{j-k})^2 - 1),
// gives T_44 of order 8 (propagated: local extrapolation) and T_43 of order 6, whose
// difference estimates the error: ||T_44 - T_43|| in the weighted RMS norm of
// dormand_prince.hpp (absolute tolerances from the system's scales), accepted when <= 1; next step H 0.9 err^{-1/7}, within
// [0.2 H, 4 H] (no growth right after a rejection). f(t, y) is shared by the four
// sequences, and f at the new point is the next step's first evaluation: an accepted
// step costs 1 + 3 + 5 + 7 + 1 = 17 evaluations.
// Why for this project: the four midpoint sequences are independent chains of
// evaluations, so the processor overlaps them, where the stages of a Runge-Kutta step
// form one dependent chain; for a small system whose cost is the latency of each
// evaluation, order 8 then costs little more per step than order 5 and takes far
// fewer steps. Only for right-hand sides smooth over each step: use it on the contact
// in regularising variables (model/contact_system.hpp), not on the square-root
// singularities of the physical variables.
//
// Events: after each accepted step, a g_i that went from > 0 to <= 0 is located on the
// cubic Hermite interpolant of (y, f) at both ends (Illinois regula falsi, no
// evaluation); the step is re-taken to end exactly there, the events located there are
// handled, and a `restart` action restarts the method from that point. The location
// is accurate to O(H^4) of the interpolant, not to the order of the method; where a
// quantity is read at an event at which it is stationary (a peak, or the separation
// of the regularised contact, where dt/dtau = 2u and dv/dtau vanish) that error
// enters squared.
//
// No allocation: all state is fixed-size on the stack.
#include "hertzdash/integrators/dormand_prince.hpp"  // weighted_rms, the first-step heuristic
#include "hertzdash/integrators/event_landing.hpp"
#include "hertzdash/integrators/work_bound.hpp"
#include "hertzdash/ode/ode_system.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace hertzdash {

struct ExtrapolationOptions {
  double rtol = 1e-8;        ///< relative tolerance, > 0
  double atol = 1e-12;       ///< absolute tolerance relative to the system's state scales, > 0
  double max_step = 0.0;     ///< largest step (units of the independent variable); 0: no limit
  long max_steps = 1000000;  ///< accepted plus rejected steps before giving up
};

namespace detail {

/// One extrapolation step of size H from (t, y) with f0 = f(t, y): y1 = T_44 and the
/// weighted RMS of T_44 - T_43. Adds 16 to `evaluations`.
template <OdeSystem S>
double extrapolation_step(const S& sys, double t, const typename S::State& y, const typename S::State& f0, double H,
                          double rtol, const typename S::State& atol, typename S::State& y1, long& evaluations) {
  using State = typename S::State;
  constexpr std::array<int, 4> n{2, 4, 6, 8};
  std::array<State, 4> T;
  for (int j = 0; j < 4; ++j) {
    const double h = H / n[j];
    State z_previous = y, z = y + h * f0, f;
    for (int m = 1; m < n[j]; ++m) {
      sys.rhs(t + m * h, z, f);
      const State z_next = z_previous + (2 * h) * f;
      z_previous = z;
      z = z_next;
    }
    T[j] = z;
  }
  evaluations += 16;
  // Aitken-Neville in place: after pass k, T[j] holds T_{j+1,k+1} (1-based indices).
  auto pass = [&](int k) {
    for (int j = 3; j >= k; --j) {
      const double r = static_cast<double>(n[j]) / n[j - k];
      T[j] += (T[j] - T[j - 1]) / (r * r - 1);
    }
  };
  pass(1);
  pass(2);
  const State order6 = T[3];
  pass(3);
  y1 = T[3];
  return weighted_rms(State(T[3] - order6), y, y1, rtol, atol);
}

/// The cubic Hermite interpolant of (y0, f0) and (y1, f1) over a step of size H.
template <class State>
struct HermiteCubic {
  State y0, y1, d0, d1;  ///< d = H f
  State at(double s) const {
    const double r = 1 - s;
    return (r * r * (1 + 2 * s)) * y0 + (s * r * r) * d0 + (s * s * (3 - 2 * s)) * y1 - (s * s * r) * d1;
  }
};

template <OdeSystem S, class Observer>
class ExtrapolationRun {
  using State = typename S::State;
  using Events = typename S::Events;
  static constexpr double safety = 0.9, min_factor = 0.2, max_factor = 4.0;

 public:
  ExtrapolationRun(S& sys, State& y, double t0, double t_end, const ExtrapolationOptions& opt, Observer& observer)
      : sys_(sys), y_(y), t_(t0), t_end_(t_end), opt_(opt), observer_(observer) {}

  IntegrationStats run() {
    detail::require_max_step_reach("extrapolation", t_, t_end_, opt_.max_step, static_cast<double>(opt_.max_steps));
    sys_.events(t_, y_, g_);
    observer_.on_step(t_, y_);
    restart();
    bool rejected_last = false;
    for (long attempts = 0; t_ < t_end_; ++attempts) {
      if (attempts >= opt_.max_steps) throw std::runtime_error("integrate_extrapolation: too many steps");
      double H = std::min(H_, t_end_ - t_);
      if (opt_.max_step > 0) H = std::min(H, opt_.max_step);
      const double err = extrapolation_step(sys_, t_, y_, f_, H, opt_.rtol, atol_, y1_, stats_.rhs_evaluations);
      if (!(err <= 1.0)) {
        if (!std::isfinite(err)) throw std::runtime_error("integrate_extrapolation: non-finite error estimate");
        H_ = H * std::max(min_factor, safety * std::pow(err, -1.0 / 7));
        rejected_last = true;
        continue;
      }
      H_ = H * std::clamp(err > 0 ? safety * std::pow(err, -1.0 / 7) : max_factor, min_factor,
                          rejected_last ? 1.0 : max_factor);
      rejected_last = false;
      accept(H, H == t_end_ - t_);
      if (stats_.stopped_by_event) return stats_;
    }
    stats_.t_final = t_;
    return stats_;
  }

 private:
  /// Move to the end t_new of the step whose result is y1_ (f1 = f(t_new, y1_)).
  void advance(double t_new, const State& f1) {
    t_ = t_new;
    y_ = y1_;
    f_ = f1;
    ++stats_.steps;
    observer_.on_step(t_, y_);
  }

  /// Accept the step of size H to y1_, or land on the earliest event crossing in it.
  void accept(double H, bool to_end) {
    State f1;
    sys_.rhs(t_ + H, y1_, f1);
    ++stats_.rhs_evaluations;
    Events g_end;
    sys_.events(t_ + H, y1_, g_end);
    if (!any_event_crossed(g_, g_end)) {
      advance(to_end ? t_end_ : t_ + H, f1);
      g_ = g_end;
      return;
    }
    const HermiteCubic<State> dense{y_, y1_, H * f_, H * f1};
    const auto crossings = locate_event_crossings(sys_, t_, H, g_, g_end, dense);
    const double t_start = t_;
    const Events g_start = g_;
    land(t_ + crossings.earliest * H, to_end && crossings.earliest == 1.0);
    if (fire_landed_events(sys_, t_, y_, g_, g_start, t_start, H, crossings, stats_, observer_) == EventAction::restart)
      restart();
  }

  /// Reach t_star exactly: steps of at most the remaining distance, error controlled.
  void land(double t_star, bool to_end) {
    double H = t_star - t_;
    while (t_star - t_ > 0) {
      const double d = t_star - t_;
      H = std::min(H, d);
      const double err = extrapolation_step(sys_, t_, y_, f_, H, opt_.rtol, atol_, y1_, stats_.rhs_evaluations);
      if (!(err <= 1.0)) {
        if (!std::isfinite(err)) throw std::runtime_error("integrate_extrapolation: non-finite error estimate");
        H *= std::max(min_factor, safety * std::pow(err, -1.0 / 7));
        continue;
      }
      const bool last = H == d;
      State f1;
      sys_.rhs(t_ + H, y1_, f1);
      ++stats_.rhs_evaluations;
      advance(last ? (to_end ? t_end_ : t_star) : t_ + H, f1);
      if (last) return;
    }
  }

  /// (Re)start at (t_, y_): the system's scales read afresh, f there and a first step from
  /// the Hairer-Norsett-Wanner heuristic (sized for order 5, so on the safe side; the step
  /// grows 4x per step).
  void restart() {
    atol_ = absolute_tolerance(sys_, y_, opt_.atol);
    sys_.rhs(t_, y_, f_);
    ++stats_.rhs_evaluations;
    H_ = dormand_prince_initial_step(sys_, t_, y_, f_, t_end_ - t_, opt_.rtol, atol_, opt_.max_step,
                                     stats_.rhs_evaluations);
  }

  S& sys_;
  State& y_;
  double t_, t_end_;
  double H_ = 0;  ///< the next step size to try
  const ExtrapolationOptions& opt_;
  Observer& observer_;
  IntegrationStats stats_;
  Events g_;      ///< event functions at (t_, y_)
  State f_, y1_;  ///< f(t_, y_); the result of the last step tried
  State atol_;    ///< absolute tolerance of each component (since the last restart)
};

}  // namespace detail

/// Integrate `sys` from (t0, y) towards t_end with the order-8 extrapolation method; y is updated in place.
template <OdeSystem S, IntegrationObserver<typename S::State> Observer>
IntegrationStats integrate_extrapolation(S& sys, typename S::State& y, double t0, double t_end,
                                         const ExtrapolationOptions& opt, Observer& observer) {
  if (!(opt.rtol > 0)) throw std::invalid_argument("integrate_extrapolation: rtol must be > 0");
  if (!(opt.atol > 0)) throw std::invalid_argument("integrate_extrapolation: atol must be > 0");
  return detail::ExtrapolationRun<S, Observer>(sys, y, t0, t_end, opt, observer).run();
}

}  // namespace hertzdash
