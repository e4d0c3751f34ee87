// A prescribed box's soft contacts (simulation/shaker/harmonic_soft_contacts.hpp).
#include "hertzdash/simulation/shaker/harmonic_soft_contacts.hpp"

#include "hertzdash/simulation/run/soft_contact.hpp"

#include <memory>
#include <utility>

namespace hertzdash {

void set_harmonic_soft_contacts(SequenceSetUp& out, std::string_view law, const DropTestSetup& setup,
                                const SolverSettings& solver, std::string_view command, HarmonicEnvironment environment) {
  std::shared_ptr<SoftContact<HarmonicForcing>> contact = make_soft_contact<HarmonicForcing>(law, setup, solver, command);
  out.integrator_used = contact->integrator_used();
  out.spec.hertz_speed_limit_mps = hertz_scale(setup).speed_at_bound_mps;
  out.spec.soft = [contact, environment](Wall wall, double t, double v0, double, double, double t_obs) {
    return soft_impact(contact->run(environment(wall, t), v0, t_obs));
  };
  if (ContactTangentRun<HarmonicForcing> tangent = make_contact_tangent<HarmonicForcing>(law, setup, solver))
    out.spec.soft_tangent = [tangent = std::move(tangent), environment](Wall wall, double t, double v0, double, double,
                                                                        double t_obs) {
      return tangent(environment(wall, t), v0, t_obs);
    };
}

}  // namespace hertzdash
