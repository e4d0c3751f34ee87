#pragma once
// The solvers the work-precision benchmark compares, behind one small interface.
//
// hertzdash's own integrators run through ImpactSimulator (the library path users
// call). The peers -- Boost.Odeint runge_kutta_dopri5 with dense output, GSL odeiv2
// rk8pd, and CVODE created afresh per impact -- are written the way a user would
// write them with those libraries, on the same right-hand side
// (DropTest<HongoPaper>::rhs, the model's own), and live only in bench/: the
// library never links them.
//
// Every solver reports the effective restitution (rebound over approach speed at
// separation, x = 0 decreasing) and the right-hand-side evaluations it spent.
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/drop_test.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/impact_simulator.hpp"

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

/// Tolerances for a benchmark tolerance `tol`: rtol = tol and atol = tol * 1e-4 (m, m/s),
/// 1e-4 being the order of the peak deformation in metres, so that the deformation and
/// the velocity are both controlled relatively. Every adaptive solver gets the same pair.
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

/// hertzdash's ImpactSimulator with `kind`; for a fixed-step integrator `tol_or_dt` is the step [s].
std::unique_ptr<ImpactSolver> make_hertzdash_solver(IntegratorKind kind, double tol_or_dt);
/// Boost.Odeint runge_kutta_dopri5, dense output, bisection on the dense output for the events.
std::unique_ptr<ImpactSolver> make_odeint_dopri5(double tol);
/// GSL odeiv2 rk8pd with a y_new control, the crossing from cubic Hermite interpolation.
std::unique_ptr<ImpactSolver> make_gsl_rk8pd(double tol);
/// CVODE (Adams) created, used with its root finder and freed for every impact.
std::unique_ptr<ImpactSolver> make_cvode_fresh(double tol);

}  // namespace hertzdash::bench
