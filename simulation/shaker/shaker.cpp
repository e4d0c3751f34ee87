#include "hertzdash/simulation/shaker/shaker.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/soft_contact.hpp"
#include "hertzdash/simulation/shaker/next_impact.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

namespace hertzdash {

const char* to_string(ShakerImpactModel m) { return m == ShakerImpactModel::soft ? "soft" : "instantaneous"; }

ShakerImpactModel parse_shaker_impact_model(std::string_view name) {
  if (name == "soft") return ShakerImpactModel::soft;
  if (name == "instantaneous") return ShakerImpactModel::instantaneous;
  throw InvalidParameter("impact-model", std::string(name), "one of: soft, instantaneous");
}

void validate(const ShakerOptions& o) {
  require_positive("frequency", o.wall.frequency_Hz, "Hz");
  require_non_negative("amplitude", o.wall.amplitude_m, "m");
  if (!(o.impacts >= 1 && o.impacts <= max_shaker_impacts))
    throw InvalidParameter("impacts", format_value(o.impacts), fmt::format("an integer in [1, {}]", max_shaker_impacts));
  if (!(o.transient >= 0 && o.transient <= max_shaker_impacts - o.impacts))
    throw InvalidParameter("transient", format_value(o.transient),
                           fmt::format("an integer in [0, {}] (with `impacts`)", max_shaker_impacts - o.impacts));
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

namespace {

/// Where the body is between impacts: carried by the wall, or in flight searched from t_from.
struct BodyState {
  bool carried = true;
  double t_s = 0;  ///< carried: since when; in flight: where the search for the next impact starts
  Flight flight;
};

/// The flight of a body released by the wall at its release time after t, and the end of the
/// window where the wall pulls away from it (no impact can occur before: h'' >= 0 there with
/// h = h' = 0 at release, so h > 0): where the search starts. +inf when Gamma <= 1.
BodyState release(const HarmonicWallMotion& wall, double g, double t) {
  const double t_release = release_time_s(wall, g, t);
  BodyState b{.carried = false, .t_s = t_release, .flight = {}};
  if (!std::isfinite(t_release)) return b;
  const double w = wall.omega_rad_per_s(), two_pi = 2.0 * std::numbers::pi;
  const double theta = w * t_release - two_pi * std::floor(w * t_release / two_pi);
  const double theta_end = std::numbers::pi - std::asin(g / wall.peak_acceleration_mps2());
  b.t_s = t_release + std::max(theta_end - theta, 0.0) / w;
  b.flight = Flight{.t0_s = t_release, .y0_m = wall.position_m(t_release), .u0_mps = wall.velocity_mps(t_release),
                    .gravity_mps2 = g};
  return b;
}

}  // namespace

ShakerRun run_shaker(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                     const ShakerOptions& options) {
  validate(setup);
  validate(solver);
  validate(options);
  const double g = setup.gravity_mps2;
  if (!(g > 0)) throw InvalidParameter("gravity", format_value(g), "> 0 for `shaker` (the body must come back)");
  const HarmonicWallMotion& wall = options.wall;
  const double T = wall.period_s();
  ShakerRun out;
  out.gamma = shaker_gamma(wall, g);
  out.impact_model = options.impact_model;

  const bool soft = options.impact_model == ShakerImpactModel::soft;
  std::unique_ptr<SoftContact<HarmonicWall>> contact;
  if (soft) {
    contact = make_soft_contact<HarmonicWall>(law, setup, solver, "shaker");
    out.integrator_used = contact->integrator_used();
  }
  const double e = setup.restitution;
  const double stick_speed = 1e-6 * g * T;  // [m/s], see the header
  const double time_tol = 1e-13 * T;
  const double contact_limit_s = 2.0 * T;
  const long total = static_cast<long>(options.transient) + options.impacts;
  out.impacts.reserve(static_cast<std::size_t>(options.impacts));

  // Released from rest at h0 above the wall's mean position at phase phi0 (see the header).
  const ShakerStart start = shaker_start(options, e, g);
  const double t0 = start.phase * T;
  if (start.height_m > 0 && !(start.height_m > wall.position_m(t0)))
    throw InvalidParameter("height", format_value(start.height_m),
                           fmt::format("0 (at rest on the wall) or above the wall at the start, > A sin(2 pi phi0) = "
                                       "{:.6g} m (`start-phase` {:.6g})",
                                       wall.position_m(t0), start.phase));
  BodyState body{.carried = !(start.height_m > 0), .t_s = t0,
                 .flight = Flight{.t0_s = t0, .y0_m = start.height_m, .u0_mps = 0, .gravity_mps2 = g}};
  long cycle = -1, in_cycle = 0;
  bool chatter_warned = false;
  while (out.impacts_run < total) {
    if (body.carried) {
      ++out.sticking_episodes;
      body = release(wall, g, body.t_s);
      if (!std::isfinite(body.t_s)) {
        out.warnings.push_back(fmt::format("the body rests on the wall for good: gamma = {:.6g} <= 1, the wall never "
                                           "pulls away from it faster than gravity",
                                           out.gamma));
        out.end_reason = "the body rests on the wall (gamma <= 1)";
        break;
      }
    }
    const Flight& f = body.flight;
    const double u = f.velocity_mps(body.t_s);
    const double t_limit =
        body.t_s + 2.0 * (std::abs(u) + std::sqrt(u * u + 4.0 * g * wall.amplitude_m)) / g + T;
    const NextImpact next = next_impact(wall, f, body.t_s, t_limit, time_tol);
    if (!next.found) {
      out.warnings.push_back(fmt::format("no impact found after t = {:.9g} s ({} iterations): the run ends there",
                                         body.t_s, next.iterations));
      out.end_reason = "a flight without impact (see warnings)";
      break;
    }
    const double ti = next.time_s;
    ShakerImpact impact{.time_s = ti, .phase = wall.phase(ti),
                        .impact_speed_mps = std::max(wall.velocity_mps(ti) - f.velocity_mps(ti), 0.0)};
    double t_after = ti;
    const bool wall_pushes = wall.acceleration_mps2(ti) > -g;
    bool carried = false;
    if (!soft) {
      impact.rebound_speed_mps = e * impact.impact_speed_mps;
      carried = impact.rebound_speed_mps < stick_speed && wall_pushes;
    } else if (impact.impact_speed_mps < stick_speed) {
      carried = wall_pushes;  // a touch too slow for a contact: rests, or leaves with the wall pulling away
      impact.rebound_speed_mps = impact.impact_speed_mps;
    } else {
      const auto c = contact->run(HarmonicWall{wall, g, 1.0, ti}, impact.impact_speed_mps, contact_limit_s);
      out.work.add_work(c.work);
      impact.contact_time_s = c.contact_time_s;
      impact.peak_force_N = c.peak_force_N;
      if (!c.separated) {
        out.warnings.push_back(fmt::format("the contact beginning at t = {:.9g} s did not end within {} table "
                                           "cycles: the run ends there",
                                           ti, contact_limit_s / T));
        out.end_reason = "a contact that did not end (see warnings)";
        break;
      }
      impact.rebound_speed_mps = c.rebound_speed_mps;
      t_after = ti + c.contact_time_s;
      carried = impact.rebound_speed_mps < stick_speed && wall.acceleration_mps2(t_after) > -g;
    }
    const long c = static_cast<long>(std::floor(ti * wall.frequency_Hz));
    in_cycle = c == cycle ? in_cycle + 1 : 1;
    cycle = c;
    if (in_cycle > max_impacts_per_cycle && !carried) {
      carried = true;
      if (!chatter_warned)
        out.warnings.push_back(fmt::format("chatter: more than {} impacts in the table cycle beginning at t = {:.9g} "
                                           "s; the body is taken as carried by the wall until it is released",
                                           max_impacts_per_cycle, static_cast<double>(c) * T));
      chatter_warned = true;
    }
    if (out.impacts_run >= options.transient) out.impacts.push_back(impact);
    ++out.impacts_run;
    if (carried) {
      body = BodyState{.carried = true, .t_s = t_after, .flight = {}};
    } else {
      body = BodyState{.carried = false, .t_s = t_after,
                       .flight = Flight{.t0_s = t_after, .y0_m = wall.position_m(t_after),
                                        .u0_mps = wall.velocity_mps(t_after) + impact.rebound_speed_mps,
                                        .gravity_mps2 = g}};
    }
  }
  if (out.end_reason.empty()) out.end_reason = fmt::format("{} impacts run ({} transient)", total, options.transient);

  std::vector<double> t_s, v_mps;
  double e_sum = 0;
  long e_count = 0;
  for (const ShakerImpact& i : out.impacts) {
    t_s.push_back(i.time_s);
    v_mps.push_back(i.impact_speed_mps);
    if (i.impact_speed_mps > 0) {
      e_sum += i.rebound_speed_mps / i.impact_speed_mps;
      ++e_count;
    }
  }
  PatternTolerance tol = options.pattern;
  if (!(tol.speed_scale_mps > 0)) tol.speed_scale_mps = g * T;
  out.pattern = detect_impact_pattern(t_s, v_mps, wall.frequency_Hz, tol);
  out.e_effective = e_count ? e_sum / static_cast<double>(e_count) : std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace hertzdash
