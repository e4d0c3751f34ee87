// The Taylor-series integrator (integrators/taylor.hpp, power_series.hpp) on closed
// forms: the coefficient recurrence, a polynomial system with a located event, and the
// regularised contact through ImpactSimulator's taylor-regularized path against the
// undamped Hertz impact and the exact restitution of the Kelvin-Voigt law.
#include "hertzdash/integrators/taylor.hpp"
#include "hertzdash/model/damping/laws/kelvin_voigt.hpp"
#include "hertzdash/model/damping/laws/undamped.hpp"
#include "validation/common/convergence_runs.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include "undamped_hertz_errors.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>
#include <vector>

using namespace hertzdash;

namespace {

/// y' = y^2 (y > 0), one component, event g = 2 - y (y reaches 2): from y(0) = 1 the
/// solution is 1 / (1 - t), whose Taylor coefficients at 0 are all 1, and y = 2 at t = 1/2.
struct Riccati {
  static constexpr int dimension = 1;
  static constexpr int event_count = 1;
  using State = Eigen::Matrix<double, 1, 1>;
  using Events = std::array<double, 1>;
  template <class Y>
  auto polynomial_rhs(const Y& y) const {
    return std::tuple{y[0] * y[0]};
  }
  template <class Y>
  auto polynomial_events(const Y& y) const {
    return std::tuple{2.0 - y[0]};
  }
  void rhs(double, const State& y, State& dy) const { dy[0] = std::get<0>(polynomial_rhs(y)); }
  void events(double, const State& y, Events& g) const { g = {std::get<0>(polynomial_events(y))}; }
  EventAction handle_event(int, double, const State&) const { return EventAction::stop; }
};

/// The paper's steel rod at v0 = 0.626 m/s with no gravity (the closed forms' conditions).
DropTestSetup contact_without_gravity(double restitution) {
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.gravity_mps2 = 0.0;
  s.impact_velocity_mps = 0.626;
  s.restitution = restitution;
  validate(s);
  return s;
}

SolverSettings taylor(double tol) {
  SolverSettings s;
  s.integrator = IntegratorKind::taylor_regularized;
  s.rtol = tol;
  s.atol = 1e-4 * tol;
  return s;
}

const std::vector<double> tolerances{1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12};

/// Law's contact `setup` with taylor-regularized at each of `tolerances`: `error_of(tol,
/// summary)` within 10 tol at every one, and the least-squares slope of log error against
/// log tolerance within 0.8..1.2 (error proportional to tolerance).
template <class Law, class ErrorOf>
void check_error_proportional_to_tolerance(const DropTestSetup& setup, const ErrorOf& error_of) {
  std::vector<double> errors;
  for (double tol : tolerances) {
    ImpactSimulator sim(taylor(tol));
    const ImpactSummary s = sim.run<Law>(setup);
    REQUIRE(s.separated);
    const double err = error_of(tol, s);
    errors.push_back(std::max(err, 1e-16));
    CHECK(err <= 10 * tol);
  }
  const double k = convergence::fitted_slope(tolerances, errors);
  std::printf("  least-squares slope of log error against log tolerance: %.3f\n", k);
  CHECK(k >= 0.8);
  CHECK(k <= 1.2);
}

}  // namespace

TEST_CASE("power series: the recurrence gives the Taylor coefficients of 1/(1 - t)", "[taylor]") {
  // y' = y^2, y_0 = 1: y_{k+1} = (y^2)_k / (k + 1) = (k + 1) / (k + 1) = 1 if all lower
  // coefficients are 1 (the Cauchy product of k + 1 ones is k + 1). Exact in floating point.
  std::array<double, series_capacity + 1> c{};
  c[0] = 1.0;
  const std::array<SeriesVariable, 1> y{SeriesVariable{c.data()}};
  auto f = Riccati{}.polynomial_rhs(y);
  SeriesStorage<series_products<std::tuple_element_t<0, decltype(f)>>> storage;
  storage.bind(std::get<0>(f));
  for (int k = 0; k < 20; ++k) {
    std::get<0>(f).update(k);
    c[k + 1] = std::get<0>(f)[k] / (k + 1);
  }
  for (int k = 0; k <= 20; ++k) CHECK(c[k] == 1.0);
}

TEST_CASE("power series: derivative(y^2) of 1/(1 - t) has coefficients (j + 1)(j + 2), one order lost", "[taylor]") {
  // With y_j = 1 for all j, (y^2)_j = j + 1 (the Cauchy product of j + 1 ones), so
  // d(y^2)/dt = 2 y y' = 2/(1 - t)^3 has coefficients (j + 1)(j + 2): exact in floating
  // point. Coefficient j needs y_{j+1}, hence one order lost.
  std::array<double, series_capacity + 1> c{};
  c.fill(1.0);
  const std::array<SeriesVariable, 1> y{SeriesVariable{c.data()}};
  auto rate = derivative(y[0] * y[0]);
  STATIC_REQUIRE(decltype(rate)::lost_orders == 1);
  STATIC_REQUIRE(decltype(y[0] * y[0])::lost_orders == 0);
  SeriesStorage<decltype(rate)::products> storage;
  storage.bind(rate);
  for (int k = 0; k < 20; ++k) {
    rate.update(k);
    CHECK(rate[k] == (k + 1.0) * (k + 2.0));
  }
}

TEST_CASE("taylor: the event y = 2 of y' = y^2 located on the series at t = 1/2", "[taylor]") {
  // y = 1/(1 - t) reaches 2 at t* = 1/2; there the singularity at t = 1 is as near as
  // the step's start, the hardest place for a step-size rule read from the coefficients.
  // The state and t* carry the method's own error: within 10 tol (relative).
  for (double tol : {1e-6, 1e-9, 1e-12}) {
    Riccati sys;
    Riccati::State y(1.0);
    NullObserver observer;
    const IntegrationStats st = integrate_taylor(sys, y, 0.0, 10.0, TaylorOptions{tol, tol}, observer);
    std::printf("taylor y' = y^2: tol %.0e, |t* - 1/2| %.3e, %ld steps\n", tol, std::abs(st.t_final - 0.5), st.steps);
    REQUIRE(st.stopped_by_event);
    CHECK(std::abs(st.t_final - 0.5) <= 10 * tol);
    CHECK(std::abs(y[0] - 2.0) <= 20 * tol);
  }
}

/// y1' = y2, y2' = -y1 from (0, 1): y1 = sin t. Events g_i = c_i - y1 for the levels
/// c = (0.1, 0.2, 0.3), fired as y1 rises through them at t_i = asin(c_i); the first two
/// continue, the third stops.
struct RisingSine {
  static constexpr int dimension = 2;
  static constexpr int event_count = 3;
  using State = Eigen::Matrix<double, 2, 1>;
  using Events = std::array<double, 3>;
  static constexpr std::array<double, 3> levels{0.1, 0.2, 0.3};
  template <class Y>
  auto polynomial_rhs(const Y& y) const {
    return std::tuple{y[1], -1.0 * y[0]};
  }
  template <class Y>
  auto polynomial_events(const Y& y) const {
    return std::tuple{levels[0] - y[0], levels[1] - y[0], levels[2] - y[0]};
  }
  void rhs(double, const State& y, State& dy) const { dy = State{y[1], -y[0]}; }
  void events(double, const State& y, Events& g) const { g = {levels[0] - y[0], levels[1] - y[0], levels[2] - y[0]}; }
  EventAction handle_event(int i, double, const State&) const {
    return i == 2 ? EventAction::stop : EventAction::continue_integration;
  }
};

struct EventTimes {
  std::vector<std::pair<int, double>> fired;
  void on_step(double, const RisingSine::State&) {}
  void on_event(int i, double t, const RisingSine::State&, EventAction) { fired.emplace_back(i, t); }
};

TEST_CASE("taylor: several events in one step, the step cut at each, are located on the same series", "[taylor]") {
  // sin t is entire and its coefficients fall like 1/k!, so the first step is longer than
  // asin(0.3) = 0.305 at these tolerances (about (p! tol)^{1/p} > 1): all three events
  // lie in it, and each cut continues on the same series (one generation: p right-hand-side
  // evaluations), where a root found before the cut is reused. Each event time carries the
  // series' truncation error at most, below tol; 10 tol as in the test above.
  for (double tol : {1e-6, 1e-9, 1e-12}) {
    RisingSine sys;
    RisingSine::State y{0.0, 1.0};
    EventTimes observer;
    const IntegrationStats st = integrate_taylor(sys, y, 0.0, 10.0, TaylorOptions{tol, tol}, observer);
    REQUIRE(st.stopped_by_event);
    CHECK(st.rhs_evaluations == taylor_order(tol));
    REQUIRE(observer.fired.size() == 3);
    for (int i = 0; i < 3; ++i) {
      CHECK(observer.fired[i].first == i);
      CHECK(std::abs(observer.fired[i].second - std::asin(RisingSine::levels[i])) <= 10 * tol);
    }
  }
}

TEST_CASE("taylor-regularized: undamped Hertz impact against the closed forms, error proportional to tolerance",
          "[taylor][regularized]") {
  // No gravity, no damping: e_eff = 1, X = (5 m v0^2 / 4K)^{2/5}, F = K X^{3/2} and the
  // contact time (4/5) B(2/5, 1/2) X / v0 (model/hertz.hpp). The step rule holds the
  // series' last terms to the tolerance, so each step's error is a fixed fraction of it
  // and the global error is proportional to the tolerance: each error within 10 tol down
  // to tol = 1e-12 (an error of 1e-12 reached), and the least-squares slope of log error
  // against log tol over 1e-4..1e-12 within 0.8..1.2.
  const DropTestSetup setup = contact_without_gravity(1.0);
  const UndampedHertzImpact exact = undamped_hertz_impact(hertz_stiffness(setup), setup.mass_kg, 0.626);
  std::printf("taylor-regularized undamped Hertz: tol, |e-1|, rel err X, rel err F, rel err t_c, rhs evaluations\n");
  check_error_proportional_to_tolerance<Undamped>(setup, [&](double tol, const ImpactSummary& s) {
    return testing::undamped_hertz_errors(tol, s, exact).largest();
  });
}

TEST_CASE("taylor-regularized: Kelvin-Voigt returns its input restitution exactly, error proportional to tolerance",
          "[taylor][regularized]") {
  // The linear spring-dashpot with the exact linear-oscillator zeta and no gravity has
  // e_eff = e exactly (model/damping/laws/kelvin_voigt.hpp): x(t) is a damped sine
  // whose rebound speed is e v0. In u = x^{1/2} its force k u^2 + c v is a polynomial.
  // |e_eff - e| within 10 tol down to 1e-12; slope within 0.8..1.2.
  const DropTestSetup setup = contact_without_gravity(0.8);
  std::printf("taylor-regularized Kelvin-Voigt, e = 0.8: tol, |e_eff - e|\n");
  check_error_proportional_to_tolerance<KelvinVoigt>(setup, [](double tol, const ImpactSummary& s) {
    const double err = std::abs(s.e_effective - 0.8);
    std::printf("  %.0e  %.3e\n", tol, err);
    return err;
  });
}

TEST_CASE("taylor-regularized: the paper's law agrees with dopri5 in the physical variables",
          "[taylor][regularized]") {
  // Independent methods and variables at tolerance 1e-11, each within tens of tol of the
  // truth: within 1e-8 of each other in e_eff, peak force, peak deformation, contact time.
  DropTestSetup setup = paper_setup(load_paper_parameters(), "steel", 0.02);
  validate(setup);
  SolverSettings physical;
  physical.integrator = IntegratorKind::dopri5;
  physical.rtol = 1e-11;
  physical.atol = 1e-15;
  ImpactSimulator a_sim(taylor(1e-11)), b_sim(physical);
  const ImpactSummary a = a_sim.run<HongoPaper>(setup), b = b_sim.run<HongoPaper>(setup);
  auto rel = [](double p, double q) { return std::abs(p / q - 1); };
  CHECK(rel(a.e_effective, b.e_effective) < 1e-8);
  CHECK(rel(a.peak_force_N, b.peak_force_N) < 1e-8);
  CHECK(rel(a.max_deformation_m, b.max_deformation_m) < 1e-8);
  CHECK(rel(a.contact_time_s, b.contact_time_s) < 1e-8);
}

TEST_CASE("taylor-regularized: coincident events of an undamped contact fire once each", "[taylor][regularized]") {
  // e = 1 makes the paper's law undamped (zeta = 0): dF/dtau = 3 K u^2 v vanishes with v,
  // so the peak-force and the largest-compression events share their root, where the
  // system's rate (evaluated at the landed state) and the series' differ by a rounding. Once
  // each with separation, three events in all; the rebound speed is the approach speed to
  // the tolerance (energy conserved: e_eff = 1 within 10 tol). The height is where the
  // integrator once fired the two in turn forever: the sixth of 44 heights from 1 to 100 mm
  // of a restitution map, 1 mm + 99 mm x 5/43.
  DropTestSetup setup = paper_setup(load_paper_parameters(), "steel", 0.02);
  setup.restitution = 1.0;
  setup.impact_velocity_mps = std::sqrt(2 * setup.gravity_mps2 * (1e-3 + 99e-3 * 5.0 / 43.0));
  validate(setup);
  ImpactSimulator sim(taylor(1e-8));
  const ImpactSummary s = sim.run<HongoPaper>(setup);
  REQUIRE(s.separated);
  CHECK(s.work.events == 3);
  CHECK(std::abs(s.e_effective - 1.0) <= 1e-7);
}
