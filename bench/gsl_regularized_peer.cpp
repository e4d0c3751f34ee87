// Peer: GSL odeiv2 rk8pd on hertzdash's regularised contact, as a knowledgeable user
// would hand it the same polynomial right-hand side (ContactSystem<HongoPaper, FixedWall>::rhs).
//
// gsl_odeiv2_evolve_apply with a y_new(atol, rtol) control advances one adaptive step
// in tau at a time from onset (u, v, t) = (0, v0, 0); the step, control and evolve
// objects are allocated once and reset per impact. On the step over which u falls
// through 0, the separation is found by Newton's method (hermite_separation) on the
// cubic Hermite interpolant of (u, v) (du/dtau = v is in the state, the slopes of v
// cost two evaluations), and the step is re-taken from its start to end there, as
// hertzdash's gbs8 does. e_eff = -v / v0 there.
#include "bench/gsl_rk8pd_objects.hpp"
#include "bench/impact_solvers.hpp"

#include <gsl/gsl_odeiv2.h>

#include <stdexcept>

namespace hertzdash::bench {

namespace {

using Contact = ContactSystem<HongoPaper, FixedWall>;

struct GslContext {
  const Contact* sys;
  long evaluations;
};

int gsl_rhs(double tau, const double y[], double dydt[], void* params) {
  auto* c = static_cast<GslContext*>(params);
  ++c->evaluations;
  Contact::State d;
  c->sys->rhs(tau, Contact::State{y[0], y[1], y[2]}, d);
  dydt[0] = d[0], dydt[1] = d[1], dydt[2] = d[2];
  return GSL_SUCCESS;
}

class GslRk8pdRegularized final : public ImpactSolver {
 public:
  explicit GslRk8pdRegularized(double tol) : gsl_(3, tol) {}

  ImpactResult run(const DropTestSetup& setup) override {
    const RegularizedPeerImpact impact(setup);
    GslContext ctx{&impact.sys, 0};
    gsl_odeiv2_system ode{gsl_rhs, nullptr, 3, &ctx};
    gsl_.reset();
    double y[3] = {impact.y0[0], impact.y0[1], impact.y0[2]};
    double tau = 0, h = 1e-3 * impact.tau_scale;
    const double tau_end = 1e3 * impact.tau_scale;
    while (tau < tau_end) {
      const double tau_a = tau, ya[3] = {y[0], y[1], y[2]};
      gsl_.apply(ode, tau, tau_end, h, y);
      if (!(ya[0] > 0 && y[0] <= 0)) continue;
      double fa[3], fb[3];
      gsl_rhs(tau_a, ya, fa, &ctx);
      gsl_rhs(tau, y, fb, &ctx);
      // Re-take the step from its start to end on the interpolated separation (v is
      // stationary at u = 0, so the error of the interpolated root enters squared).
      const double tau_star = hermite_separation(tau_a, ya, fa[1], tau, y, fb[1]);
      tau = tau_a;
      y[0] = ya[0], y[1] = ya[1], y[2] = ya[2];
      h = tau_star - tau_a;
      gsl_.reset_evolve();
      while (tau < tau_star) gsl_.apply(ode, tau, tau_star, h, y);
      return {-y[1] / impact.v0_mps, ctx.evaluations};
    }
    throw std::runtime_error("GSL regularised peer: no separation before the end");
  }

 private:
  GslRk8pdObjects gsl_;
};

}  // namespace

std::unique_ptr<ImpactSolver> make_gsl_rk8pd_regularized(double tol) {
  return std::make_unique<GslRk8pdRegularized>(tol);
}

}  // namespace hertzdash::bench
