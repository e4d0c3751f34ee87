#pragma once
// One drop test in the physical variables: the drop test system of model/drop_test.hpp
// (free fall, then contact from the gap event) with any integrator of the table whose
// row has Variables::physical. Fills the summary (and the optional trace) from the
// accepted steps and the fired events.
//
// The run ends at separation, or, if the rod comes to rest on the ball, 20 undamped
// contact times after onset: long enough for any impact to end.
// The integrator is a callable integrate(system, y, t0, t1, observer) -> IntegrationStats.
#include "hertzdash/model/drop_test.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"

#include <algorithm>
#include <vector>

namespace hertzdash {

namespace detail {

/// Builds the summary (and the optional trace) from the steps and events.
template <class System>
class ImpactObserver {
 public:
  ImpactObserver(const System& sys, ImpactSummary& summary, std::vector<TraceSample>* trace)
      : sys_(&sys), s_(&summary), trace_(trace) {}

  void on_step(double t, const typename System::State& y) {
    if (sys_->in_contact()) sample(t, y);
  }
  void on_event(int which, double t, const typename System::State& y, EventAction action) {
    if (which == event_index(DropTestEvent::contact) && action == EventAction::restart) begin(t, y);
    if (action == EventAction::stop) {
      s_->separated = true;
      s_->t_separation_s = t;
      s_->separation_deformation_m = std::max(y[0], 0.0);
      s_->rebound_velocity_mps = std::max(-y[1], 0.0);
    }
  }
  void begin(double t, const typename System::State& y) {
    s_->t_onset_s = t;
    s_->impact_velocity_mps = y[1];
    s_->law_coefficients = sys_->law().coefficients();
    sample(t, y);
  }

 private:
  void sample(double t, const typename System::State& y) {
    const double F = sys_->contact_force(y);
    s_->peak_force_N = std::max(s_->peak_force_N, F);
    s_->max_deformation_m = std::max(s_->max_deformation_m, y[0]);
    if (trace_) {
      const auto& m = sys_->model();
      trace_->push_back(rigid_trace_sample(t, y[0], y[1], F, m.gravity_mps2 - F / m.mass_kg, y[0] + m.setup.height_m, y[1]));
    }
  }
  const System* sys_;
  ImpactSummary* s_;
  std::vector<TraceSample>* trace_;
};

}  // namespace detail

/// The drop test of a validated set-up in the physical variables: fills the fields of `s`
/// that describe the impact and the work (the caller derives contact time and e_effective).
template <DampingLaw Law, class Integrate>
void run_physical_impact(const DropTestSetup& setup, Integrate&& integrate, ImpactSummary& s,
                         std::vector<TraceSample>* trace) {
  const DropTestModel model(setup);
  DropTest<Law> sys(model);
  s.K = model.K;
  detail::ImpactObserver<DropTest<Law>> observer(sys, s, trace);
  auto y = sys.initial_state();
  if (sys.in_contact()) observer.begin(0.0, y);

  const double v0 = approach_speed(setup);
  const double fall_s = setup.impact_velocity_mps ? 0.0 : v0 / setup.gravity_mps2;
  const double t_end = fall_s + 20.0 * undamped_hertz_impact(model.K, model.mass_kg, v0).contact_time_s;
  s.work = integrate(sys, y, 0.0, t_end, observer);
}

}  // namespace hertzdash
