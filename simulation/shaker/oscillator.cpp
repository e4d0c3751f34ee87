// The impact oscillator with a stop (simulation/shaker/oscillator.hpp).
#include "hertzdash/simulation/shaker/oscillator.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/soft_contact.hpp"

#include <cmath>
#include <memory>
#include <numbers>

namespace hertzdash {

void validate(const OscillatorOptions& o) {
  require_positive("stiffness", o.stiffness_N_per_m, "N/m");
  if (!(o.damping_ratio >= 0 && o.damping_ratio < 1))
    throw InvalidParameter("damping-ratio", format_value(o.damping_ratio), "in [0, 1)");
  require_non_negative("force-amplitude", o.force_amplitude_N, "N");
  require_positive("frequency", o.frequency_Hz, "Hz");
  require_positive("stop-distance", o.stop_distance_m, "m");
  if (!(o.start_position_m < o.stop_distance_m))
    throw InvalidParameter("start-position", format_value(o.start_position_m), "below `stop-distance`");
  if (!std::isfinite(o.start_velocity_mps))
    throw InvalidParameter("start-velocity", format_value(o.start_velocity_mps), "a finite speed [m/s]");
  validate_impact_counts(o.impacts, o.transient);
}

OscillatorRun run_oscillator(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                             const OscillatorOptions& o) {
  validate(setup);
  validate(solver);
  validate(o);
  const double m = setup.mass_kg, k = o.stiffness_N_per_m, d = o.stop_distance_m, w = 2 * std::numbers::pi * o.frequency_Hz;
  const ForcedOscillator body{.mass_kg = m, .stiffness_N_per_m = k, .damping_ratio = o.damping_ratio,
                              .force_amplitude_N = o.force_amplitude_N, .omega_rad_per_s = w,
                              .force_phase_rad = std::numbers::pi / 2};
  ImpactSequenceSpec spec{.body = body, .prescribed = OscillatorMotion::prescribed(0, w),
                          .walls = {{.name = "stop", .sigma = -1, .offset_m = d}}, .frequency_Hz = o.frequency_Hz,
                          .speed_scale_mps = (o.force_amplitude_N + k * d) / (m * o.frequency_Hz),
                          .y0_m = o.start_position_m, .u0_mps = o.start_velocity_mps, .impacts = o.impacts,
                          .transient = o.transient, .restitution = setup.restitution, .pattern = o.pattern,
                          .energy = true, .sampled = ImpactSequenceSpec::Sampled::body};
  std::unique_ptr<SoftContact<OscillatorStop>> contact;
  if (o.impact_model == ShakerImpactModel::soft) {  // the stop's contact (model/contact_environments.hpp)
    contact = make_soft_contact<OscillatorStop>(law, setup, solver, "oscillator");
    const OscillatorStop stop{k, body.damping_N_s_per_m(), o.force_amplitude_N, w, d};
    spec.soft = [&contact, stop](Wall, double t, double v0, double, double, double t_obs) {
      OscillatorStop at = stop;
      at.t_onset_s = t;
      const auto c = contact->run(at, v0, t_obs);
      return SoftImpact{.separated = c.separated, .contact_time_s = c.contact_time_s,
                        .rebound_speed_mps = c.rebound_speed_mps, .peak_force_N = c.peak_force_N, .work = c.work};
    };
  }
  OscillatorRun out{run_impact_sequence(spec)};
  out.impact_model = o.impact_model;
  if (contact) out.integrator_used = contact->integrator_used();
  out.steady_amplitude_m = body.steady_amplitude_m();
  return out;
}

}  // namespace hertzdash
