#pragma once
// The solvers the work-precision benchmark compares, behind one small interface.
//
// hertzdash's own integrators run through ImpactSimulator (the library path users
// call). The peers are written the way a knowledgeable user would write them with
// those libraries, and live only in bench/: the library never links them. Two groups:
//   - physical variables: Boost.Odeint runge_kutta_dopri5 with dense output, GSL
//     odeiv2 rk8pd, and CVODE created afresh per impact, on the same right-hand side
//     (DropTest<HongoPaper>::rhs, the model's own);
//   - regularised variables: Boost.Odeint bulirsch_stoer (controlled, and
//     bulirsch_stoer_dense_out), runge_kutta_dopri5 (controlled, dense output) and GSL
//     rk8pd, handed exactly hertzdash's regularised contact
//     (ContactSystem<HongoPaper, FixedWall>::rhs: the polynomial right-hand side in
//     u = x^{1/2}, v = x', t against tau), the fall in closed form as hertzdash does,
//     and the same separation event (u falls through 0).
//
// Every solver reports the effective restitution (rebound over approach speed at
// separation, x = 0 decreasing) and the right-hand-side evaluations it spent.
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/drop_test.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/contact_environments.hpp"
#include "hertzdash/model/contact_system.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <memory>
#include <string>

namespace hertzdash::bench {

struct ImpactResult {
  double e_effective = 0;      ///< rebound / approach speed [-]
  long rhs_evaluations = 0;    ///< right-hand-side evaluations of this impact
};

class ImpactSolver {
 public:
  virtual ~ImpactSolver() = default;
  /// One impact of a validated set-up: a free fall then contact, or (with an impact
  /// velocity) the contact phase alone; ends at separation.
  virtual ImpactResult run(const DropTestSetup& setup) = 0;
};

/// Tolerances for a benchmark tolerance `tol`: rtol = tol and atol = tol * 1e-4, 1e-4 being
/// the order of the peak deformation in metres, so that the deformation and the velocity are
/// both controlled relatively. Every adaptive solver gets the same pair: the peers in SI
/// units (m, m/s; m^{1/2}, s regularised), hertzdash's integrators relative to the impact's
/// scales (SolverSettings::atol: X = 2.6e-4 m, v0 = 0.63 m/s, t_H = 1.2e-3 s here), which is
/// at least as tight on every component since every scale is below 1 (v0 the largest: equal
/// to within 1.6x there, 4000x tighter on x).
struct Tolerances {
  double rtol, atol;
};
inline Tolerances tolerances_for(double tol) { return {tol, tol * 1e-4}; }

/// What every peer starts one impact from: the model, the system (the same
/// right-hand side hertzdash integrates), its initial state, and the time scales that
/// size first steps and end times.
struct PeerImpact {
  explicit PeerImpact(const DropTestSetup& setup)
      : model(setup),
        sys(model),
        y0(sys.initial_state()),
        contact_time_s(undamped_hertz_impact(model.K, model.mass_kg, approach_speed(setup)).contact_time_s),
        fall_time_s(sys.in_contact() ? 0.0 : std::sqrt(2 * setup.height_m / setup.gravity_mps2)) {}
  PeerImpact(const PeerImpact&) = delete;
  PeerImpact& operator=(const PeerImpact&) = delete;

  DropTestModel model;
  DropTest<HongoPaper> sys;      ///< the system (holds a copy of `model`)
  DropTest<HongoPaper>::State y0;
  double contact_time_s;         ///< undamped Hertz contact time at the approach speed [s]
  double fall_time_s;            ///< free fall from rest to contact [s] (0 if starting at onset)
};

/// What every regularised peer starts one impact from: hertzdash's regularised contact
/// for the set-up (at onset: the fall from rest is closed-form, v0 = sqrt(2 g h)), its
/// onset state (u, v, t) = (0, v0, 0), and the tau scale T/(2 X*^{1/2}), T = X*/v0, that
/// sizes first steps.
struct RegularizedPeerImpact {
  explicit RegularizedPeerImpact(const DropTestSetup& setup)
      : v0_mps(approach_speed(setup)),
        sys(ImpactConditions{hertz_stiffness(setup), setup.mass_kg, v0_mps, setup.restitution}, setup.damping,
            FixedWall{setup.gravity_mps2}),
        y0(sys.initial_state()) {
    const double X = hertz_impact_scale_m(hertz_stiffness(setup), setup.mass_kg, v0_mps);
    tau_scale = (X / v0_mps) / (2 * std::sqrt(X));
  }
  RegularizedPeerImpact(const RegularizedPeerImpact&) = delete;
  RegularizedPeerImpact& operator=(const RegularizedPeerImpact&) = delete;

  double v0_mps;
  ContactSystem<HongoPaper, FixedWall> sys;
  ContactSystem<HongoPaper, FixedWall>::State y0;
  double tau_scale = 0;
};

/// Cubic Hermite on [0, 1] with values p0, p1 and end slopes m0, m1 (already times the step).
inline double cubic_hermite(double s, double p0, double m0, double p1, double m1) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1 + (s3 - s2) * m1;
}

/// The separation on a step [lo, hi] of the regularised contact over which u fell
/// through 0: Newton's method on a continuous extension at(tau) -> (u, v, ...), whose
/// derivative du/dtau = v is its own second component, kept inside the step, to
/// rounding. Returns tau there.
template <class At>
double newton_separation(const At& at, double lo, double hi) {
  double tau = hi;
  for (int i = 0; i < 30; ++i) {
    const auto y = at(tau);
    const double next = std::clamp(tau - y[0] / y[1], lo, hi);
    const double change = std::abs(next - tau);
    tau = next;
    if (change <= 4e-16 * std::abs(tau)) break;
  }
  return tau;
}

/// newton_separation on the cubic Hermite interpolant of (u, v) over the step from
/// (tau_a, ya) to (tau_b, yb) of the regularised contact: u' = v, and v' = fva and fvb at
/// the ends. ya and yb point to (u, v, ...). Returns tau at the separation.
inline double hermite_separation(double tau_a, const double* ya, double fva, double tau_b, const double* yb,
                                 double fvb) {
  const double h = tau_b - tau_a;
  auto at = [&](double tau) {
    const double s = (tau - tau_a) / h;
    return std::array<double, 2>{cubic_hermite(s, ya[0], h * ya[1], yb[0], h * yb[1]),
                                 cubic_hermite(s, ya[1], h * fva, yb[1], h * fvb)};
  };
  return newton_separation(at, tau_a, tau_b);
}

/// hertzdash's ImpactSimulator with `kind`; for a fixed-step integrator `tol_or_dt` is the step [s].
std::unique_ptr<ImpactSolver> make_hertzdash_solver(IntegratorKind kind, double tol_or_dt);
/// Boost.Odeint runge_kutta_dopri5, dense output, bisection on the dense output for the events.
std::unique_ptr<ImpactSolver> make_odeint_dopri5(double tol);
/// GSL odeiv2 rk8pd with a y_new control, the crossing from cubic Hermite interpolation.
std::unique_ptr<ImpactSolver> make_gsl_rk8pd(double tol);
/// CVODE (Adams) created, used with its root finder and freed for every impact.
std::unique_ptr<ImpactSolver> make_cvode_fresh(double tol);
/// Boost.Odeint bulirsch_stoer on the regularised contact; the separation on the cubic
/// Hermite interpolant of the crossing step (two evaluations for the slopes of v).
std::unique_ptr<ImpactSolver> make_odeint_bs_regularized(double tol);
/// Boost.Odeint bulirsch_stoer_dense_out on the regularised contact; the separation on its dense output.
std::unique_ptr<ImpactSolver> make_odeint_bs_dense_regularized(double tol);
/// Boost.Odeint runge_kutta_dopri5 (controlled, dense output) on the regularised contact;
/// the separation on its dense output.
std::unique_ptr<ImpactSolver> make_odeint_dopri5_regularized(double tol);
/// GSL odeiv2 rk8pd on the regularised contact; the separation on the cubic Hermite
/// interpolant of the crossing step (two evaluations for the slopes of v).
std::unique_ptr<ImpactSolver> make_gsl_rk8pd_regularized(double tol);

}  // namespace hertzdash::bench
