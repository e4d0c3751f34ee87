// Peer: GSL odeiv2 rk8pd (embedded Runge-Kutta Prince-Dormand (8, 9)), as a user would write it.
//
// gsl_odeiv2_evolve_apply with a y_new(atol, rtol) control advances one adaptive
// step at a time; the step, control and evolve objects are allocated once and
// reset per impact. When x changes sign over a step, the crossing is the root of
// the cubic Hermite interpolant of x (x' = xdot is in the state, so no extra
// evaluations), found by bisection; the velocity there is the cubic Hermite
// interpolant of xdot, whose end derivatives cost two evaluations.
#include "bench/gsl_rk8pd_objects.hpp"
#include "bench/impact_solvers.hpp"

#include <gsl/gsl_odeiv2.h>

#include <stdexcept>

namespace hertzdash::bench {

namespace {

struct GslContext {
  const DropTest<HongoPaper>* sys;
  long evaluations;
};

int gsl_rhs(double t, const double y[], double dydt[], void* params) {
  auto* c = static_cast<GslContext*>(params);
  ++c->evaluations;
  DropTest<HongoPaper>::State ye{y[0], y[1]}, de;
  c->sys->rhs(t, ye, de);
  dydt[0] = de[0];
  dydt[1] = de[1];
  return GSL_SUCCESS;
}

class GslRk8pd final : public ImpactSolver {
 public:
  explicit GslRk8pd(double tol) : gsl_(2, tol) {}

  ImpactResult run(const DropTestSetup& setup) override {
    PeerImpact impact(setup);
    auto& sys = impact.sys;
    GslContext ctx{&sys, 0};
    gsl_odeiv2_system ode{gsl_rhs, nullptr, 2, &ctx};
    double y[2] = {impact.y0[0], impact.y0[1]};
    double t = 0;
    const double contact_scale_s = impact.contact_time_s;
    if (!sys.in_contact()) {
      const double fall_s = impact.fall_time_s;
      to_crossing(ode, ctx, y, t, 1e-3 * fall_s, 10 * fall_s, +1);
      sys.handle_event(event_index(DropTestEvent::contact), t, DropTest<HongoPaper>::State{y[0], y[1]});
    }
    const double v_impact = y[1];
    to_crossing(ode, ctx, y, t, 1e-3 * contact_scale_s, t + 20 * contact_scale_s, -1);
    return {-y[1] / v_impact, ctx.evaluations};
  }

 private:
  void to_crossing(gsl_odeiv2_system& ode, GslContext& ctx, double y[2], double& t, double h, double t_end,
                   int direction) {
    gsl_.reset();
    auto beyond = [direction](double x) { return direction > 0 ? x >= 0 : x <= 0; };
    while (t < t_end) {
      const double t0 = t, ya[2] = {y[0], y[1]};
      gsl_.apply(ode, t, t_end, h, y);
      if (!beyond(y[0]) || beyond(ya[0])) continue;
      const double dt = t - t0;
      double fa[2], fb[2];
      gsl_rhs(t0, ya, fa, &ctx);
      gsl_rhs(t, y, fb, &ctx);
      double lo = 0, hi = 1;
      while ((hi - lo) * dt > 1e-15) {
        const double mid = 0.5 * (lo + hi);
        (beyond(cubic_hermite(mid, ya[0], dt * ya[1], y[0], dt * y[1])) ? hi : lo) = mid;
      }
      const double x = cubic_hermite(hi, ya[0], dt * fa[0], y[0], dt * fb[0]);
      const double v = cubic_hermite(hi, ya[1], dt * fa[1], y[1], dt * fb[1]);
      y[0] = x, y[1] = v;
      t = t0 + hi * dt;
      return;
    }
    throw std::runtime_error("GSL peer: no crossing before the end time");
  }

  GslRk8pdObjects gsl_;
};

}  // namespace

std::unique_ptr<ImpactSolver> make_gsl_rk8pd(double tol) { return std::make_unique<GslRk8pd>(tol); }

}  // namespace hertzdash::bench
