#include "hertzdash/simulation/run/bounce_sequence.hpp"

#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"
#include "hertzdash/simulation/run/law_runs.hpp"
#include "hertzdash/simulation/run/result_checks.hpp"

#include <fmt/format.h>

#include <cmath>

namespace hertzdash {

namespace {

/// Rigid model: one run per impact, flights in closed form (see the header).
void run_rigid_bounces(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                       const BounceOptions& options, BounceSequence& out) {
  ImpactSimulator simulator(solver);
  const double g = setup.gravity_mps2;
  const double v_t = terminal_speed_mps(setup.air_drag, setup.mass_kg, setup.ball_radius_m, g);
  const Fall drop = setup.impact_velocity_mps ? Fall{0.0, *setup.impact_velocity_mps} : fall_from_rest(setup.height_m, g, v_t);
  double v0 = drop.speed_mps, t_onset = drop.time_s;
  DropTestSetup impact = setup;
  impact.air_drag = {};  // contacts without drag (model/air_drag.hpp)
  for (int n = 0; n < options.impacts; ++n) {
    impact.impact_velocity_mps = v0;
    const ImpactSummary r = simulator.run(impact, law);
    if (n == 0) out.integrator_used = r.integrator_used;
    out.work.add_work(r.work);
    BounceImpact b{.onset_time_s = t_onset, .approach_speed_mps = r.impact_velocity_mps,
                   .peak_force_N = r.peak_force_N, .max_deformation_m = r.max_deformation_m, .separated = r.separated,
                   .diagnostics = r.diagnostics};
    if (r.separated) {
      b.contact_time_s = r.contact_time_s;
      b.separation_time_s = t_onset + r.contact_time_s;
      b.rebound_speed_mps = r.rebound_velocity_mps;
    }
    out.impacts.push_back(b);
    if (options.on_impact) options.on_impact(out.impacts.size());
    if (!b.separated || b.rebound_speed_mps < options.min_rebound_velocity_mps) return;
    // The flight from the separation at depth x_s (> 0 where the tension clamp ended contact):
    // up to the apex H above it, down H - x_s to the next onset (in vacuum v = sqrt(v_r^2 - 2 g x_s),
    // a flight of (v_r + v) / g, 2 v_r / g for x_s = 0; with drag model/air_drag.hpp's closed forms).
    const double v_r = b.rebound_speed_mps, x_s = r.separation_deformation_m;
    const std::optional<ReturnFlight> flight = return_flight(v_r, x_s, g, v_t);
    if (!flight) {
      out.end_reason = fmt::format("the rebound ({:.3g} m/s) did not lift the rod clear of the {:.3g} m deformation at "
                                   "which the tension clamp ended contact",
                                   v_r, x_s);
      return;
    }
    t_onset = b.separation_time_s + flight->time_s;
    v0 = flight->landing_speed_mps;
  }
}

std::string end_reason(const BounceSequence& s, const BounceOptions& o) {
  const BounceImpact& last = s.impacts.back();
  if (!last.separated) return "the rod came to rest on the ball";
  if (static_cast<int>(s.impacts.size()) == o.impacts) return fmt::format("{} impacts followed (--bounces)", o.impacts);
  if (last.rebound_speed_mps < o.min_rebound_velocity_mps)
    return fmt::format("rebound {:.3g} m/s below --min-rebound-velocity {:.3g} m/s", last.rebound_speed_mps,
                       o.min_rebound_velocity_mps);
  return "the run's time limit (impacts x (2 v0 / g + 20 undamped contact times)): the rod may have come to rest";
}

}  // namespace

int parse_bounces(double impacts) {
  if (!(impacts >= 1 && impacts <= max_bounces && impacts == std::floor(impacts)))
    throw InvalidParameter("bounces", format_value(impacts), fmt::format("an integer in [1, {}]", max_bounces));
  return static_cast<int>(impacts);
}

void validate(const BounceOptions& o) {
  parse_bounces(o.impacts);
  require_non_negative("min-rebound-velocity", o.min_rebound_velocity_mps, "m/s");
}

ImpactSummary bounce_impact_summary(const BounceImpact& b, const BounceSequence& sequence, const DropTestSetup& setup) {
  ImpactSummary s;
  s.K = hertz_stiffness(setup);
  s.impact_velocity_mps = b.approach_speed_mps;
  s.rebound_velocity_mps = b.rebound_speed_mps;
  s.peak_force_N = b.peak_force_N;
  s.max_deformation_m = b.max_deformation_m;
  s.peak_contact_pressure_Pa = hertz_peak_pressure_Pa(s.K, setup.ball_radius_m, b.max_deformation_m);
  s.contact_time_s = b.contact_time_s;
  s.separated = b.separated;
  s.integrator_used = sequence.integrator_used;
  s.diagnostics = b.diagnostics;
  if (sequence.step_used_s > 0) {
    ElasticRodReport steps;
    steps.elements = setup.elastic_rod ? setup.elastic_rod->elements : 0;
    steps.stable_step_s = sequence.stable_step_s;
    steps.step_used_s = sequence.step_used_s;
    s.elastic_rod = steps;
  }
  return s;
}

std::vector<double> interval_ratios(const std::vector<double>& t) {
  std::vector<double> r;
  for (std::size_t n = 0; n + 2 < t.size(); ++n) r.push_back((t[n + 2] - t[n + 1]) / (t[n + 1] - t[n]));
  return r;
}

BounceSequence run_bounce_sequence(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                                   const BounceOptions& options) {
  validate(setup);
  validate(solver);
  validate(options);
  if (!(setup.gravity_mps2 > 0))
    throw InvalidParameter("gravity", format_value(setup.gravity_mps2),
                           "> 0 for a bounce sequence (without gravity the rod never comes back)");
  BounceSequence out;
  DropTestSetup s = setup;
  const LawRuns& runs = law_runs(law);
  if (runs.calibrated_time_constant) {
    if (!runs.material_constant(s.damping)) s = runs.calibrated_time_constant(s);
    out.viscous_time_constant_s = s.damping.viscous_time_constant_s;
  }
  if (!s.elastic_rod) {
    run_rigid_bounces(s, law, solver, options, out);
  } else {
    if (is_iterated(s.damping.omega_n))
      throw InvalidParameter("omega-n", to_string(s.damping.omega_n),
                             "a variant that is not iterated, for a bounce sequence of the elastic rod");
    if (s.air_drag.active())
      throw InvalidParameter("air-density", format_value(s.air_drag.air_density_kg_per_m3),
                             "0 for the elastic rod, whose flights are integrated without drag (drag acts in the "
                             "rigid model's flights)");
    runs.run_elastic_bounces(s, solver, options, out);
    for (BounceImpact& b : out.impacts)
      b.diagnostics = impact_diagnostics(bounce_impact_summary(b, out, s), s, solver);
  }
  for (const BounceImpact& b : out.impacts) {
    out.onset_times_s.push_back(b.onset_time_s);
    if (b.separated) out.e_velocity_ratio.push_back(b.rebound_speed_mps / b.approach_speed_mps);
  }
  out.e_from_intervals = interval_ratios(out.onset_times_s);
  if (out.end_reason.empty()) out.end_reason = end_reason(out, options);
  return out;
}

RestitutionCalibration calibrate_interval_restitution(const DropTestSetup& setup, std::string_view law,
                                                      const SolverSettings& solver, double target) {
  DropTestSetup trial = setup;
  const BounceOptions three{.impacts = 3, .min_rebound_velocity_mps = 0.0};
  return calibrate_input_restitution(
      [&](double e_input) {
        trial.restitution = e_input;
        const BounceSequence b = run_bounce_sequence(trial, law, solver, three);
        return b.e_from_intervals.empty() ? 0.0 : b.e_from_intervals.front();
      },
      target, "target-interval-restitution", fmt::format("first interval ratios law '{}'", law));
}

}  // namespace hertzdash
