#include "hertzdash/simulation/shaker/shaker.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/shaker/harmonic_soft_contacts.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace hertzdash {

void validate(const ShakerOptions& o) {
  require_positive("frequency", o.wall.frequency_Hz, "Hz");
  require_non_negative("amplitude", o.wall.amplitude_m, "m");
  validate_impact_counts(o.impacts, o.transient);
  if (o.start_height_m) require_non_negative("height", *o.start_height_m, "m");
  if (o.start_phase && !(*o.start_phase >= 0 && *o.start_phase < 1))
    throw InvalidParameter("start-phase", format_value(*o.start_phase), "in [0, 1)");
}

ShakerStart shaker_start(const ShakerOptions& o, double e, double g) {
  const HarmonicWallMotion& wall = o.wall;
  const double T = wall.period_s(), A = wall.amplitude_m, gamma = shaker_gamma(wall, g);
  const double cos_theta = std::numbers::pi * (1 - e) / ((1 + e) * gamma);
  ShakerStart start{A + g * T * T / 8.0, 0.0};
  if (gamma > 0 && cos_theta <= 1) {
    const double theta = std::acos(cos_theta);
    start = {A * std::sin(theta) + g * T * T / 8.0, theta / (2.0 * std::numbers::pi) + 0.5};
  }
  return {o.start_height_m.value_or(start.height_m), o.start_phase.value_or(start.phase)};
}

SequenceSetUp make_shaker_sequence(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                                   const ShakerOptions& options) {
  validate(setup);
  validate(solver);
  validate(options);
  const double g = setup.gravity_mps2;
  if (!(g > 0)) throw InvalidParameter("gravity", format_value(g), "> 0 for `shaker` (the body must come back)");
  const HarmonicWallMotion& wall = options.wall;
  const double T = wall.period_s(), w = wall.omega_rad_per_s(), m = setup.mass_kg;
  // Released from rest at h0 above the wall's mean position at phase phi0 (see the header).
  const ShakerStart start = shaker_start(options, setup.restitution, g);
  const double t0 = start.phase * T;
  if (start.height_m > 0 && !(start.height_m > wall.position_m(t0)))
    throw InvalidParameter("height", format_value(start.height_m),
                           fmt::format("0 (at rest on the wall) or above the wall at the start, > A sin(2 pi phi0) = "
                                       "{:.6g} m (`start-phase` {:.6g})",
                                       wall.position_m(t0), start.phase));
  SequenceSetUp out{
      .spec = {.body = {.mass_kg = m, .stiffness_N_per_m = 0, .omega_rad_per_s = w, .constant_force_N = -m * g},
               .prescribed = OscillatorMotion::prescribed(wall.amplitude_m, w), .walls = {{.name = "wall"}},
               .frequency_Hz = wall.frequency_Hz, .speed_scale_mps = g * T, .t0_s = t0, .y0_m = start.height_m,
               .carried_by = start.height_m > 0 ? -1 : 0, .impacts = options.impacts, .transient = options.transient,
               .restitution = setup.restitution, .pattern = options.pattern},
      .integrator_used = std::nullopt};
  if (options.impact_model == ShakerImpactModel::soft)
    set_harmonic_soft_contacts(out, law, setup, solver, "hertzdash shaker",
                               [wall, g](Wall, double t) { return harmonic_wall(wall, g, 1.0, t); });
  return out;
}

ShakerRun run_shaker(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                     const ShakerOptions& options) {
  const SequenceSetUp sequence = make_shaker_sequence(setup, law, solver, options);
  ShakerRun out{run_impact_sequence(sequence.spec)};
  out.gamma = shaker_gamma(options.wall, setup.gravity_mps2);
  out.impact_model = options.impact_model;
  if (sequence.integrator_used) out.integrator_used = *sequence.integrator_used;
  return out;
}

}  // namespace hertzdash
