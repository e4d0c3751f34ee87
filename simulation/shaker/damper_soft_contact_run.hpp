#pragma once
// The definition of make_damper_soft_contact_of<Law> (simulation/shaker/damper_soft_contact.hpp):
// the damper's contact (model/damper_contact.hpp) run by the integrator row chosen once per run.
// Included only by the generated translation unit of each registered law.
#include "hertzdash/model/damper_contact.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/shaker/damper_soft_contact.hpp"

#include <algorithm>
#include <memory>
#include <type_traits>

namespace hertzdash {

namespace detail {

template <DampingLaw Law>
struct DamperContactObserver {
  const DamperContact<Law>* sys;
  DamperContactOutcome* out;
  void on_step(double, const typename DamperContact<Law>::State& y) {
    out->peak_force_N = std::max(out->peak_force_N, sys->force(y));
    out->contact_time_s = y[2];
    out->X_m = y[3];
    out->V_mps = y[4];
  }
  void on_event(int which, double, const typename DamperContact<Law>::State& y, EventAction) {
    out->contact_time_s = y[2];
    out->X_m = y[3];
    out->V_mps = y[4];
    if (which != event_index(DamperContactEvent::separation)) return;
    out->separated = true;
    out->rebound_speed_mps = std::max(-y[1], 0.0);
  }
};

template <DampingLaw Law, class Row>
class DamperSoftContactOf final : public DamperSoftContact {
 public:
  DamperSoftContactOf(const DropTestSetup& setup, const SolverSettings& solver, const ForcedOscillator& primary)
      : K_(hertz_stiffness(setup)), mass_kg_(setup.mass_kg), e_(setup.restitution), g_(setup.gravity_mps2),
        damping_(setup.damping), primary_(primary), solver_(solver) {}

  DamperContactOutcome run(double sigma, double t_onset_s, double v0_mps, double X0_m, double V0_mps,
                           double t_obs_s) override {
    DamperContactOutcome out;
    DamperContact<Law> sys(K_, mass_kg_, v0_mps, e_, damping_, g_, primary_, sigma, t_onset_s, X0_m, V0_mps, t_obs_s);
    DamperContactObserver<Law> observer{&sys, &out};
    auto y = sys.initial_state();
    // As the shaker's contact (simulation/shaker/shaker_contact_run.hpp): tau bounded by the events.
    const double tau_end = 1e7 * (t_obs_s + sys.state_scale()[2]) / (2.0 * sys.state_scale()[0]);
    out.work = Row::integrate(sys, y, 0.0, tau_end, solver_, workspace_, observer);
    return out;
  }
  IntegratorKind integrator_used() const override { return Row::traits.kind; }

 private:
  double K_, mass_kg_, e_, g_;
  DampingSettings damping_;
  ForcedOscillator primary_;
  SolverSettings solver_;
  IntegratorWorkspace workspace_;
};

}  // namespace detail

template <DampingLaw Law>
std::unique_ptr<DamperSoftContact> make_damper_soft_contact_of(const DropTestSetup& setup, const SolverSettings& solver,
                                                               const ForcedOscillator& primary) {
  if (setup.no_tension)
    throw InvalidParameter("no-tension", "on", "off for `walls` (the tension clamp needs the physical variables)");
  if (setup.elastic_rod) throw InvalidParameter("rod-model", "elastic", "rigid for `walls`");
  const IntegratorKind used = integrator_used(solver.integrator, ImpactNeeds{.root_polynomial_law = RootPolynomialLaw<Law>});
  std::unique_ptr<DamperSoftContact> out;
  with_integrator_row(used, [&]<class Row>(std::type_identity<Row>) {
    if constexpr (Row::traits.variables == Variables::regularized) {
      if constexpr (Row::traits.method != IntegratorMethod::taylor || PolynomialOdeSystem<DamperContact<Law>>)
        out = std::make_unique<detail::DamperSoftContactOf<Law, Row>>(setup, solver, primary);
    }
  });
  if (!out)
    throw InvalidParameter("integrator", to_string(solver.integrator),
                           "an integrator in regularising variables for `walls` (" + regularising_integrator_names() +
                               ")");
  return out;
}

}  // namespace hertzdash
