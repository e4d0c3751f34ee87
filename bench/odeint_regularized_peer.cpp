// Peers: Boost.Odeint on hertzdash's regularised contact, as a knowledgeable user would
// hand it the same polynomial right-hand side (ContactSystem<HongoPaper, FixedWall>::rhs).
//
// From onset (u, v, t) = (0, v0, 0) the stepper advances in tau until u falls through
// 0 (separation); the rebound speed is -v there, e_eff = -v / v0.
//   - bulirsch_stoer (controlled): try_step until accepted; on the crossing step, the
//     separation on the cubic Hermite interpolant of (u, v) between the step's ends
//     (du/dtau = v is in the state; the slopes of v cost two evaluations), and the
//     step re-taken (integrate_adaptive) from its start to end there, as hertzdash's
//     gbs8 does.
//   - bulirsch_stoer_dense_out and runge_kutta_dopri5 (controlled, dense output):
//     do_step; on the crossing step, the separation on calc_state (no evaluations).
// In every case the crossing is found by Newton's method in tau (newton_separation)
// on the interpolant, to rounding. The steppers are built once per solver and reset for each impact.
#include "bench/impact_solvers.hpp"

#include <boost/numeric/odeint.hpp>

#include <array>
#include <stdexcept>

namespace hertzdash::bench {

namespace {

namespace odeint = boost::numeric::odeint;
using State3 = std::array<double, 3>;
using Contact = ContactSystem<HongoPaper, FixedWall>;

struct CountingRhs {
  const Contact* sys;
  long* evaluations;
  void operator()(const State3& y, State3& dy, double tau) const {
    ++*evaluations;
    Contact::State d;
    sys->rhs(tau, Contact::State{y[0], y[1], y[2]}, d);
    dy = {d[0], d[1], d[2]};
  }
};

constexpr long max_steps = 1000000;

class OdeintBsRegularized final : public ImpactSolver {
 public:
  explicit OdeintBsRegularized(double tol) : stepper_(tolerances_for(tol).atol, tolerances_for(tol).rtol) {}

  ImpactResult run(const DropTestSetup& setup) override {
    const RegularizedPeerImpact impact(setup);
    long evaluations = 0;
    const CountingRhs rhs{&impact.sys, &evaluations};
    stepper_.reset();
    State3 y{impact.y0[0], impact.y0[1], impact.y0[2]};
    double tau = 0, dtau = 1e-3 * impact.tau_scale;
    for (long attempt = 0; attempt < max_steps; ++attempt) {
      const State3 ya = y;
      const double tau_a = tau;
      if (stepper_.try_step(rhs, y, tau, dtau) != odeint::success) continue;
      if (!(ya[0] > 0 && y[0] <= 0)) continue;
      // The separation on the step's cubic Hermite interpolant, then the step re-taken
      // from its start to end there (v is stationary at u = 0, so the error of the
      // interpolated root enters squared).
      State3 fa, fb;
      rhs(ya, fa, tau_a);
      rhs(y, fb, tau);
      const double tau_star = hermite_separation(tau_a, ya.data(), fa[1], tau, y.data(), fb[1]);
      y = ya;
      odeint::integrate_adaptive(stepper_, rhs, y, tau_a, tau_star, tau_star - tau_a);
      return {-y[1] / impact.v0_mps, evaluations};
    }
    throw std::runtime_error("odeint bulirsch_stoer peer: no separation");
  }

 private:
  odeint::bulirsch_stoer<State3> stepper_;
};

/// A dense-output stepper (bulirsch_stoer_dense_out, or dopri5 made dense) to the separation.
template <class Dense>
ImpactResult dense_to_separation(Dense& stepper, const DropTestSetup& setup) {
  const RegularizedPeerImpact impact(setup);
  long evaluations = 0;
  const CountingRhs rhs{&impact.sys, &evaluations};
  stepper.initialize(State3{impact.y0[0], impact.y0[1], impact.y0[2]}, 0.0, 1e-3 * impact.tau_scale);
  for (long step = 0; step < max_steps; ++step) {
    const auto [tau_a, tau_b] = stepper.do_step(rhs);
    if (!(stepper.previous_state()[0] > 0 && stepper.current_state()[0] <= 0)) continue;
    auto at = [&](double tau) {
      State3 y;
      stepper.calc_state(tau, y);
      return y;
    };
    const double v = at(newton_separation(at, tau_a, tau_b))[1];
    return {-v / impact.v0_mps, evaluations};
  }
  throw std::runtime_error("odeint dense-output peer: no separation");
}

class OdeintBsDenseRegularized final : public ImpactSolver {
 public:
  explicit OdeintBsDenseRegularized(double tol) : stepper_(tolerances_for(tol).atol, tolerances_for(tol).rtol) {}
  ImpactResult run(const DropTestSetup& setup) override { return dense_to_separation(stepper_, setup); }

 private:
  odeint::bulirsch_stoer_dense_out<State3> stepper_;
};

class OdeintDopri5Regularized final : public ImpactSolver {
 public:
  explicit OdeintDopri5Regularized(double tol)
      : stepper_(odeint::make_dense_output(tolerances_for(tol).atol, tolerances_for(tol).rtol,
                                           odeint::runge_kutta_dopri5<State3>())) {}
  ImpactResult run(const DropTestSetup& setup) override { return dense_to_separation(stepper_, setup); }

 private:
  odeint::result_of::make_dense_output<odeint::runge_kutta_dopri5<State3>>::type stepper_;
};

}  // namespace

std::unique_ptr<ImpactSolver> make_odeint_bs_regularized(double tol) {
  return std::make_unique<OdeintBsRegularized>(tol);
}
std::unique_ptr<ImpactSolver> make_odeint_bs_dense_regularized(double tol) {
  return std::make_unique<OdeintBsDenseRegularized>(tol);
}
std::unique_ptr<ImpactSolver> make_odeint_dopri5_regularized(double tol) {
  return std::make_unique<OdeintDopri5Regularized>(tol);
}

}  // namespace hertzdash::bench
