#pragma once
// The definition of make_shaker_contact_of<Law> (simulation/shaker/shaker_contact.hpp): the
// shaken contact (model/shaken_contact.hpp) run by the integrator row chosen once per run.
// Included only by the generated translation unit of each registered law.
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/shaken_contact.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/shaker/shaker_contact.hpp"

#include <algorithm>
#include <memory>
#include <type_traits>

namespace hertzdash {

namespace detail {

/// The peak force from the steps (the peak-force event lands one) and the separation.
template <DampingLaw Law>
struct ShakenContactObserver {
  const ShakenContact<Law>* sys;
  ShakerContactOutcome* out;
  void on_step(double, const typename ShakenContact<Law>::State& y) {
    out->peak_force_N = std::max(out->peak_force_N, sys->force(y));
    out->contact_time_s = y[2];
  }
  void on_event(int which, double, const typename ShakenContact<Law>::State& y, EventAction) {
    out->contact_time_s = y[2];
    if (which != event_index(ShakenContactEvent::separation)) return;
    out->separated = true;
    out->rebound_speed_mps = std::max(-y[1], 0.0);
  }
};

template <DampingLaw Law, class Row>
class ShakerContactOf final : public ShakerContact {
 public:
  ShakerContactOf(const DropTestSetup& setup, const SolverSettings& solver, const HarmonicWallMotion& wall)
      : K_(hertz_stiffness(setup)), mass_kg_(setup.mass_kg), e_(setup.restitution), g_(setup.gravity_mps2),
        damping_(setup.damping), wall_(wall), solver_(solver) {}

  ShakerContactOutcome run(double t_onset_s, double v0_mps, double t_obs_s) override {
    ShakerContactOutcome out;
    ShakenContact<Law> sys(ImpactConditions{K_, mass_kg_, v0_mps, e_}, damping_, g_, wall_, t_onset_s, t_obs_s);
    ShakenContactObserver<Law> observer{&sys, &out};
    auto y = sys.initial_state();
    // tau is bounded by the events (separation, or t reaching t_obs); the end lies beyond them
    // for a contact whose u stays above 1e-7 of its scale X^{1/2} on average (dt/dtau = 2u).
    const double tau_end = 1e7 * (t_obs_s + sys.state_scale()[2]) / (2.0 * sys.state_scale()[0]);
    out.work = Row::integrate(sys, y, 0.0, tau_end, solver_, workspace_, observer);
    return out;
  }
  IntegratorKind integrator_used() const override { return Row::traits.kind; }

 private:
  double K_, mass_kg_, e_, g_;
  DampingSettings damping_;
  HarmonicWallMotion wall_;
  SolverSettings solver_;
  IntegratorWorkspace workspace_;
};

}  // namespace detail

template <DampingLaw Law>
std::unique_ptr<ShakerContact> make_shaker_contact_of(const DropTestSetup& setup, const SolverSettings& solver,
                                                      const HarmonicWallMotion& wall) {
  if (setup.no_tension)
    throw InvalidParameter("no-tension", "on", "off for `shaker` (the tension clamp needs the physical variables, "
                                               "whose system has no wall motion)");
  if (setup.elastic_rod)
    throw InvalidParameter("rod-model", "elastic", "rigid for `shaker`");
  const IntegratorKind used = integrator_used(solver.integrator, ImpactNeeds{.root_polynomial_law = RootPolynomialLaw<Law>});
  std::unique_ptr<ShakerContact> out;
  with_integrator_row(used, [&]<class Row>(std::type_identity<Row>) {
    if constexpr (Row::traits.variables == Variables::regularized) {
      if constexpr (Row::traits.method != IntegratorMethod::taylor || PolynomialOdeSystem<ShakenContact<Law>>)
        out = std::make_unique<detail::ShakerContactOf<Law, Row>>(setup, solver, wall);
    }
  });
  if (!out)
    throw InvalidParameter("integrator", to_string(solver.integrator),
                           "an integrator in regularising variables for `shaker` (" + regularising_integrator_names() +
                               "): the wall's motion is a forcing of the regularised contact only "
                               "(simulation/shaker/shaker_contact.hpp)");
  return out;
}

}  // namespace hertzdash
