#pragma once
// Adaptive Taylor-series integrator for polynomial right-hand sides, with events
// located on the series.
//
// Method (Jorba and Zou, Experimental Mathematics 14 (2005) 99-117): for an autonomous
// y' = f(y) with f a polynomial, the Taylor coefficients y_k of the solution at the
// step's start follow from y_0 = y by the recurrence y_{k+1} = f(y)_k / (k + 1), with f
// evaluated on truncated power series (power_series.hpp): O(p^2) work per product in f
// for order p, no right-hand-side evaluation in the usual sense. One step of size h
// is then y(t + s) = sum_{k <= p} y_k s^k.
//   Order from the tolerance: p = ceil(-0.6 ln(rtol)) + 1 within [6, 30], so that the
// step size below, in units of the series' radius of convergence, does not depend on
// the tolerance (Jorba and Zou's optimal order has -ln(rtol)/2, i.e. rtol^{1/p} ~ e^{-2},
// for a cost of p^2 per step; here each step also pays a fixed part -- the step size,
// the state and events at its end -- and the recurrence is bound by the latency of its
// p orders, so fewer, longer steps of a higher order are cheaper: measured on the
// contact workload at rtol 1e-6..1e-12, 0.6 took 7-14 % less time than 0.5 at equal
// error, 0.7 and 0.8 no less than 0.6, with less regular errors).
//   Step from the coefficients' decay: with ||.|| the weighted RMS norm of
// dormand_prince.hpp (scales atol_i + rtol |y_i| at the step's start, atol_i = atol x the
// system's scale of component i, read at the start and after every restart), the last two terms
// of the series are held to the tolerance, h = min over j in {p-1, p} of
// ||y_j||^{-1/j} (lower orders if both vanish): the first neglected term is then about h/rho times the last (rho the
// radius of convergence), so the local error is a fixed fraction of the tolerance and
// the global error proportional to it. No step is ever rejected.
//
// Events: after each step, the system's event functions at the step's end say which
// g_i went from > 0 to <= 0. Only for those, the step's series of g_i itself is
// generated (the system's polynomial_events evaluated on the state's series, one order
// less for an event that is a rate, power_series.hpp's derivative) and its root found
// by safeguarded Newton on that polynomial (Horner with the derivative; a few
// iterations of 2p operations, no evaluation of the system); the state there is the
// series' value, and the events located there are fired
// (integrators/event_landing.hpp). The step is cut at the event: the observer sees the
// event point as a step end. After `continue`, the rest of the step is read from the
// same series (no new coefficients); after `restart` the method restarts there; `stop`
// ends the integration there. Where the series of g_i and the system's g_i disagree on a
// sign at an end of the step (an event function the system differences, say), the
// root is that end.
//
// Only for systems that offer the polynomial form of their right-hand side and event
// functions, `polynomial_rhs(y)` and `polynomial_events(y)` over any ring scalar type
// with a derivative, returning std::tuples of the components of y' and of the events
// (PolynomialOdeSystem below), e.g. the regularised contact
// (model/contact_system.hpp) of a law declaring force_of_root.
//
// Work reported: one right-hand-side evaluation per Taylor coefficient of the state
// (p per step), the closest equivalent of the other integrators' count; the event
// series are not counted.
// No allocation: all state is fixed-size on the stack.
#include "hertzdash/integrators/dormand_prince.hpp"  // weighted_rms scales
#include "hertzdash/integrators/event_landing.hpp"
#include "hertzdash/integrators/power_series.hpp"
#include "hertzdash/ode/ode_system.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>

namespace hertzdash {

struct TaylorOptions {
  double rtol = 1e-8;        ///< relative tolerance, > 0
  double atol = 1e-12;       ///< absolute tolerance relative to the system's state scales, > 0
  long max_steps = 1000000;  ///< steps before giving up
};

/// A system whose right-hand side is an autonomous polynomial, offered over any ring
/// scalar type: polynomial_rhs(y) -> std::tuple of dimension components of y', and its
/// event functions likewise, polynomial_events(y) -> std::tuple of event_count components
/// (equal to events(), or to what events() approximates).
template <class S>
concept PolynomialOdeSystem = OdeSystem<S> && (S::dimension > 0) &&
                              requires(const S& s, const std::array<SeriesVariable, S::dimension>& y) {
                                { std::tuple_size<decltype(s.polynomial_rhs(y))>::value } -> std::convertible_to<std::size_t>;
                                requires std::tuple_size_v<decltype(s.polynomial_rhs(y))> == S::dimension;
                                requires std::tuple_size_v<decltype(s.polynomial_events(y))> == S::event_count;
                              };

/// The Taylor order the integrator uses at relative tolerance rtol.
inline int taylor_order(double rtol) {
  return std::clamp(static_cast<int>(std::ceil(-0.6 * std::log(rtol))) + 1, 6, series_capacity - 2);
}

namespace detail {

template <PolynomialOdeSystem S, class Observer>
class TaylorRun {
  using State = typename S::State;
  using Events = typename S::Events;
  static constexpr int n = S::dimension;
  using Leaves = std::array<SeriesVariable, n>;
  static constexpr int m = S::event_count;
  static_assert(m <= 32, "event_series_ready_ holds a bit per event");
  using Rhs = decltype(std::declval<const S&>().polynomial_rhs(std::declval<const Leaves&>()));
  using EventSeries = decltype(std::declval<const S&>().polynomial_events(std::declval<const Leaves&>()));
  template <class Tuple>
  static constexpr int products_in = []<std::size_t... I>(std::index_sequence<I...>) {
    return series_products<std::tuple_element_t<I, Tuple>...>;
  }(std::make_index_sequence<std::tuple_size_v<Tuple>>{});

 public:
  TaylorRun(S& sys, State& y, double t0, double t_end, const TaylorOptions& opt, Observer& observer)
      : sys_(sys), y_(y), t_(t0), t_end_(t_end), opt_(opt), observer_(observer), order_(taylor_order(opt.rtol)),
        rhs_(sys.polynomial_rhs(leaves())), atol_(absolute_tolerance(sys, y, opt.atol)),
        event_series_(sys.polynomial_events(leaves())) {
    bind_storage();
  }
  TaylorRun(const TaylorRun&) = delete;  // rhs_ reads coefficients_ and storage_ through pointers
  TaylorRun& operator=(const TaylorRun&) = delete;

  IntegrationStats run() {
    sys_.events(t_, y_, g_);
    observer_.on_step(t_, y_);
    for (long steps = 0; t_ < t_end_; ++steps) {
      if (steps >= opt_.max_steps) throw std::runtime_error("integrate_taylor: too many steps");
      generate_coefficients();
      const double h = std::min(step_size(), t_end_ - t_);
      if (!(h > 0)) throw std::runtime_error("integrate_taylor: step size " + std::to_string(h));
      if (finish_step(h)) return stats_;
    }
    stats_.t_final = t_;
    return stats_;
  }

 private:
  Leaves leaves() const {
    Leaves l;
    for (int i = 0; i < n; ++i) l[i] = SeriesVariable{coefficients_[i].data()};
    return l;
  }

  /// Points the product nodes of the right-hand side and of the event series at storage_.
  void bind_storage() {
    std::apply(
        [&](auto&... rhs) { std::apply([&](auto&... events) { storage_.bind(rhs..., events...); }, event_series_); },
        rhs_);
  }

  /// The Taylor coefficients at (t_, y_), orders 0..order_.
  void generate_coefficients() {
    for (int i = 0; i < n; ++i) coefficients_[i][0] = y_[i];
    for (int k = 0; k < order_; ++k) {
      const double inverse = 1.0 / (k + 1);
      [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((std::get<I>(rhs_).update(k), coefficients_[I][k + 1] = std::get<I>(rhs_)[k] * inverse), ...);
      }(std::make_index_sequence<n>{});
    }
    stats_.rhs_evaluations += order_;
    event_series_ready_ = 0;
  }

  /// h = min over j in {p-1, p} of ||y_j||^{-1/j} (weighted RMS norm, scales at y_); if
  /// both vanish (a series with gaps, such as u ~ v0 tau + O(tau^6) at onset without
  /// gravity), the highest nonzero coefficient below them sets h the same way. As
  /// exp(-max_j ln(||y_j||^2) / (2j)): a logarithm per order and one exponential.
  double step_size() const {
    constexpr double none = -std::numeric_limits<double>::infinity();
    double log_inverse_h = none;
    for (int j = order_; j >= 1; --j) {
      double sum = 0;
      for (int i = 0; i < n; ++i) {
        const double r = coefficients_[i][j] / (atol_[i] + opt_.rtol * std::abs(y_[i]));
        sum += r * r;
      }
      if (sum > 0) log_inverse_h = std::max(log_inverse_h, std::log(sum / n) / (2 * j));
      if (j <= order_ - 1 && log_inverse_h > none) break;
    }
    if (!(log_inverse_h > none)) throw std::runtime_error("integrate_taylor: no step size (the series is constant)");
    return std::exp(-log_inverse_h);
  }

  /// The series of event I over this step: coefficients 0..order_ - lost orders.
  template <std::size_t I>
  void generate_event_series() {
    auto& e = std::get<I>(event_series_);
    const int order = order_ - std::tuple_element_t<I, EventSeries>::lost_orders;
    for (int k = 0; k <= order; ++k) {
      e.update(k);
      event_coefficients_[I][k] = e[k];
    }
    event_orders_[I] = order;
  }

  /// g_i(s) on this step's series, and its derivative (Horner).
  std::pair<double, double> event_at(int i, double s) const {
    const auto& c = event_coefficients_[i];
    double g = c[event_orders_[i]], dg = 0;
    for (int k = event_orders_[i] - 1; k >= 0; --k) {
      dg = dg * s + g;
      g = g * s + c[k];
    }
    return {g, dg};
  }

  /// g_i at the two ends lo and hi of a bracket (two interleaved Horner chains).
  std::pair<double, double> event_at_ends(int i, double lo, double hi) const {
    const auto& c = event_coefficients_[i];
    double g_lo = c[event_orders_[i]], g_hi = g_lo;
    for (int k = event_orders_[i] - 1; k >= 0; --k) {
      g_lo = g_lo * lo + c[k];
      g_hi = g_hi * hi + c[k];
    }
    return {g_lo, g_hi};
  }

  /// The root of g_i on [lo, hi] (s after the step's start) where g_i falls through 0 by
  /// the system's events: Newton on the series from the secant through the ends, kept in
  /// the bracket (bisection where a Newton step leaves it), to |change| <= tol. An end
  /// where the series already has the sign of the other is the root. A root located
  /// earlier in this step (the step since cut at an earlier event) is the root again: the
  /// same series, and the cut is never past it, since the earliest root sets the cut (it
  /// was located to the longer bracket's tolerance: a few roundings, like this one's).
  double locate_on_series(int i, double lo, double hi, double tol) {
    if (!(event_series_ready_ >> i & 1u)) {
      [&]<std::size_t... I>(std::index_sequence<I...>) {
        ((static_cast<int>(I) == i ? generate_event_series<I>() : void()), ...);
      }(std::make_index_sequence<m>{});
      event_series_ready_ |= 1u << i;
    } else if (event_roots_[i] >= lo) {
      return event_roots_[i];
    }
    const auto [g_lo, g_hi] = event_at_ends(i, lo, hi);
    if (!(g_lo > 0)) return event_roots_[i] = lo;
    if (g_hi > 0) return event_roots_[i] = hi;
    double s = lo + (hi - lo) * g_lo / (g_lo - g_hi);
    for (int iteration = 0; iteration < 100; ++iteration) {
      const auto [g, dg] = event_at(i, s);
      if (g > 0) lo = s;
      else hi = s;
      double next = s - g / dg;
      if (!(next >= lo && next <= hi)) next = 0.5 * (lo + hi);
      const double change = std::abs(next - s);
      s = next;
      if (change <= tol || hi - lo <= tol) break;
    }
    return event_roots_[i] = s;
  }

  /// Every crossing on the rest [a, h] of the step (g_a at a, g_end at h), as
  /// locate_event_crossings (event_landing.hpp) reports them: fractions of the rest.
  EventCrossings<m> locate_crossings(double t_start, double a, double h, const Events& g_a, const Events& g_end) {
    EventCrossings<m> c;
    const double rest = h - a;
    const double tol = event_location_tolerance(t_start + a, rest);
    c.theta_tol = tol / rest;
    for (int i = 0; i < m; ++i) {
      c.theta[i] = 2.0;
      if (!(g_a[i] > 0 && g_end[i] <= 0)) continue;
      c.theta[i] = (locate_on_series(i, a, h, tol) - a) / rest;
      c.earliest = std::min(c.earliest, c.theta[i]);
    }
    return c;
  }

  /// The series' value s after the step's start (Horner).
  State at(double s) const {
    State y = y_;
    for (int i = 0; i < n; ++i) {
      double sum = coefficients_[i][order_];
      for (int k = order_ - 1; k >= 0; --k) sum = sum * s + coefficients_[i][k];
      y[i] = sum;
    }
    return y;
  }

  /// Advance over the step of size h from (t_, y_), cut at every event located in it;
  /// true if an event stopped the integration.
  bool finish_step(double h) {
    const double t_start = t_;
    const bool to_end = h == t_end_ - t_start;
    double a = 0;  // the part of the step already done
    // Events fired in this step stay at <= 0 to its end: each fires at most once per
    // series. (Roots that coincide, such as v = 0 and dF/dtau = 0 of an undamped contact,
    // would otherwise fire in turn forever where the system's event functions, re-read
    // at each landing, and the series differ by a rounding.)
    unsigned fired = 0;
    auto keep_fired_down = [&] {
      for (int i = 0; i < m; ++i)
        if (fired >> i & 1u) g_[i] = std::min(g_[i], 0.0);
    };
    for (;;) {
      const State y_end = at(h);
      Events g_end;
      sys_.events(t_start + h, y_end, g_end);
      if (!any_event_crossed(g_, g_end)) {
        move_to(to_end ? t_end_ : t_start + h, y_end);
        g_ = g_end;
        keep_fired_down();
        return false;
      }
      // Locate on the rest of the step, [a, h] after t_start.
      const auto crossings = locate_crossings(t_start, a, h, g_, g_end);
      const double s = a + crossings.earliest * (h - a);
      const Events g_before = g_;
      move_to(t_start + s, at(s));
      const EventAction action =
          fire_landed_events(sys_, t_, y_, g_, g_before, t_start + a, h - a, crossings, stats_, observer_);
      for (int i = 0; i < m; ++i)
        if (g_before[i] > 0 && g_[i] <= 0) fired |= 1u << i;  // fire_landed_events fires exactly these
      keep_fired_down();
      if (action == EventAction::stop) return true;
      if (action == EventAction::restart) {
        rhs_ = sys_.polynomial_rhs(leaves());  // the system may have changed form
        atol_ = absolute_tolerance(sys_, y_, opt_.atol);  // and its scales
        event_series_ = sys_.polynomial_events(leaves());
        bind_storage();
        return false;
      }
      if (s >= h) return false;
      a = s;
    }
  }

  void move_to(double t, const State& y) {
    t_ = t;
    y_ = y;
    ++stats_.steps;
    observer_.on_step(t_, y_);
  }

  S& sys_;
  State& y_;
  double t_, t_end_;
  const TaylorOptions& opt_;
  Observer& observer_;
  int order_;
  std::array<std::array<double, series_capacity + 1>, n> coefficients_{};
  Rhs rhs_;
  State atol_;  ///< absolute tolerance of each component (since the last restart)
  EventSeries event_series_;
  SeriesStorage<products_in<Rhs> + products_in<EventSeries>> storage_;  ///< their products' coefficients
  std::array<std::array<double, series_capacity + 1>, m> event_coefficients_{};
  std::array<int, m> event_orders_{};
  unsigned event_series_ready_ = 0;  ///< bit i: event i's series is this step's
  std::array<double, m> event_roots_{};  ///< root of event i located in this step (if its series is ready)
  IntegrationStats stats_;
  Events g_;  ///< event functions at (t_, y_)
};

}  // namespace detail

/// Integrate `sys` from (t0, y) towards t_end with the Taylor-series method; y is updated in place.
template <PolynomialOdeSystem S, IntegrationObserver<typename S::State> Observer>
IntegrationStats integrate_taylor(S& sys, typename S::State& y, double t0, double t_end, const TaylorOptions& opt,
                                  Observer& observer) {
  if (!(opt.rtol > 0)) throw std::invalid_argument("integrate_taylor: rtol must be > 0");
  if (!(opt.atol > 0)) throw std::invalid_argument("integrate_taylor: atol must be > 0");
  return detail::TaylorRun<S, Observer>(sys, y, t0, t_end, opt, observer).run();
}

}  // namespace hertzdash
