#pragma once
// The bounce sequence of the elastic rod on the load cell (simulation/run/bounce_sequence.hpp):
// model/elastic_drop_test.hpp followed through its separations, flights integrated, with any
// integrator row in the physical variables. Impact records are the centre of mass's speeds
// and the contact's force and deformation, as in elastic_impact.hpp.
#include "hertzdash/model/elastic_drop_test.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/run/bounce_sequence.hpp"
#include "hertzdash/simulation/run/elastic_impact.hpp"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

namespace hertzdash {

namespace detail {

template <class System>
class ElasticBounceObserver {
 public:
  ElasticBounceObserver(const System& sys, double t_onset_s, std::vector<BounceImpact>& impacts,
                        const std::function<void(std::size_t)>& on_impact)
      : sys_(&sys), t0_(t_onset_s), impacts_(&impacts), on_impact_(&on_impact) {}

  void begin(double t, const typename System::State& y) {
    BounceImpact b;
    b.onset_time_s = t0_ + t;
    b.approach_speed_mps = sys_->centre_of_mass_velocity_mps(y);
    impacts_->push_back(b);
  }
  void on_step(double, const typename System::State& y) {
    if (!sys_->in_contact() || impacts_->empty()) return;
    BounceImpact& b = impacts_->back();
    b.peak_force_N = std::max(b.peak_force_N, sys_->contact_force_N(y));
    b.max_deformation_m = std::max(b.max_deformation_m, sys_->deformation_m(y));
  }
  void on_event(int which, double t, const typename System::State& y, EventAction action) {
    if (action == EventAction::continue_integration) return;
    if (which == event_index(ElasticDropTestEvent::contact) && sys_->in_contact()) {  // onset
      begin(t, y);
      return;
    }
    BounceImpact& b = impacts_->back();  // separation, or force zero under the clamp
    b.separated = true;
    b.separation_time_s = t0_ + t;
    b.contact_time_s = b.separation_time_s - b.onset_time_s;
    b.rebound_speed_mps = std::max(-sys_->centre_of_mass_velocity_mps(y), 0.0);
    if (*on_impact_) (*on_impact_)(impacts_->size());
  }

 private:
  const System* sys_;
  double t0_;
  std::vector<BounceImpact>* impacts_;
  const std::function<void(std::size_t)>* on_impact_;
};

}  // namespace detail

/// The elastic sequence of a validated set-up (elastic_rod set) with the integrator row's
/// integrate(system, y, t0, t1, settings, observer): fills out.impacts and out.work.
template <DampingLaw Law, class Integrate>
void run_elastic_bounces(const DropTestSetup& setup, IntegratorKind kind, bool fixed_step,
                         const SolverSettings& settings, const BounceOptions& options, Integrate&& integrate,
                         BounceSequence& out) {
  const ElasticDropTestModel model(setup);
  ElasticDropTest<Law> sys(model);
  sys.follow_impacts(options.impacts, options.min_rebound_velocity_mps);
  // Every flight is at most 2 v0 / g (no impact gains energy), every contact well within 20
  // undamped contact times.
  const double contact_s = undamped_hertz_impact(model.K, setup.mass_kg, model.v0_mps).contact_time_s;
  const double t_end = options.impacts * (2.0 * model.v0_mps / setup.gravity_mps2 + 20.0 * contact_s);
  const SolverSettings used = elastic_solver_settings(model, kind, fixed_step, settings, t_end);
  if (fixed_step) {
    out.step_used_s = used.dt_s;
    out.stable_step_s = elastic_stable_step_s(model, kind);
  }

  const double t_onset_s = setup.impact_velocity_mps ? 0.0 : model.v0_mps / setup.gravity_mps2;
  detail::ElasticBounceObserver<ElasticDropTest<Law>> observer(sys, t_onset_s, out.impacts, options.on_impact);
  auto y = sys.initial_state();
  observer.begin(0.0, y);
  out.work = integrate(sys, y, 0.0, t_end, used, observer);
  out.flights_integrated = true;
}

}  // namespace hertzdash
