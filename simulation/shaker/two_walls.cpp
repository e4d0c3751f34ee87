// A body between two walls, the driven box and the impact damper (simulation/shaker/two_walls.hpp).
#include "hertzdash/simulation/shaker/two_walls.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/soft_contact.hpp"
#include "hertzdash/simulation/shaker/safe_root.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

namespace hertzdash {

const char* to_string(TwoWallsRig r) { return r == TwoWallsRig::box ? "box" : "damper"; }

TwoWallsRig parse_two_walls_rig(std::string_view name) {
  if (name == "box") return TwoWallsRig::box;
  if (name == "damper") return TwoWallsRig::damper;
  throw InvalidParameter("rig", std::string(name), "one of: box, damper");
}

const char* to_string(Wall w) { return w == Wall::floor ? "floor" : "ceiling"; }

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
  if (!(o.impacts >= 1 && o.impacts <= max_shaker_impacts))
    throw InvalidParameter("impacts", format_value(o.impacts), fmt::format("an integer in [1, {}]", max_shaker_impacts));
  if (!(o.transient >= 0 && o.transient <= max_shaker_impacts - o.impacts))
    throw InvalidParameter("transient", format_value(o.transient),
                           fmt::format("an integer in [0, {}] (with `impacts`)", max_shaker_impacts - o.impacts));
}

namespace {

constexpr int samples_per_cycle = 64;
constexpr double max_flight_cycles = 10000;  // the longest flight searched, in drive cycles
// 8-point Gauss-Legendre on [-1, 1]: nodes +-x, weights w (Abramowitz and Stegun, Table 25.4).
constexpr std::array<double, 4> gauss_x{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                        0.9602898564975363};
constexpr std::array<double, 4> gauss_w{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                        0.1012285362903763};

double sign_of(Wall w) { return w == Wall::floor ? 1.0 : -1.0; }

/// The window of the primary's amplitude and the damper's energy integrals, piece by piece.
struct Accounting {
  bool damper = false;
  double frequency_Hz = 1, force_amplitude_N = 0, damping_N_s_per_m = 0, max_piece_s = 1;
  bool keeping = false;
  double x_min = INFINITY, x_max = -INFINITY;
  EnergyAccount* energy = nullptr;

  void sample(double x) {
    x_min = std::min(x_min, x);
    x_max = std::max(x_max, x);
  }
  /// The box moving as `box` on [ta, tb].
  void segment(const OscillatorMotion& box, double ta, double tb) {
    if (!damper || !(tb > ta)) return;
    const double w = 2.0 * std::numbers::pi * frequency_Hz;
    const int pieces = static_cast<int>(std::ceil((tb - ta) / max_piece_s));
    const double h = (tb - ta) / pieces;
    for (int p = 0; p < pieces; ++p) {
      const double mid = ta + (p + 0.5) * h;
      for (std::size_t i = 0; i < gauss_x.size(); ++i) {
        for (const double s : {-1.0, 1.0}) {
          const double t = mid + s * gauss_x[i] * 0.5 * h, V = box.velocity_mps(t);
          const double weight = gauss_w[i] * 0.5 * h;
          energy->drive_work_J += weight * force_amplitude_N * std::sin(w * t) * V;
          energy->damping_dissipation_J += weight * damping_N_s_per_m * V * V;
        }
      }
    }
    if (!keeping) return;
    // X at the grid's points and at its extremes: each root of X' between two points, refined by
    // Newton's method (X'' its derivative) kept inside the bracket by bisection.
    const double n = samples_per_cycle * frequency_Hz;
    double t0 = ta, v0 = box.velocity_mps(ta);
    sample(box.position_m(ta));
    for (double k = std::floor(ta * n) + 1;; ++k) {
      const double t1 = std::min(k / n, tb), v1 = box.velocity_mps(t1);
      sample(box.position_m(t1));
      if ((v0 < 0) != (v1 < 0)) {
        double lo = t0, hi = t1, t = 0.5 * (t0 + t1);
        for (int i = 0; i < 60 && hi - lo > 1e-15 * (1.0 + std::abs(t)); ++i) {
          const double v = box.velocity_mps(t);
          ((v < 0) == (v0 < 0) ? lo : hi) = t;
          const double newton = t - v / box.acceleration_mps2(t);
          t = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
        }
        sample(box.position_m(t));
      }
      if (t1 >= tb) break;
      t0 = t1, v0 = v1;
    }
  }
};

}  // namespace

TwoWallsRun run_two_walls(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                          const TwoWallsOptions& options) {
  validate(setup);
  validate(solver);
  validate(options);
  const double g = setup.gravity_mps2, m = setup.mass_kg, e = setup.restitution, gap = options.gap_m;
  const bool damper = options.rig == TwoWallsRig::damper;
  const double f = options.drive.frequency_Hz, T = 1.0 / f, w = 2.0 * std::numbers::pi * f;
  TwoWallsRun out;
  out.rig = options.rig;
  out.impact_model = options.impact_model;

  // The primary alone (between impacts) and with the body carried (mass M + m, its weight on it).
  ForcedOscillator free = options.primary;
  free.omega_rad_per_s = w;
  free.constant_force_N = 0;
  ForcedOscillator carrying = free;
  carrying.mass_kg += m;
  carrying.constant_force_N = -m * g;
  carrying.damping_ratio = free.damping_N_s_per_m() / (2.0 * std::sqrt(free.stiffness_N_per_m * carrying.mass_kg));
  const double M = free.mass_kg;
  OscillatorMotion box = damper ? OscillatorMotion(free, 0.0, 0.0, 0.0)
                                : OscillatorMotion::prescribed(options.drive.amplitude_m, w);
  const double accel_scale = damper ? free.steady_amplitude_m() * w * w : options.drive.peak_acceleration_mps2();
  if (damper) {
    out.primary_amplitude_bare_m = free.steady_amplitude_m();
    ForcedOscillator rigid = carrying;
    rigid.constant_force_N = 0;
    out.primary_amplitude_rigid_m = rigid.steady_amplitude_m();
  }

  // The soft contacts (simulation/run/soft_contact.hpp): the driven box's floor and ceiling, a wall
  // in harmonic motion; the damper's, the primary moving with the contact.
  const bool soft = options.impact_model == ShakerImpactModel::soft;
  std::unique_ptr<SoftContact<HarmonicWall>> contact;
  std::unique_ptr<SoftContact<SprungPrimary>> damper_contact;
  if (soft && damper) {
    damper_contact = make_soft_contact<SprungPrimary>(law, setup, solver, "walls");
    out.integrator_used = damper_contact->integrator_used();
  } else if (soft) {
    contact = make_soft_contact<HarmonicWall>(law, setup, solver, "walls");
    out.integrator_used = contact->integrator_used();
  }

  const double stick_speed = 1e-6 * (g + accel_scale) * T;
  const double time_tol = 1e-13 * T;
  const double search_span_s =
      100.0 * T + (damper ? 4.0 * 2.0 * std::numbers::pi / carrying.natural_omega_rad_per_s() : 0.0);
  const long total = static_cast<long>(options.transient) + options.impacts;
  out.impacts.reserve(static_cast<std::size_t>(options.impacts));

  Accounting account{.damper = damper, .frequency_Hz = f, .force_amplitude_N = free.force_amplitude_N,
                     .damping_N_s_per_m = free.damping_N_s_per_m(),
                     .max_piece_s = std::min(T, 2.0 * std::numbers::pi / free.natural_omega_rad_per_s()) / 16.0,
                     .energy = &out.energy};
  // The body: carried by `wall` since t_now, or in flight, each wall's search starting at search_from[wall].
  bool carried = false;
  Wall wall = Wall::floor;
  double t_now = 0;
  Flight flight{.t0_s = 0, .y0_m = gap / 2, .u0_mps = 0, .gravity_mps2 = g};
  std::array<double, 2> search_from{0.0, 0.0};
  auto energy_now = [&]() {
    const double X = box.position_m(t_now), V = box.velocity_mps(t_now);
    const double u = carried ? V : flight.velocity_mps(t_now);
    const double y = carried ? X + (wall == Wall::ceiling ? gap : 0.0) : flight.height_m(t_now);
    return 0.5 * M * V * V + 0.5 * free.stiffness_N_per_m * X * X + 0.5 * m * u * u + m * g * y;
  };
  if (damper) out.energy.initial_J = energy_now();

  long cycle = -1, in_cycle = 0;
  bool chatter_warned = false;
  while (out.impacts_run < total) {
    if (carried) {
      // Leave where the contact force sigma m (X'' + g) reaches zero; then the gap just left keeps
      // h'' = -sigma (X'' + g) >= 0 until that changes sign again: its search starts there.
      ++out.sticking_episodes;
      const double sigma = sign_of(wall);
      auto force = [&](double t) { return sigma * (box.acceleration_mps2(t) + g); };
      auto force_rate = [&](double t) { return sigma * box.derivative(3, t); };
      double t_release = t_now;
      if (force(t_now) >= 0) {
        // A force that only touches zero (Gamma = 1 exactly: the box's deceleration reaches g and
        // no more) does not release the body: the search goes on past the touch.
        SafeRoot r;
        for (double from = t_now;;) {
          r = first_safe_root(force, force_rate, box.derivative_bound(4), from, t_now + search_span_s, time_tol);
          if (!r.found || !r.grazing) break;
          from = r.time_s + 1e-9 * T;
          if (force(from) < 0) break;
        }
        if (!r.found) {
          out.warnings.push_back(fmt::format("the body rests on the {} for good from t = {:.9g} s: the box never "
                                             "accelerates away from it faster than gravity",
                                             to_string(wall), t_now));
          out.end_reason = "the body rests on a wall (see warnings)";
          break;
        }
        t_release = r.time_s;
      }
      account.segment(box, t_now, t_release);
      const double X = box.position_m(t_release), V = box.velocity_mps(t_release);
      if (damper) box = OscillatorMotion(free, t_release, X, V);
      t_now = t_release;
      carried = false;
      flight = Flight{.t0_s = t_release, .y0_m = X + (wall == Wall::ceiling ? gap : 0.0), .u0_mps = V, .gravity_mps2 = g};
      auto pull = [&](double t) { return -sigma * (box.acceleration_mps2(t) + g); };
      auto pull_rate = [&](double t) { return -sigma * box.derivative(3, t); };
      const double limit = t_release + search_span_s;
      const SafeRoot window = first_safe_root(pull, pull_rate, box.derivative_bound(4), t_release, limit, time_tol);
      search_from = {t_release, t_release};
      search_from[static_cast<int>(wall)] = window.found ? window.time_s : limit;
    }

    // The next impact: the earlier first root of the two gaps (the ceiling's searched up to the floor's).
    const double M_bound = g + box.derivative_bound(2);
    auto h_floor = [&](double t) { return flight.height_m(t) - box.position_m(t); };
    auto dh_floor = [&](double t) { return flight.velocity_mps(t) - box.velocity_mps(t); };
    auto h_ceiling = [&](double t) { return box.position_m(t) + gap - flight.height_m(t); };
    auto dh_ceiling = [&](double t) { return box.velocity_mps(t) - flight.velocity_mps(t); };
    // Searched span by span (each point passed certified root-free) up to max_flight_cycles.
    SafeRoot on_floor, on_ceiling;
    double limit = t_now;
    while (!on_floor.found && !on_ceiling.found && limit < t_now + max_flight_cycles * T) {
      limit += search_span_s;
      on_floor = first_safe_root(h_floor, dh_floor, M_bound, search_from[0], limit, time_tol);
      on_ceiling = first_safe_root(h_ceiling, dh_ceiling, M_bound, search_from[1],
                                   on_floor.found ? on_floor.time_s : limit, time_tol);
      if (on_floor.root_free_to_s < limit || on_ceiling.root_free_to_s < limit) break;  // the iteration cap
      search_from = {on_floor.root_free_to_s, on_ceiling.root_free_to_s};
    }
    if (!on_floor.found && !on_ceiling.found) {
      out.warnings.push_back(fmt::format("no impact found between t = {:.9g} s and {:.9g} s: the body never "
                                         "reaches a wall there (the box's motion smaller than the clearance?); "
                                         "the run ends",
                                         t_now, limit));
      out.end_reason = "a flight without impact (see warnings)";
      break;
    }
    const bool ceiling = on_ceiling.found && (!on_floor.found || on_ceiling.time_s < on_floor.time_s);
    const Wall hit = ceiling ? Wall::ceiling : Wall::floor;
    const double ti = ceiling ? on_ceiling.time_s : on_floor.time_s, sigma = sign_of(hit);
    account.segment(box, t_now, ti);
    const double X = box.position_m(ti), V = box.velocity_mps(ti), u = flight.velocity_mps(ti);
    TwoWallsImpact impact{.time_s = ti, .phase = options.drive.phase(ti), .wall = hit,
                          .impact_speed_mps = std::max(sigma * (V - u), 0.0), .box_displacement_m = X};
    double t_after = ti, u_after = u, V_after = V;
    if (!soft) {
      impact.rebound_speed_mps = e * impact.impact_speed_mps;
      if (damper) {
        u_after = u + M * (1 + e) * (V - u) / (m + M);
        V_after = V - m * (1 + e) * (V - u) / (m + M);
        out.energy.impact_loss_J += 0.5 * (1 - e * e) * m * M / (m + M) * (V - u) * (V - u);
        box = OscillatorMotion(free, ti, X, V_after);
      } else {
        u_after = V + e * (V - u);
      }
    } else if (impact.impact_speed_mps < stick_speed) {
      impact.rebound_speed_mps = impact.impact_speed_mps;  // a touch too slow for a contact: carried below
    } else if (damper) {
      const auto c = damper_contact->run(SprungPrimary{free, g, sigma, ti, X, V}, impact.impact_speed_mps, 2.0 * T);
      out.work.add_work(c.work);
      impact.contact_time_s = c.contact_time_s;
      impact.peak_force_N = c.peak_force_N;
      if (!c.separated) {
        out.warnings.push_back(fmt::format("the contact beginning at t = {:.9g} s did not end within 2 drive "
                                           "cycles: the run ends there",
                                           ti));
        out.end_reason = "a contact that did not end (see warnings)";
        break;
      }
      impact.rebound_speed_mps = c.rebound_speed_mps;
      t_after = ti + c.contact_time_s;
      V_after = c.environment[1];
      u_after = V_after + sigma * impact.rebound_speed_mps;
      box = OscillatorMotion(free, t_after, c.environment[0], V_after);
    } else {
      const auto c = contact->run(HarmonicWall{options.drive, g, sigma, ti}, impact.impact_speed_mps, 2.0 * T);
      out.work.add_work(c.work);
      impact.contact_time_s = c.contact_time_s;
      impact.peak_force_N = c.peak_force_N;
      if (!c.separated) {
        out.warnings.push_back(fmt::format("the contact beginning at t = {:.9g} s did not end within 2 drive "
                                           "cycles: the run ends there",
                                           ti));
        out.end_reason = "a contact that did not end (see warnings)";
        break;
      }
      impact.rebound_speed_mps = c.rebound_speed_mps;
      t_after = ti + c.contact_time_s;
      u_after = box.velocity_mps(t_after) + sigma * impact.rebound_speed_mps;
    }
    const long c = static_cast<long>(std::floor(ti * f));
    in_cycle = c == cycle ? in_cycle + 1 : 1;
    cycle = c;
    bool stick = impact.rebound_speed_mps < stick_speed;
    if (in_cycle > max_impacts_per_cycle && !stick) {
      stick = true;
      if (!chatter_warned)
        out.warnings.push_back(fmt::format("chatter: more than {} impacts in the drive cycle beginning at t = {:.9g} "
                                           "s; the body is taken as carried by the {} until it is released",
                                           max_impacts_per_cycle, static_cast<double>(c) * T, to_string(hit)));
      chatter_warned = true;
    }
    if (out.impacts_run == options.transient) account.keeping = true;
    if (account.keeping) {
      out.impacts.push_back(impact);
      account.sample(X);
      account.sample(box.position_m(t_after));
    }
    ++out.impacts_run;
    t_now = t_after;
    if (stick) {
      carried = true;
      wall = hit;
      if (damper) {
        // The body joins the box at the common, momentum-conserving velocity (a loss of order stick_speed^2).
        const double Vc = (m * u_after + M * V_after) / (m + M);
        out.energy.impact_loss_J += 0.5 * m * u_after * u_after + 0.5 * M * V_after * V_after - 0.5 * (m + M) * Vc * Vc;
        box = OscillatorMotion(carrying, t_after, box.position_m(t_after), Vc);
      }
    } else {
      flight = Flight{.t0_s = t_after, .y0_m = box.position_m(t_after) + (ceiling ? gap : 0.0), .u0_mps = u_after,
                      .gravity_mps2 = g};
      search_from = {t_after, t_after};
    }
  }
  if (out.end_reason.empty()) out.end_reason = fmt::format("{} impacts run ({} transient)", total, options.transient);
  out.end_time_s = t_now;
  if (damper) out.energy.final_J = energy_now();
  if (soft) {
    // The contacts' own work (the drive, the primary's damping and the law's dissipation while in
    // contact) is not integrated: no balance to report.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    out.energy = {nan, nan, nan, nan, nan};
  }

  std::vector<double> t_s, v_mps;
  double e_sum = 0;
  long e_count = 0;
  for (const TwoWallsImpact& i : out.impacts) {
    t_s.push_back(i.time_s);
    v_mps.push_back(i.impact_speed_mps);
    (i.wall == Wall::floor ? out.floor_impacts : out.ceiling_impacts) += 1;
    if (i.impact_speed_mps > 0) {
      e_sum += i.rebound_speed_mps / i.impact_speed_mps;
      ++e_count;
    }
  }
  PatternTolerance tol = options.pattern;
  if (!(tol.speed_scale_mps > 0)) tol.speed_scale_mps = (g + accel_scale) * T;
  out.pattern = detect_impact_pattern(t_s, v_mps, f, tol);
  out.impacts_per_cycle =
      out.pattern.period > 0 ? static_cast<double>(out.pattern.impacts_per_period) / out.pattern.period : 0.0;
  out.e_effective = e_count ? e_sum / static_cast<double>(e_count) : std::numeric_limits<double>::quiet_NaN();
  out.primary_amplitude_m = damper && account.x_max >= account.x_min ? 0.5 * (account.x_max - account.x_min)
                                                                      : std::numeric_limits<double>::quiet_NaN();
  return out;
}

}  // namespace hertzdash
