// A body between two walls, the driven box and the impact damper (simulation/shaker/two_walls.hpp).
#include "hertzdash/simulation/shaker/two_walls.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/soft_contact.hpp"
#include "hertzdash/simulation/shaker/harmonic_soft_contacts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <numbers>

namespace hertzdash {

const char* to_string(TwoWallsRig r) { return r == TwoWallsRig::box ? "box" : "damper"; }

TwoWallsRig parse_two_walls_rig(std::string_view name) {
  if (name == "box") return TwoWallsRig::box;
  if (name == "damper") return TwoWallsRig::damper;
  throw InvalidParameter("rig", std::string(name), "one of: box, damper");
}

void validate(const TwoWallsOptions& o) {
  require_positive("gap", o.gap_m, "m");
  require_positive("frequency", o.drive.frequency_Hz, "Hz");
  if (o.rig == TwoWallsRig::box) {
    require_non_negative("amplitude", o.drive.amplitude_m, "m");
  } else {
    require_positive("primary-mass", o.primary.mass_kg, "kg");
    require_positive("primary-stiffness", o.primary.stiffness_N_per_m, "N/m");
    if (!(o.primary.damping_ratio >= 0 && o.primary.damping_ratio < 1))
      throw InvalidParameter("primary-damping-ratio", format_value(o.primary.damping_ratio), "in [0, 1)");
    require_non_negative("force-amplitude", o.primary.force_amplitude_N, "N");
  }
  validate_impact_counts(o.impacts, o.transient);
}

SequenceSetUp make_two_walls_sequence(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                                      const TwoWallsOptions& options) {
  validate(setup);
  validate(solver);
  validate(options);
  const double g = setup.gravity_mps2, m = setup.mass_kg, gap = options.gap_m;
  const bool damper = options.rig == TwoWallsRig::damper;
  const double f = options.drive.frequency_Hz, T = 1.0 / f, w = 2.0 * std::numbers::pi * f;

  // The primary alone (between impacts); the box's motion prescribed otherwise.
  ForcedOscillator free = options.primary;
  free.omega_rad_per_s = w;
  free.constant_force_N = 0;
  const double accel_scale = damper ? free.steady_amplitude_m() * w * w : options.drive.peak_acceleration_mps2();
  SequenceSetUp out{
      .spec = {.body = {.mass_kg = m, .stiffness_N_per_m = 0, .omega_rad_per_s = w, .constant_force_N = -m * g},
               .box = free, .walls = {{.name = "floor"}, {.name = "ceiling", .sigma = -1, .offset_m = gap}},
               .frequency_Hz = f, .speed_scale_mps = (g + accel_scale) * T, .y0_m = gap / 2, .impacts = options.impacts,
               .transient = options.transient, .restitution = setup.restitution, .pattern = options.pattern,
               .energy = damper,
               .sampled = damper ? ImpactSequenceSpec::Sampled::box : ImpactSequenceSpec::Sampled::none},
      .integrator_used = std::nullopt};
  ImpactSequenceSpec& spec = out.spec;
  if (!damper) spec.prescribed = OscillatorMotion::prescribed(options.drive.amplitude_m, w);

  // The soft contacts (simulation/run/soft_contact.hpp): the driven box's floor and ceiling, a wall
  // in harmonic motion (sigma per wall); the damper's, the primary moving with the contact. The
  // callbacks share their contact's ownership (SequenceSetUp).
  auto sigma = [](Wall wall) { return wall == Wall::floor ? 1.0 : -1.0; };
  if (options.impact_model == ShakerImpactModel::soft) spec.hertz_speed_limit_mps = hertz_scale(setup).speed_at_bound_mps;
  if (options.impact_model == ShakerImpactModel::soft && damper) {
    std::shared_ptr<SoftContact<SprungPrimary>> contact = make_soft_contact<SprungPrimary>(law, setup, solver, "hertzdash walls");
    out.integrator_used = contact->integrator_used();
    spec.soft = [contact, free, g, sigma](Wall wall, double t, double v0, double X, double V, double t_obs) {
      const auto c = contact->run(SprungPrimary{free, g, sigma(wall), t, X, V}, v0, t_obs);
      SoftImpact s = soft_impact(c);
      s.X_m = c.environment[0], s.V_mps = c.environment[1];
      return s;
    };
    if (ContactTangentRun<SprungPrimary> tangent = make_contact_tangent<SprungPrimary>(law, setup, solver))
      spec.soft_tangent = [tangent = std::move(tangent), free, g, sigma](Wall wall, double t, double v0, double X, double V,
                                                                          double t_obs) {
        return tangent(SprungPrimary{free, g, sigma(wall), t, X, V}, v0, t_obs);
      };
  } else if (options.impact_model == ShakerImpactModel::soft) {
    set_harmonic_soft_contacts(out, law, setup, solver, "hertzdash walls",
                               [drive = options.drive, g, sigma](Wall wall, double t) {
                                 return harmonic_wall(drive, g, sigma(wall), t);
                               });
  }
  return out;
}

TwoWallsRun run_two_walls(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                          const TwoWallsOptions& options) {
  const SequenceSetUp sequence = make_two_walls_sequence(setup, law, solver, options);
  const ImpactSequenceSpec& spec = sequence.spec;
  const bool damper = options.rig == TwoWallsRig::damper;
  TwoWallsRun out{run_impact_sequence(spec)};
  out.rig = options.rig;
  out.impact_model = options.impact_model;
  if (sequence.integrator_used) out.integrator_used = *sequence.integrator_used;
  for (const TwoWallsImpact& i : out.impacts) (i.wall == Wall::floor ? out.floor_impacts : out.ceiling_impacts) += 1;
  out.impacts_per_cycle =
      out.pattern.period > 0 ? static_cast<double>(out.pattern.impacts_per_period) / out.pattern.period : 0.0;
  out.primary_amplitude_m = out.amplitude_m;
  if (damper) {
    const ForcedOscillator& free = spec.box;
    out.primary_amplitude_bare_m = free.steady_amplitude_m();
    ForcedOscillator rigid = carrying(free, spec.body, 0.0);
    rigid.constant_force_N = 0;
    out.primary_amplitude_rigid_m = rigid.steady_amplitude_m();
  }
  return out;
}

}  // namespace hertzdash
