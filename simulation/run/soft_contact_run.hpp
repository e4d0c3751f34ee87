#pragma once
// The definition of make_soft_contact_of<Law, Env> (simulation/run/soft_contact.hpp): the
// contact system (model/contact_system.hpp) run by the integrator row chosen once per run.
// Included only by simulation/run/law_runs_definition.hpp, in each law's generated unit.
#include "hertzdash/model/contact_system.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"  // with_calibrated_time_constant
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/soft_contact.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <type_traits>

namespace hertzdash {

namespace detail {

/// The peak force from the steps (the peak-force event lands one), the environment's state and
/// the separation.
template <class System, class Env>
struct SoftContactObserver {
  const System* sys;
  SoftContactOutcome<Env>* out;
  void on_step(double, const typename System::State& y) {
    out->peak_force_N = std::max(out->peak_force_N, sys->force(y));
    reached(y);
  }
  void on_event(int which, double, const typename System::State& y, EventAction) {
    reached(y);
    if (which != event_index(ContactEvent::separation)) return;
    out->separated = true;
    out->rebound_speed_mps = std::max(-y[1], 0.0);
  }
  void reached(const typename System::State& y) {
    out->contact_time_s = y[2];
    for (int i = 0; i < Env::extra_dimension; ++i) out->environment[i] = y[3 + i];
  }
};

template <DampingLaw Law, class Env, class Row>
class SoftContactOf final : public SoftContact<Env> {
 public:
  SoftContactOf(const DropTestSetup& setup, const SolverSettings& solver)
      : K_(hertz_stiffness(setup)), mass_kg_(setup.mass_kg), e_(setup.restitution),
        speed_limit_mps_(std::sqrt(4.0 * K_ * std::pow(setup.ball_radius_m, 2.5) / (5.0 * mass_kg_))),
        damping_(setup.damping), solver_(solver) {}

  SoftContactOutcome<Env> run(const Env& env, double v0_mps, double t_obs_s) override {
    SoftContactOutcome<Env> out;
    out.hertz_speed_limit_mps = speed_limit_mps_;
    ContactSystem<Law, Env> sys(ImpactConditions{K_, mass_kg_, v0_mps, e_}, damping_, env, t_obs_s);
    SoftContactObserver<ContactSystem<Law, Env>, Env> observer{&sys, &out};
    auto y = sys.initial_state();
    const double tau_end = regularised_tau_end(t_obs_s, sys.state_scale());
    out.work = Row::integrate(sys, y, 0.0, tau_end, solver_, workspace_, observer);
    return out;
  }
  IntegratorKind integrator_used() const override { return Row::traits.kind; }

 private:
  double K_, mass_kg_, e_, speed_limit_mps_;
  DampingSettings damping_;
  SolverSettings solver_;
  IntegratorWorkspace workspace_;
};

}  // namespace detail

template <DampingLaw Law, class Env>
std::unique_ptr<SoftContact<Env>> make_soft_contact_of(const DropTestSetup& setup, const SolverSettings& solver,
                                                       std::string_view command) {
  const std::string cmd(command);
  if (setup.no_tension)
    throw InvalidParameter("no-tension", "on", "off for `" + cmd + "` (the tension clamp needs the physical "
                                               "variables, whose system has no moving other body)");
  if (setup.elastic_rod) throw InvalidParameter("rod-model", "elastic", "rigid for `" + cmd + "`");
  DropTestSetup calibrated = setup;
  if constexpr (MaterialTimeConstantLaw<Law>)
    if (!Law::material_constant(setup.damping)) calibrated = with_calibrated_time_constant<Law>(setup);
  const IntegratorKind used = integrator_used(solver.integrator, ImpactNeeds{.root_polynomial_law = RootPolynomialLaw<Law>});
  std::unique_ptr<SoftContact<Env>> out;
  with_integrator_row(used, [&]<class Row>(std::type_identity<Row>) {
    if constexpr (Row::traits.variables == Variables::regularized) {
      if constexpr (Row::traits.method != IntegratorMethod::taylor || PolynomialOdeSystem<ContactSystem<Law, Env>>)
        out = std::make_unique<detail::SoftContactOf<Law, Env, Row>>(calibrated, solver);
    }
  });
  if (!out)
    throw InvalidParameter("integrator", to_string(solver.integrator),
                           "an integrator in regularising variables for `" + cmd + "` (" +
                               regularising_integrator_names() +
                               "): the other body's motion is a forcing of the regularised contact only "
                               "(model/contact_system.hpp)");
  return out;
}

}  // namespace hertzdash
