#pragma once
// One drop test the fast way: the free fall in closed form, then the contact in
// regularising variables (model/contact_system.hpp, the fixed wall of model/contact_environments.hpp) with any integrator of the
// table whose row has Variables::regularized (dopri5-regularized, cvode-regularized,
// gbs8-regularized, taylor-regularized).
//
// Why: in the physical variables the contact force grows like sqrt(t - t_on) after
// onset and (damped laws) vanishes like sqrt(t_s - t) before separation, so an
// adaptive method must shrink its steps there and cannot trust its error estimate
// (integrators/dormand_prince.hpp checks those steps by step doubling). In the
// variables u = x^{1/2}, dt/dtau = 2u the contact is smooth through onset and
// separation for every law of the form x^{1/2} * (polynomial in x, x') that declares
// it (RootPolynomialLaw), so the error estimates (embedded, extrapolated, or the decay of
// the Taylor coefficients) are reliable everywhere and the steps stay long (the system
// declares smooth_at_events, so dopri5 drops its singular-point checks; for other laws they
// stay on), and CVODE's error follows its tolerance where in the physical variables it does
// not. The fall needs no integration at all: from rest at x = -h under gravity g, contact
// begins at t_on = v0/g with v0 = sqrt(2 g h) (approach_speed), exactly.
//
// The summary is the same as ImpactSimulator's physical-variable run, to within the
// tolerance: onset from the closed form, separation (u = 0 decreasing, v < 0) and the
// peak force and largest deformation from steps landed on the events
// dF/dtau = 0 and v = 0. The run ends at separation, or, if the rod comes to rest on
// the ball, 20 undamped contact times after onset (as the physical run).
// Not for the tension clamp (no_tension: contact ends where F reaches zero, an event
// this system does not have); the integrator table falls back to the physical variables there.
// Tolerances: rtol as given; atol relative to the scales X^{1/2}, v0 and t_H of u, v and t
// (ContactSystem::state_scale).
// The integrator is a callable integrate(system, y, tau0, tau1, observer) ->
// IntegrationStats over the system ContactUntil<Law> below.
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/contact_environments.hpp"
#include "hertzdash/model/contact_system.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace hertzdash {

namespace detail {

/// The regularised contact, stopped at separation or at its observation time, 20 undamped
/// contact times after onset (the end of a contact that never separates).
template <DampingLaw Law>
struct ContactUntil : ContactSystem<Law, FixedWall> {
  ContactUntil(const ImpactConditions& c, const DampingSettings& s, double gravity_mps2)
      : ContactSystem<Law, FixedWall>(c, s, FixedWall{gravity_mps2}) {
    this->set_observation_time_s(20.0 * this->state_scale()[2]);
  }
  EventAction handle_event(int which, double tau, const typename ContactSystem<Law, FixedWall>::State& y) const {
    if (which == event_index(ContactEvent::observation_time)) return EventAction::stop;
    return ContactSystem<Law, FixedWall>::handle_event(which, tau, y);
  }
};

/// Builds the summary (and the optional trace, physical variables) from the steps.
template <DampingLaw Law>
class RegularizedImpactObserver {
  using State = typename ContactSystem<Law, FixedWall>::State;

 public:
  RegularizedImpactObserver(const ContactUntil<Law>& sys, const DropTestSetup& setup, double t_onset_s,
                            ImpactSummary& s, std::vector<TraceSample>* trace)
      : sys_(&sys), gravity_mps2_(setup.gravity_mps2), mass_kg_(setup.mass_kg), height_m_(setup.height_m),
        t_onset_s_(t_onset_s), s_(&s), trace_(trace) {}

  void on_step(double, const State& y) {
    const double F = sys_->force(y), x = y[0] * y[0];
    s_->peak_force_N = std::max(s_->peak_force_N, F);
    s_->max_deformation_m = std::max(s_->max_deformation_m, x);
    if (trace_)
      trace_->push_back(rigid_trace_sample(t_onset_s_ + y[2], x, y[1], F, gravity_mps2_ - F / mass_kg_, x + height_m_, y[1]));
  }
  void on_event(int which, double, const State& y, EventAction) {
    if (which != event_index(ContactEvent::separation)) return;
    s_->separated = true;
    s_->t_separation_s = t_onset_s_ + y[2];
    s_->rebound_velocity_mps = std::max(-y[1], 0.0);
  }

 private:
  const ContactUntil<Law>* sys_;
  double gravity_mps2_, mass_kg_, height_m_;
  double t_onset_s_;
  ImpactSummary* s_;
  std::vector<TraceSample>* trace_;
};

}  // namespace detail

/// The impact of a validated set-up without the tension clamp (see above): fills the
/// fields of `s` that describe the impact and the work (the caller derives contact time
/// and e_effective).
template <DampingLaw Law, class Integrate>
void run_regularized_impact(const DropTestSetup& setup, Integrate&& integrate, ImpactSummary& s,
                            std::vector<TraceSample>* trace) {
  const double K = hertz_stiffness(setup);
  const double v0 = approach_speed(setup);  // [m/s], exact for the fall from rest
  const double t_onset_s = setup.impact_velocity_mps ? 0.0 : v0 / setup.gravity_mps2;
  const ImpactConditions c{K, setup.mass_kg, v0, setup.restitution};
  detail::ContactUntil<Law> sys(c, setup.damping, setup.gravity_mps2);

  s.K = K;
  s.t_onset_s = t_onset_s;
  s.impact_velocity_mps = v0;
  s.law_coefficients = sys.law().coefficients();
  detail::RegularizedImpactObserver<Law> observer(sys, setup, t_onset_s, s, trace);
  auto y = sys.initial_state();
  // tau is bounded by the events (t reaches 20 contact times, or separation); the end
  // only has to lie beyond them: 1e7 tau scales X^{1/2}/(2 v0), dt/dtau = 2u at u ~ X^{1/2}.
  const double tau_end = 1e7 * sys.state_scale()[0] / (2.0 * v0);
  s.work = integrate(sys, y, 0.0, tau_end, observer);
}

}  // namespace hertzdash
