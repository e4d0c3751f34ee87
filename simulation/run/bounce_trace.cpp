#include "hertzdash/simulation/run/bounce_trace.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

namespace hertzdash {

std::vector<TraceSample> bounce_trace(const BounceSequence& sequence, const DropTestSetup& setup,
                                      std::string_view law, const SolverSettings& solver) {
  if (setup.elastic_rod)
    throw InvalidParameter("rod-model", "elastic",
                           "rigid for a bounce `trace` (the elastic rod's flights are integrated with the rod "
                           "ringing; its sequence records no time series)");
  DropTestSetup impact = setup;
  impact.damping.viscous_time_constant_s = sequence.viscous_time_constant_s;  // the A the sequence used
  impact.air_drag = {};  // contacts without drag, as the sequence ran them (model/air_drag.hpp)
  const double v_t = terminal_speed_mps(setup.air_drag, setup.mass_kg, setup.ball_radius_m, setup.gravity_mps2);
  const double g = setup.gravity_mps2, release_height_m = setup.impact_velocity_mps ? 0.0 : setup.height_m;
  ImpactSimulator simulator(solver);
  std::vector<TraceSample> out, contact;
  for (std::size_t n = 0; n < sequence.impacts.size(); ++n) {
    const BounceImpact& b = sequence.impacts[n];
    impact.impact_velocity_mps = b.approach_speed_mps;
    contact.clear();
    simulator.run(impact, law, &contact);
    if (contact.empty()) continue;  // every run records its onset; nothing to place otherwise
    // The run's clock starts at its own onset; the sequence's at the release.
    const double shift_s = b.onset_time_s - contact.front().t_s;
    for (TraceSample s : contact) {
      s.t_s += shift_s;
      s.rod_displacement_m = release_height_m + s.x_m;
      // CVODE's first steps are as short as 1e-15 s, below the resolution of a clock that reads
      // tenths of a second: a sample that does not advance it is left out, so time increases strictly.
      if (out.empty() || s.t_s > out.back().t_s) out.push_back(s);
    }
    if (!b.separated || n + 1 == sequence.impacts.size()) break;
    // The flight: the face leaves at depth x_s with the rebound speed upward, decelerated by g
    // (and the air's drag), and returns at the next onset (bounce_sequence.cpp); x = x_s - y(tau),
    // y the height above the separation (model/air_drag.hpp: x_s - v_r tau + g tau^2 / 2 in vacuum).
    const TraceSample& last = out.back();
    const double x_s = last.x_m, v_r = b.rebound_speed_mps, t_sep = b.separation_time_s;
    const double flight_s = sequence.impacts[n + 1].onset_time_s - t_sep;
    for (int k = 1; k < bounce_flight_samples; ++k) {
      const double tau = flight_s * k / bounce_flight_samples;
      const FlightPoint p = flight_point(v_r, tau, g, v_t);
      const double x = x_s - p.height_m, xdot = -p.upward_velocity_mps;
      out.push_back(rigid_trace_sample(t_sep + tau, x, xdot, 0.0, g, release_height_m + x, xdot));
    }
  }
  return out;
}

}  // namespace hertzdash
