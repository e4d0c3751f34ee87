// Peer: Boost.Odeint runge_kutta_dopri5 with dense output, as a user would write it.
//
// The system is DropTest<HongoPaper> (the model's right-hand side, called through
// std::array states). Each do_step() of the dense-output stepper advances one
// adaptive step; when the gap function changes sign over it (onset: x rises
// through 0; separation: x falls through 0), the crossing is found by bisection
// on calc_state() -- the dense output, no extra evaluations -- to 1e-15 s. At
// onset the stepper is re-initialised in contact mode from the interpolated state.
#include "bench/impact_solvers.hpp"


#include <boost/numeric/odeint.hpp>

#include <array>

namespace hertzdash::bench {

namespace {

namespace odeint = boost::numeric::odeint;
using OdeintState = std::array<double, 2>;

struct CountingRhs {
  const DropTest<HongoPaper>* sys;
  long* evaluations;
  void operator()(const OdeintState& y, OdeintState& dy, double t) const {
    ++*evaluations;
    DropTest<HongoPaper>::State ye{y[0], y[1]}, de;
    sys->rhs(t, ye, de);
    dy = {de[0], de[1]};
  }
};

class OdeintDopri5 final : public ImpactSolver {
 public:
  explicit OdeintDopri5(double tol) : tol_(tolerances_for(tol)) {}

  ImpactResult run(const DropTestSetup& setup) override {
    PeerImpact impact(setup);
    auto& sys = impact.sys;
    long evaluations = 0;
    const CountingRhs rhs{&sys, &evaluations};
    OdeintState y{impact.y0[0], impact.y0[1]};
    double t = 0;
    const double contact_scale_s = impact.contact_time_s;
    if (!sys.in_contact()) {
      // Free fall until x rises through zero.
      y = integrate_to_crossing(rhs, y, t, 1e-3 * impact.fall_time_s, +1);
      sys.handle_event(event_index(DropTestEvent::contact), t, DropTest<HongoPaper>::State{y[0], y[1]});
    }
    const double v_impact = y[1];
    y = integrate_to_crossing(rhs, y, t, 1e-3 * contact_scale_s, -1);
    return {-y[1] / v_impact, evaluations};
  }

 private:
  /// Steps until x crosses zero in `direction` (+1 rising, -1 falling); returns the
  /// interpolated state there and sets t to the crossing time.
  OdeintState integrate_to_crossing(const CountingRhs& rhs, const OdeintState& y0, double& t, double dt0,
                                    int direction) {
    auto stepper = odeint::make_dense_output(tol_.atol, tol_.rtol, odeint::runge_kutta_dopri5<OdeintState>());
    stepper.initialize(y0, t, dt0);
    auto beyond = [direction](double x) { return direction > 0 ? x >= 0 : x <= 0; };
    for (;;) {
      const auto [t0, t1] = stepper.do_step(rhs);
      if (!beyond(stepper.current_state()[0]) || beyond(stepper.previous_state()[0])) continue;
      double lo = t0, hi = t1;
      OdeintState y;
      while (hi - lo > 1e-15) {
        const double mid = 0.5 * (lo + hi);
        stepper.calc_state(mid, y);
        (beyond(y[0]) ? hi : lo) = mid;
      }
      stepper.calc_state(hi, y);
      t = hi;
      return y;
    }
  }

  Tolerances tol_;
};

}  // namespace

std::unique_ptr<ImpactSolver> make_odeint_dopri5(double tol) { return std::make_unique<OdeintDopri5>(tol); }

}  // namespace hertzdash::bench
