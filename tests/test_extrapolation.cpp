// The order-8 Gragg-Bulirsch-Stoer extrapolation method (integrators/extrapolation.hpp)
// on closed forms: its order on a smooth problem, events landed on, and the undamped
// Hertz impact through ImpactSimulator's gbs8-regularized path.
#include "hertzdash/integrators/extrapolation.hpp"
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/damping/laws/undamped.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include "harmonic_oscillator.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace {

using namespace hertzdash;

using Rotation = test::HarmonicOscillator;

}  // namespace

TEST_CASE("gbs8: one step has local error of order 9 (method order 8) on the rotation", "[gbs8]") {
  // One step of size H from (1, 0): exact (cos H, -sin H). For a method of order 8 the
  // local error is C H^9: halving H divides it by 2^9 = 512, observed order of the
  // local error 9 +- 0.3 (H from 0.4 to 0.1, where the error is far above rounding).
  Rotation sys;
  std::vector<double> H{0.4, 0.2, 0.1}, errors;
  std::printf("gbs8 single step on the rotation: H, local error\n");
  for (double h : H) {
    const Rotation::State y(1.0, 0.0);
    Rotation::State f, y1;
    sys.rhs(0.0, y, f);
    long evaluations = 0;
    detail::extrapolation_step(sys, 0.0, y, f, h, 1.0, Rotation::State(1.0, 1.0), y1, evaluations);
    CHECK(evaluations == 16);
    errors.push_back(std::hypot(y1[0] - std::cos(h), y1[1] + std::sin(h)));
    std::printf("  %.2f  %.3e\n", h, errors.back());
  }
  for (std::size_t i = 1; i < H.size(); ++i) {
    const double order = std::log(errors[i - 1] / errors[i]) / std::log(H[i - 1] / H[i]);
    std::printf("  observed local order %.3f\n", order);
    CHECK(order == Approx(9.0).margin(0.3));
  }
}

namespace {
/// Remembers the times of the accepted steps.
struct StepTimes {
  std::vector<double> t;
  template <class State> void on_step(double time, const State&) { t.push_back(time); }
  template <class State> void on_event(int, double, const State&, EventAction) {}
};
}  // namespace

TEST_CASE("gbs8: the event q = 0 landed on, the landed state on the exact solution", "[gbs8]") {
  // The stop event g = q falls through zero at t = pi/2. The step is re-taken to end on
  // the located time t*, so the landed state is the method's solution at t*: within
  // 10 tol of (cos t*, -sin t*). t* itself is located on the cubic Hermite interpolant
  // of the step [t0, t0 + H], whose error in q is at most H^4 max|q^(4)| / 384 = H^4/384;
  // with |q'| = 1 at the root, |t* - pi/2| is within that plus the state's error. H is
  // at most 4 times the accepted step before it (the controller's growth limit), which
  // the observer sees.
  std::printf("gbs8 rotation event: tol, |t* - pi/2|, its bound, landed-state error, rhs evaluations\n");
  for (double tol : {1e-6, 1e-8, 1e-10}) {
    Rotation sys;
    Rotation::State y(1.0, 0.0);
    StepTimes steps;
    const IntegrationStats st = integrate_extrapolation(sys, y, 0.0, 10.0, ExtrapolationOptions{tol, tol}, steps);
    REQUIRE(st.stopped_by_event);
    REQUIRE(steps.t.size() >= 4);
    const std::size_t n = steps.t.size();  // ..., t_{n-3}, t_{n-2} = t0, t_{n-1} = t*
    const double H = 4 * (steps.t[n - 2] - steps.t[n - 3]);
    const double t_star = st.t_final, et = std::abs(t_star - std::numbers::pi / 2);
    const double bound = std::pow(H, 4) / 384 + 10 * tol;
    const double es = std::hypot(y[0] - std::cos(t_star), y[1] + std::sin(t_star));
    std::printf("  %.0e  %.3e  %.3e  %.3e  %ld\n", tol, et, bound, es, st.rhs_evaluations);
    CHECK(es <= 10 * tol);
    CHECK(et <= bound);
  }
}

TEST_CASE("gbs8-regularized: the paper's law agrees with dopri5 in the physical variables", "[gbs8][regularized]") {
  // Independent methods and variables at tolerance 1e-11, each within tens of tol of
  // the truth: within 1e-8 of each other in e_eff, peak force, peak deformation and
  // contact time (peak and separation read at events located to O(H^4), entering squared).
  DropTestSetup setup = paper_setup(load_paper_parameters(), "steel", 0.02);
  validate(setup);
  SolverSettings fast, physical;
  fast.integrator = IntegratorKind::gbs8_regularized;
  fast.rtol = 1e-11;
  fast.atol = 1e-15;
  physical.integrator = IntegratorKind::dopri5;
  physical.rtol = 1e-11;
  physical.atol = 1e-15;
  ImpactSimulator a_sim(fast), b_sim(physical);
  const ImpactSummary a = a_sim.run<HongoPaper>(setup), b = b_sim.run<HongoPaper>(setup);
  std::printf("paper's law: e_eff gbs8-regularized %.12f, dopri5 %.12f\n", a.e_effective, b.e_effective);
  auto rel = [](double p, double q) { return std::abs(p / q - 1); };
  CHECK(rel(a.e_effective, b.e_effective) < 1e-8);
  CHECK(rel(a.peak_force_N, b.peak_force_N) < 1e-8);
  CHECK(rel(a.max_deformation_m, b.max_deformation_m) < 1e-8);
  CHECK(rel(a.contact_time_s, b.contact_time_s) < 1e-8);
}
