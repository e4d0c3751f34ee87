// A soft contact's tangents (simulation/run/soft_contact_tangent.hpp): the law chosen by name
// among the registered ones, its type erased (ContactForceJets), so that the tangent system and
// Dormand-Prince are compiled once.
#include "hertzdash/simulation/run/soft_contact_tangent.hpp"

#include "hertzdash/integrators/dormand_prince.hpp"
#include "hertzdash/model/contact_system.hpp"
#include "hertzdash/model/contact_tangent_system.hpp"
#include "hertzdash/model/damping/registered_law_types.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"  // with_calibrated_time_constant

#include <memory>

namespace hertzdash {

namespace {

/// Keeps whether the contact separated.
struct SeparationObserver {
  bool separated = false;
  template <class State> void on_step(double, const State&) {}
  template <class State> void on_event(int which, double, const State&, EventAction) {
    separated = separated || which == event_index(TangentContactEvent::separation);
  }
};

using LawMaker = std::unique_ptr<ContactForceJets> (*)(const ImpactConditions&, const DampingSettings&);

}  // namespace

std::string contact_tangent_laws() {
  std::string out;
  for_each_damping_law([&]<class Law>(std::type_identity<Law>) {
    if constexpr (SpeedDerivativeLaw<Law>) out += (out.empty() ? "" : ", ") + std::string(Law::info.name);
  });
  return out;
}

template <class Env>
ContactTangentRun<Env> make_contact_tangent(std::string_view law, const DropTestSetup& setup, const SolverSettings& solver) {
  using TangentSystem = ContactTangentSystem<Env>;
  LawMaker make = nullptr;
  DropTestSetup calibrated = setup;
  with_damping_law(law, [&]<class Law>(std::type_identity<Law>) {
    if constexpr (SpeedDerivativeLaw<Law>) {
      make = [](const ImpactConditions& c, const DampingSettings& s) -> std::unique_ptr<ContactForceJets> {
        return std::make_unique<LawForceJets<Law>>(c, s);
      };
      if constexpr (MaterialTimeConstantLaw<Law>)
        if (!Law::material_constant(setup.damping)) calibrated = with_calibrated_time_constant<Law>(setup);
    }
  });
  if (!make) return {};
  const double K = hertz_stiffness(calibrated), m = calibrated.mass_kg, e = calibrated.restitution;
  const DampingSettings damping = calibrated.damping;
  const DormandPrinceOptions options{.rtol = solver.rtol, .atol = solver.atol, .singular_points = false};
  return [make, K, m, e, damping, options](const Env& env, double v0, double t_obs) {
    const std::unique_ptr<ContactForceJets> force = make(ImpactConditions{K, env.reduced_mass_kg(m), v0, e}, damping);
    TangentSystem sys(*force, env, K, m, v0, t_obs);
    typename TangentSystem::State y = sys.initial_state();
    SeparationObserver observer;
    const double tau_end = regularised_tau_end(t_obs, sys.state_scale());
    ContactTangent out;
    out.work = integrate_dormand_prince(sys, y, 0.0, tau_end, options, observer);
    // Rows t_c = t, v_sep = -v, the other body's z_k; column p from S_p (see the header).
    constexpr int D = TangentSystem::base_dimension, P = TangentSystem::parameters, N = Env::onset_state_dimension;
    out.separated = observer.separated;
    out.contact_time_s = y[2];
    out.rebound_speed_mps = -y[1];
    out.other_state = y.template segment<N>(3);
    out.jacobian.resize(P, P);
    for (int p = 0; p < P; ++p) {
      const int S = (1 + p) * D;
      out.jacobian(0, p) = y[S + 2];
      out.jacobian(1, p) = -y[S + 1];
      for (int k = 0; k < N; ++k) out.jacobian(2 + k, p) = y[S + 3 + k];
    }
    return out;
  };
}

template ContactTangentRun<HarmonicForcing> make_contact_tangent<HarmonicForcing>(std::string_view, const DropTestSetup&,
                                                                                  const SolverSettings&);
template ContactTangentRun<SprungPrimary> make_contact_tangent<SprungPrimary>(std::string_view, const DropTestSetup&,
                                                                              const SolverSettings&);

}  // namespace hertzdash
