#pragma once
// Adaptive Dormand-Prince 5(4) with dense output and event location that lands
// steps on the events.
//
// Method (J. R. Dormand, P. J. Prince, J. Comput. Appl. Math. 6 (1980) 19-26;
// dense output of L. F. Shampine, Math. Comp. 46 (1986) 135-150, as in Hairer,
// Norsett, Wanner, Solving ODEs I, sec. II.6):
//   seven stages, the seventh evaluated at the new point (first-same-as-last,
//   so an accepted step costs 6 right-hand-side evaluations), order 5 solution
//   propagated (local extrapolation), order 4 embedded solution for the error
//   estimate, and a continuous extension of order 4 that costs no evaluation:
//     y(t + theta h) = y0 + theta (r1 + (1-theta) (r2 + theta (r3 + (1-theta) r4))),
//     r1 = y1 - y0, r2 = h k1 - r1, r3 = r1 - h k7 - r2, r4 = h sum_i d_i k_i.
//   The coefficients below were checked in exact rational arithmetic: b and the
//   embedded b* satisfy all order conditions up to order 4 (b up to 5), and the
//   continuous weights b_i(theta) satisfy the order-4 conditions at every theta.
//
// Step control: the error estimate e = y1 - y1* is measured in the weighted RMS
// norm ||e|| = sqrt(mean_i (e_i / (atol_i + rtol max(|y0_i|, |y1_i|)))^2), atol_i = atol
// x the system's scale of component i (ode/ode_system.hpp, absolute_tolerance); a step is
// accepted when ||e|| <= 1 and the next step is h 0.9 ||e||^{-1/5}, limited to
// [0.2 h, 5 h] (no growth right after a rejection). After two rejections at one
// point the shrink uses the order those two attempts show (|e| ~ h^p, p in
// [0.5, 5]) instead of 5. The first step, and the first after every restart, is
// sized by Hairer-Norsett-Wanner I, II.4 (one extra evaluation), in the same norm.
// The scales are read at the start and after every restart.
//
// Singular points. A right-hand side is often only continuous where an event
// restarts it: the contact force grows like sqrt(t - t_on) after onset and, for a
// damped law, vanishes like sqrt(t_s - t) before separation. For a step that starts
// on such a point the embedded estimate misses the true error of the order-5
// solution by a factor 37 (5 if the point lies h/4 before the step, 1.1 if h before).
// Hence: (i) the first step after a restart is checked by step doubling (one step of
// h against two of h/2, 18 evaluations; the two halves are kept), which measures the
// error whatever its form; (ii) the steps after it are no longer than the time since
// the restart, where the embedded estimate is reliable; (iii) the step that lands on
// an event is checked by step doubling too, and while the check fails an ordinary
// step of half the remaining distance or less goes first. With these the global error
// is proportional to the tolerance (local extrapolation: local error O(tol^{6/5}) per
// step times O(tol^{-1/5}) steps), where without them it was tens of times larger.
// A system that is smooth at its restarts and events (options.singular_points =
// false) needs none of (i)-(iii), and every step is then an ordinary one.
//
// Events: after each accepted step, a g_i that went from > 0 to <= 0 is located on
// the dense output (Illinois regula falsi on theta -> g_i(t + theta h, y(theta)):
// no right-hand-side evaluation). The step is then re-taken with exactly the length
// that ends at the earliest crossing (checked as in (iii)), the events located there
// are handled, and a `restart` action restarts the method from that point with the
// new right-hand side. So no step straddles an event: the contact force law never
// changes inside a step.
//
// No allocation: all state is fixed-size (Eigen::Matrix<double, N, 1>) on the stack.
#include "hertzdash/integrators/event_landing.hpp"
#include "hertzdash/integrators/work_bound.hpp"
#include "hertzdash/ode/ode_system.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <cmath>
#include <stdexcept>

namespace hertzdash {

struct DormandPrinceOptions {
  double rtol = 1e-8;        ///< relative tolerance, > 0
  double atol = 1e-12;       ///< absolute tolerance relative to the system's state scales, > 0
  double max_step = 0.0;     ///< largest step [s]; 0 means no limit
  long max_steps = 1000000;  ///< accepted plus rejected steps before giving up
  /// The right-hand side may be singular where an event restarts it or lands a step
  /// (a sqrt(t - t_on) force): check those steps by step doubling (see "Singular
  /// points"). false for a system smooth there (e.g. the contact in regularising
  /// variables, model/contact_system.hpp): every step is then controlled by
  /// the embedded estimate alone.
  bool singular_points = true;
};

namespace detail {

/// The Dormand-Prince 5(4) tableau (c, a, b = the seventh row of a, error weights
/// e = b - b*, dense-output weights d).
struct DormandPrinceTableau {
  static constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
  static constexpr double a21 = 1.0 / 5;
  static constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
  static constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
  static constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
  static constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                          a65 = -5103.0 / 18656;
  static constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784, b6 = 11.0 / 84;
  static constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                          e6 = 22.0 / 525, e7 = -1.0 / 40;
  static constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                          d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                          d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
};

/// Per-run workspace of one step: the stages and the new point.
template <class State>
struct DormandPrinceStep {
  State k1, k2, k3, k4, k5, k6, k7;  ///< stage derivatives; k1 = f(t, y), k7 = f(t + h, y1)
  State y1;                          ///< order-5 solution at t + h
};

/// One step of size h from (t, y) with k1 = f(t, y) given: fills k2..k7 and y1 (6 evaluations).
/// Each stage point is summed as y + (h a_j1) k1 + ... + (h a_j,j-1) k_j-1, left to
/// right, so the stage just computed enters with one product and one sum: the
/// stages form a chain of dependent evaluations, and this keeps it short.
template <OdeSystem S>
void dormand_prince_step(const S& sys, double t, const typename S::State& y, double h,
                         DormandPrinceStep<typename S::State>& w) {
  using T = DormandPrinceTableau;
  typename S::State z;
  z = y + (h * T::a21) * w.k1;
  sys.rhs(t + T::c2 * h, z, w.k2);
  z = y + (h * T::a31) * w.k1 + (h * T::a32) * w.k2;
  sys.rhs(t + T::c3 * h, z, w.k3);
  z = y + (h * T::a41) * w.k1 + (h * T::a42) * w.k2 + (h * T::a43) * w.k3;
  sys.rhs(t + T::c4 * h, z, w.k4);
  z = y + (h * T::a51) * w.k1 + (h * T::a52) * w.k2 + (h * T::a53) * w.k3 + (h * T::a54) * w.k4;
  sys.rhs(t + T::c5 * h, z, w.k5);
  z = y + (h * T::a61) * w.k1 + (h * T::a62) * w.k2 + (h * T::a63) * w.k3 + (h * T::a64) * w.k4 +
      (h * T::a65) * w.k5;
  sys.rhs(t + h, z, w.k6);
  w.y1 = y + (h * T::b1) * w.k1 + (h * T::b3) * w.k3 + (h * T::b4) * w.k4 + (h * T::b5) * w.k5 + (h * T::b6) * w.k6;
  sys.rhs(t + h, w.y1, w.k7);
}

/// Weighted RMS norm of v with weights atol_i + rtol max(|a_i|, |b_i|).
template <class State>
double weighted_rms(const State& v, const State& a, const State& b, double rtol, const State& atol) {
  const auto scale = (atol.array() + rtol * a.cwiseAbs().cwiseMax(b.cwiseAbs()).array());
  return std::sqrt((v.array() / scale).square().mean());
}

/// The continuous extension over one accepted step [t, t + h].
template <class State>
struct DormandPrinceDense {
  State r0, r1, r2, r3, r4;
  void build(const State& y0, double h, const DormandPrinceStep<State>& w) {
    using T = DormandPrinceTableau;
    r0 = y0;
    r1 = w.y1 - y0;
    r2 = h * w.k1 - r1;
    r3 = r1 - h * w.k7 - r2;
    r4 = h * (T::d1 * w.k1 + T::d3 * w.k3 + T::d4 * w.k4 + T::d5 * w.k5 + T::d6 * w.k6 + T::d7 * w.k7);
  }
  State at(double theta) const {
    const double s = 1.0 - theta;
    return r0 + theta * (r1 + s * (r2 + theta * (r3 + s * r4)));
  }
};

/// First step size (Hairer-Norsett-Wanner I, II.4): one explicit Euler trial step; norms
/// weighted by atol_i + rtol |y_i|.
template <OdeSystem S>
double dormand_prince_initial_step(const S& sys, double t, const typename S::State& y, const typename S::State& f0,
                                   double span, double rtol, const typename S::State& atol, double max_step,
                                   long& rhs_evaluations) {
  using State = typename S::State;
  const double d0 = weighted_rms(y, y, y, rtol, atol);
  const double d1 = weighted_rms(f0, y, y, rtol, atol);
  double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 * span : 0.01 * d0 / d1;
  h0 = std::min(h0, span);
  const State y1 = y + h0 * f0;
  State f1;
  sys.rhs(t + h0, y1, f1);
  ++rhs_evaluations;
  const double d2 = weighted_rms(State(f1 - f0), y, y, rtol, atol) / h0;
  const double dmax = std::max(d1, d2);
  const double h1 = dmax <= 1e-15 ? std::max(1e-6 * span, 1e-3 * h0) : std::pow(0.01 / dmax, 0.2);
  double h = std::min({100 * h0, h1, span});
  if (max_step > 0) h = std::min(h, max_step);
  return h;
}

}  // namespace detail

namespace detail {

/// One integration: the per-run workspace and the steps of the algorithm.
template <OdeSystem S, class Observer>
class DormandPrinceRun {
  using State = typename S::State;
  using Events = typename S::Events;
  using Step = DormandPrinceStep<State>;
  static constexpr double safety = 0.9, min_factor = 0.2, max_factor = 5.0;

 public:
  DormandPrinceRun(S& sys, State& y, double t0, double t_end, const DormandPrinceOptions& opt, Observer& observer)
      : sys_(sys), y_(y), t_(t0), t_end_(t_end), t_restart_(t0), opt_(opt), observer_(observer) {}

  IntegrationStats run() {
    detail::require_max_step_reach("Dormand-Prince", t_, t_end_, opt_.max_step, static_cast<double>(opt_.max_steps));
    sys_.events(t_, y_, g_);
    observer_.on_step(t_, y_);
    restart();
    bool rejected_last = false;
    for (long attempts = 0; t_ < t_end_; ++attempts) {
      if (attempts >= opt_.max_steps) throw std::runtime_error("integrate_dormand_prince: too many steps");
      double h = std::min(h_, t_end_ - t_);
      if (opt_.max_step > 0) h = std::min(h, opt_.max_step);
      // The right-hand side may be singular at the last restart (sqrt(t - t_restart)
      // after contact onset). The embedded estimate of a step [t, t + h] misses such an
      // error by a factor 37 when t = t_restart, 5 when h = 4 (t - t_restart), and
      // 1.1 when h = t - t_restart. So the first step after a restart is checked by step
      // doubling, and the following ones are no longer than the time since the restart.
      const bool near_restart = opt_.singular_points && t_ == t_restart_;
      if (opt_.singular_points && !near_restart) h = std::min(h, t_ - t_restart_);
      const double err = near_restart ? doubling_error(h) : embedded_error(h);
      if (!(err <= 1.0)) {
        if (!std::isfinite(err)) throw std::runtime_error("integrate_dormand_prince: non-finite error estimate");
        // Shrink by (0.9/err)^{1/5}, the order of the estimate if the solution is
        // smooth. After a second rejection at the same point, use the order the two
        // attempts show instead (3/2 at a square-root singularity), so that a
        // singular start costs two or three attempts rather than ten.
        double factor = std::max(min_factor, safety * fifth_root_inverse(err));
        if (rejected_last && rejected_t_ == t_ && rejected_err_ > err) {
          const double order = std::clamp(std::log(rejected_err_ / err) / std::log(rejected_h_ / h), 0.5, 5.0);
          factor = std::min(factor, std::pow(safety / err, 1.0 / order));
        }
        rejected_t_ = t_, rejected_h_ = h, rejected_err_ = err;
        h_ = h * factor;
        rejected_last = true;
        continue;
      }
      const double factor =
          std::clamp(err > 0 ? safety * fifth_root_inverse(err) : max_factor, min_factor, rejected_last ? 1.0 : max_factor);
      rejected_last = false;
      h_ = h * factor;
      // Accept: the step itself, or (near a restart) its two more accurate halves.
      const bool to_end = h == t_end_ - t_;
      if (near_restart) {
        const Step second = half2_;  // accept() overwrites the workspaces when it lands on an event
        if (!accept(half1_, 0.5 * h, false)) accept(second, 0.5 * h, to_end);
      } else {
        accept(w_, h, to_end);
      }
      if (stats_.stopped_by_event) return stats_;
    }
    stats_.t_final = t_;
    return stats_;
  }

 private:
  /// x^{-1/5} for the step-size update. A heuristic needs ~1%, not pow's 1 ulp (pow
  /// was a tenth of the run time): the exponent-field estimate y = x^{-1/5} read off
  /// the float bit pattern (bits(y) ~ (6/5) bits(1) - bits(x)/5, within 15%), then
  /// one Newton step on x y^5 = 1, y <- y (6 - x y^5)/5 (error squared: < 3%).
  static double fifth_root_inverse(double x) {
    const float xf = static_cast<float>(std::clamp(x, 1e-30, 1e30));
    const auto bits = std::bit_cast<std::uint32_t>(xf);
    constexpr std::uint32_t one = 0x3f800000u;  // bits of 1.0f
    float y = std::bit_cast<float>(static_cast<std::uint32_t>(one + one / 5 - bits / 5));
    const float y2 = y * y;
    y = y * (6.0f - xf * y2 * y2 * y) * 0.2f;
    return y;
  }

  /// One step of length h into w_; its embedded error estimate (weighted RMS).
  double embedded_error(double h) {
    dormand_prince_step(sys_, t_, y_, h, w_);
    stats_.rhs_evaluations += 6;
    using T = DormandPrinceTableau;
    const State err = h * (T::e1 * w_.k1 + T::e3 * w_.k3 + T::e4 * w_.k4 + T::e5 * w_.k5 + T::e6 * w_.k6 + T::e7 * w_.k7);
    return weighted_rms(err, y_, w_.y1, opt_.rtol, atol_);
  }

  /// One step of length h into w_ and two of h/2 into half1_, half2_; the
  /// difference of the two results estimates the error of the single step whatever
  /// the form of the local error (h^6 if smooth, h^{3/2} at a square-root
  /// singularity), and bounds that of the two halves, which are kept.
  double doubling_error(double h) {
    dormand_prince_step(sys_, t_, y_, h, w_);
    half1_.k1 = w_.k1;
    dormand_prince_step(sys_, t_, y_, 0.5 * h, half1_);
    half2_.k1 = half1_.k7;
    dormand_prince_step(sys_, t_ + 0.5 * h, half1_.y1, 0.5 * h, half2_);
    stats_.rhs_evaluations += 18;
    return weighted_rms(State(half2_.y1 - w_.y1), y_, half2_.y1, opt_.rtol, atol_);
  }

  /// Move to the end t_new of the accepted step `ws` from (t_, y_).
  void advance(const Step& ws, double t_new) {
    t_ = t_new;
    y_ = ws.y1;
    w_.k1 = ws.k7;
    ++stats_.steps;
    observer_.on_step(t_, y_);
  }

  /// Accept the step `ws` of length h from (t_, y_), or, if an event function
  /// crosses zero within it, land on the earliest crossing instead. Returns true if
  /// the step was cut short by an event (the rest of it is then void).
  bool accept(const Step& ws, double h, bool to_end) {
    Events g_end;
    sys_.events(t_ + h, ws.y1, g_end);
    if (!any_event_crossed(g_, g_end)) {
      advance(ws, to_end ? t_end_ : t_ + h);
      g_ = g_end;
      return false;
    }
    // Locate every crossing on the dense output (no evaluations); land on the earliest
    // and fire the events there.
    dense_.build(y_, h, ws);
    const auto crossings = locate_event_crossings(sys_, t_, h, g_, g_end, dense_);
    const Events g_start = g_;
    const double t_start = t_;
    land(t_ + crossings.earliest * h, to_end && crossings.earliest == 1.0);
    if (fire_landed_events(sys_, t_, y_, g_, g_start, t_start, h, crossings, stats_, observer_) == EventAction::restart)
      restart();
    return true;
  }

  /// Reach t_star exactly. The step that ends on an event may end on a singularity
  /// of the solution (sqrt(t_star - t) at separation), so it is checked by step
  /// doubling; while the check fails, an ordinary step of half the distance or less
  /// (checked by its embedded estimate, reliable that far from t_star) goes first.
  void land(double t_star, bool to_end) {
    if (!opt_.singular_points) {
      // Smooth at t_star: one ordinary step, shortened while its estimate fails.
      for (;;) {
        const double d = t_star - t_;
        if (d <= 0) return;
        double h = d;
        for (int k = 0; k < 60 && !(embedded_error(h) <= 1.0); ++k) h *= 0.5;
        advance(w_, h == d ? (to_end ? t_end_ : t_star) : t_ + h);
      }
    }
    for (int tries = 0;; ++tries) {
      const double d = t_star - t_;
      if (d <= 0) return;
      const double err = doubling_error(d);
      if (err <= 1.0 || tries >= 40) {
        const Step second = half2_;
        advance(half1_, t_ + 0.5 * d);
        advance(second, to_end ? t_end_ : t_star);
        return;
      }
      double h = 0.5 * d;
      for (int k = 0; k < 60 && !(embedded_error(h) <= 1.0); ++k) h *= 0.5;
      advance(w_, t_ + h);
    }
  }

  /// (Re)start the method at (t_, y_): nothing carries over but the state; the
  /// system's scales are read afresh.
  void restart() {
    t_restart_ = t_;
    atol_ = absolute_tolerance(sys_, y_, opt_.atol);
    sys_.rhs(t_, y_, w_.k1);
    ++stats_.rhs_evaluations;
    h_ = dormand_prince_initial_step(sys_, t_, y_, w_.k1, t_end_ - t_, opt_.rtol, atol_, opt_.max_step,
                                     stats_.rhs_evaluations);
  }

  S& sys_;
  State& y_;
  double t_, t_end_, t_restart_;
  double h_ = 0;  ///< the next step size to try [s]
  double rejected_t_ = 0, rejected_h_ = 0, rejected_err_ = 0;  ///< the last rejected attempt
  const DormandPrinceOptions& opt_;
  Observer& observer_;
  IntegrationStats stats_;
  Events g_;                      ///< event functions at (t_, y_)
  State atol_;                    ///< absolute tolerance of each component (since the last restart)
  Step w_, half1_, half2_;        ///< w_.k1 = f(t_, y_) between steps
  DormandPrinceDense<State> dense_;
};

}  // namespace detail

/// Integrate `sys` from (t0, y) towards t_end with Dormand-Prince 5(4); y is updated in place.
template <OdeSystem S, IntegrationObserver<typename S::State> Observer>
IntegrationStats integrate_dormand_prince(S& sys, typename S::State& y, double t0, double t_end,
                                          const DormandPrinceOptions& opt, Observer& observer) {
  if (!(opt.rtol > 0)) throw std::invalid_argument("integrate_dormand_prince: rtol must be > 0");
  if (!(opt.atol > 0)) throw std::invalid_argument("integrate_dormand_prince: atol must be > 0");
  return detail::DormandPrinceRun<S, Observer>(sys, y, t0, t_end, opt, observer).run();
}

}  // namespace hertzdash
