// The impact-sequence driver (simulation/shaker/impact_sequence.hpp).
#include "hertzdash/simulation/shaker/impact_sequence.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/shaker/safe_root.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace hertzdash {

const char* to_string(ShakerImpactModel m) { return m == ShakerImpactModel::soft ? "soft" : "instantaneous"; }

ShakerImpactModel parse_shaker_impact_model(std::string_view name) {
  if (name == "soft") return ShakerImpactModel::soft;
  if (name == "instantaneous") return ShakerImpactModel::instantaneous;
  throw InvalidParameter("impact-model", std::string(name), "one of: soft, instantaneous");
}

const char* to_string(Wall w) { return w == Wall::floor ? "floor" : "ceiling"; }

void validate_impact_counts(int impacts, int transient) {
  if (!(impacts >= 1 && impacts <= max_shaker_impacts))
    throw InvalidParameter("impacts", format_value(impacts), fmt::format("an integer in [1, {}]", max_shaker_impacts));
  if (!(transient >= 0 && transient <= max_shaker_impacts - impacts))
    throw InvalidParameter("transient", format_value(transient),
                           fmt::format("an integer in [0, {}] (with `impacts`)", max_shaker_impacts - impacts));
}

namespace {

constexpr int samples_per_cycle = 64;
constexpr double max_flight_cycles = 10000;  // the longest flight searched, in drive cycles
// 8-point Gauss-Legendre on [-1, 1]: nodes +-x, weights w (Abramowitz and Stegun, Table 25.4).
constexpr std::array<double, 4> gauss_x{0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                        0.9602898564975363};
constexpr std::array<double, 4> gauss_w{0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                        0.1012285362903763};
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// One run: the state between impacts (the box's motion, the body's flight or the wall carrying
/// it) and the steps of the header's loop.
class SequenceRun {
 public:
  explicit SequenceRun(const ImpactSequenceSpec& spec) : s_(spec), dynamic_(!spec.prescribed) {
    const double T = 1.0 / s_.frequency_Hz;
    auto period = [](const ForcedOscillator& o) {
      return o.stiffness_N_per_m > 0 ? 2.0 * std::numbers::pi / o.natural_omega_rad_per_s() : 0.0;
    };
    const double body = period(s_.body), box = dynamic_ ? period(s_.box) : 0.0;
    const double longest = std::max({body, box, dynamic_ ? period(carrying(s_.box, s_.body, 0.0)) : 0.0});
    double shortest = T;
    for (const double p : {body, box})
      if (p > 0) shortest = std::min(shortest, p);
    span_s_ = 100.0 * T + 4.0 * longest;
    piece_s_ = shortest / 16.0;
    stick_speed_ = 1e-6 * s_.speed_scale_mps;
    time_tol_ = 1e-13 * T;
    box_ = dynamic_ ? OscillatorMotion(s_.box, s_.t0_s, s_.X0_m, s_.V0_mps) : *s_.prescribed;
    t_now_ = s_.t0_s;
    keeping_ = s_.transient == 0;
    if (s_.carried_by >= 0) {
      const double V = box_.velocity_mps(t_now_);
      carry(static_cast<Wall>(s_.carried_by), V, V);
    } else {
      body_ = OscillatorMotion(s_.body, s_.t0_s, s_.y0_m, s_.u0_mps);
      search_from_ = {t_now_, t_now_};
    }
  }

  ImpactSequence run() {
    if (s_.energy) out_.energy.initial_J = energy_now();
    const long total = static_cast<long>(s_.transient) + s_.impacts;
    // `impacts` may be only a cap (a run to end_time_s asks for max_shaker_impacts): reserve no more
    // than a run of ordinary length keeps, and let a longer one grow (720 MB a call under ASan's shadow
    // poisoning made the orbit code's 10,000 maps take half an hour).
    out_.impacts.reserve(static_cast<std::size_t>(std::min(s_.impacts, 4096)));
    while (out_.impacts_run < total && (!carried_ || release()) && next_impact()) {
    }
    if (out_.end_reason.empty()) out_.end_reason = fmt::format("{} impacts run ({} transient)", total, s_.transient);
    if (beyond_hertz_ > 0)  // the drop test's refusal (model/drop_test_setup.hpp, HertzScale) as a warning
      out_.warnings.push_back(fmt::format(
          "{} soft impact{} came at up to {:.4g} m/s, beyond {:.4g} m/s, where the undamped Hertz deformation "
          "reaches the ball radius: at or above the ball radius the small-deformation Hertz contact does not hold "
          "(`simulate` refuses such an impact)",
          beyond_hertz_, beyond_hertz_ == 1 ? "" : "s", fastest_, speed_limit_));
    out_.end_time_s = t_now_;
    out_.end_position_m = body_position(t_now_);
    out_.end_velocity_mps = body_velocity(t_now_);
    out_.end_box_position_m = box_.position_m(t_now_);
    out_.end_box_velocity_mps = box_.velocity_mps(t_now_);
    out_.end_carried = carried_;
    if (s_.energy) out_.energy.final_J = energy_now();
    // The soft contacts' own work (the drive, the dashpots and the law's dissipation while in
    // contact) is not integrated: no balance to report.
    if (s_.soft) out_.energy = {nan, nan, nan, nan, nan};
    std::vector<double> t_s, v_mps;
    double e_sum = 0;
    long e_count = 0;
    for (const SequenceImpact& i : out_.impacts) {
      t_s.push_back(i.time_s);
      v_mps.push_back(i.impact_speed_mps);
      if (i.impact_speed_mps > 0) {
        e_sum += i.rebound_speed_mps / i.impact_speed_mps;
        ++e_count;
      }
    }
    PatternTolerance tol = s_.pattern;
    if (!(tol.speed_scale_mps > 0)) tol.speed_scale_mps = s_.speed_scale_mps;
    out_.pattern = detect_impact_pattern(t_s, v_mps, s_.frequency_Hz, tol);
    out_.e_effective = e_count ? e_sum / static_cast<double>(e_count) : nan;
    const bool sampled = s_.sampled != ImpactSequenceSpec::Sampled::none && x_max_ >= x_min_;
    out_.amplitude_m = sampled ? 0.5 * (x_max_ - x_min_) : nan;
    out_.peak_phase = sampled ? phase(t_max_) : nan;
    return std::move(out_);
  }

 private:
  const SequenceWall& wall(Wall w) const { return s_.walls[static_cast<std::size_t>(w)]; }
  double phase(double t) const {
    const double c = t * s_.frequency_Hz, p = c - std::floor(c);
    return p < 1.0 ? p : 0.0;
  }
  /// The body's displacement and velocity now: in flight, or on the box.
  double body_position(double t) const { return carried_ ? box_.position_m(t) + wall(wall_).offset_m : body_.position_m(t); }
  double body_velocity(double t) const { return carried_ ? box_.velocity_mps(t) : body_.velocity_mps(t); }
  double energy_now() const {
    const double t = t_now_;
    return (dynamic_ ? s_.box.energy_J(box_.position_m(t), box_.velocity_mps(t)) : 0.0) +
           s_.body.energy_J(body_position(t), body_velocity(t));
  }
  void sample(double x, double t) {
    x_min_ = std::min(x_min_, x);
    if (x > x_max_) x_max_ = x, t_max_ = t;
  }
  void sample_now(double t) {
    if (keeping_ && s_.sampled != ImpactSequenceSpec::Sampled::none)
      sample(s_.sampled == ImpactSequenceSpec::Sampled::box ? box_.position_m(t) : body_position(t), t);
  }

  /// The energy integrals and the samples of [ta, tb] in the present state.
  void segment(double ta, double tb) {
    if (!(tb > ta)) return;
    if (s_.energy) {
      const int pieces = static_cast<int>(std::ceil((tb - ta) / piece_s_));
      const double h = (tb - ta) / pieces, c_box = s_.box.damping_N_s_per_m(), c_body = s_.body.damping_N_s_per_m();
      for (int p = 0; p < pieces; ++p) {
        const double mid = ta + (p + 0.5) * h;
        for (std::size_t i = 0; i < gauss_x.size(); ++i) {
          for (const double sign : {-1.0, 1.0}) {
            const double t = mid + sign * gauss_x[i] * 0.5 * h, weight = gauss_w[i] * 0.5 * h, u = body_velocity(t);
            EnergyAccount& a = out_.energy;
            if (dynamic_) {
              const double V = box_.velocity_mps(t);
              a.drive_work_J += weight * s_.box.force_derivative(0, t) * V;
              a.damping_dissipation_J += weight * c_box * V * V;
            }
            a.drive_work_J += weight * s_.body.force_derivative(0, t) * u;
            a.damping_dissipation_J += weight * c_body * u * u;
          }
        }
      }
    }
    if (!keeping_ || s_.sampled == ImpactSequenceSpec::Sampled::none) return;
    // The coordinate at the grid's points and at its extremes: each root of its velocity between
    // two points, refined by Newton's method kept inside the bracket by bisection.
    const bool on_box = s_.sampled == ImpactSequenceSpec::Sampled::box || carried_;
    const OscillatorMotion& x = on_box ? box_ : body_;
    const double offset = on_box && s_.sampled == ImpactSequenceSpec::Sampled::body ? wall(wall_).offset_m : 0.0;
    const double n = samples_per_cycle * s_.frequency_Hz;
    double t0 = ta, v0 = x.velocity_mps(ta);
    sample(x.position_m(ta) + offset, ta);
    for (double k = std::floor(ta * n) + 1;; ++k) {
      const double t1 = std::min(k / n, tb), v1 = x.velocity_mps(t1);
      sample(x.position_m(t1) + offset, t1);
      if ((v0 < 0) != (v1 < 0)) {
        double lo = t0, hi = t1, t = 0.5 * (t0 + t1);
        for (int i = 0; i < 60 && hi - lo > 1e-15 * (1.0 + std::abs(t)); ++i) {
          const double v = x.velocity_mps(t);
          ((v < 0) == (v0 < 0) ? lo : hi) = t;
          const double newton = t - v / x.acceleration_mps2(t);
          t = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
        }
        sample(x.position_m(t) + offset, t);
      }
      if (t1 >= tb) break;
      t0 = t1, v0 = v1;
    }
  }

  /// The body joins wall w at t_now with velocity u, the box moving at V: the common velocity
  /// conserves momentum, the rest is a loss.
  void carry(Wall w, double u, double V) {
    carried_ = true;
    wall_ = w;
    const double m = s_.body.mass_kg, M = s_.box.mass_kg, Vc = dynamic_ ? (m * u + M * V) / (m + M) : V;
    if (s_.energy)
      out_.energy.impact_loss_J += dynamic_ ? 0.5 * m * u * u + 0.5 * M * V * V - 0.5 * (m + M) * Vc * Vc
                                            : 0.5 * m * (u - V) * (u - V);
    if (!dynamic_) return;
    box_ = OscillatorMotion(carrying(s_.box, s_.body, wall(w).offset_m), t_now_, box_.position_m(t_now_), Vc);
  }

  /// The carried body leaves its wall where the force N the wall exerts on it changes sign (see
  /// the header); false: it never does, the run ends.
  bool release() {
    ++out_.sticking_episodes;
    const SequenceWall& w = wall(wall_);
    const ForcedOscillator& b = s_.body;
    const double m = b.mass_kg, c = b.damping_N_s_per_m(), k = b.stiffness_N_per_m, sigma = w.sigma;
    auto N = [&](int n, double t) {
      return m * box_.derivative(n + 2, t) + c * box_.derivative(n + 1, t) + k * box_.derivative(n, t) +
             (n == 0 ? k * w.offset_m - b.constant_force_N : 0.0) - b.force_derivative(n, t);
    };
    auto force = [&](double t) { return sigma * N(0, t); };
    auto force_rate = [&](double t) { return sigma * N(1, t); };
    const double bound = m * box_.derivative_bound(4) + c * box_.derivative_bound(3) + k * box_.derivative_bound(2) +
                         b.force_amplitude_N * std::pow(b.omega_rad_per_s, 2);
    double t_release = t_now_;
    if (force(t_now_) >= 0) {
      // A force that only touches zero (the shaker at Gamma = 1 exactly) does not release the body:
      // the search goes on past the touch.
      SafeRoot r;
      for (double from = t_now_;;) {
        r = first_safe_root(force, force_rate, bound, from, t_now_ + span_s_, time_tol_);
        if (!r.found || !r.grazing) break;
        from = r.time_s + 1e-9 / s_.frequency_Hz;
        if (force(from) < 0) break;
      }
      if (!r.found) {
        out_.warnings.push_back(fmt::format("the body rests on the {} for good from t = {:.9g} s: the force pressing "
                                            "it there does not change sign",
                                            w.name, t_now_));
        out_.end_reason = fmt::format("the body rests on the {} (see warnings)", w.name);
        return false;
      }
      t_release = r.time_s;
    }
    if (s_.end_time_s && t_release > *s_.end_time_s) return reach_end_time();
    segment(t_now_, t_release);
    const double X = box_.position_m(t_release), V = box_.velocity_mps(t_release);
    if (dynamic_) box_ = OscillatorMotion(s_.box, t_release, X, V);
    t_now_ = t_release;
    carried_ = false;
    body_ = OscillatorMotion(s_.body, t_release, X + w.offset_m, V);
    // h'' = sigma (y'' - X'') >= 0 keeps the gap just left open until it changes sign.
    auto pull = [&](double t) { return sigma * (body_.derivative(2, t) - box_.derivative(2, t)); };
    auto pull_rate = [&](double t) { return sigma * (body_.derivative(3, t) - box_.derivative(3, t)); };
    const double limit = t_release + span_s_;
    const SafeRoot window = first_safe_root(pull, pull_rate, body_.derivative_bound(4) + box_.derivative_bound(4),
                                            t_release, limit, time_tol_);
    search_from_ = {t_release, t_release};
    search_from_[static_cast<std::size_t>(wall_)] = window.found ? window.time_s : limit;
    return true;
  }

  /// The next impact (the earliest first root of the gaps) and what it does; false: the run ends.
  bool next_impact() {
    const double M = body_.derivative_bound(2) + box_.derivative_bound(2);
    std::array<SafeRoot, 2> root;
    int hit = -1;
    double limit = t_now_;
    const double end = std::min(t_now_ + max_flight_cycles / s_.frequency_Hz, s_.end_time_s.value_or(INFINITY));
    for (bool capped = false; hit < 0 && !capped && limit < end;) {
      limit += span_s_;
      double until = limit;
      for (std::size_t j = 0; j < s_.walls.size(); ++j) {
        const SequenceWall& w = s_.walls[j];
        auto h = [&](double t) { return w.sigma * (body_.position_m(t) - box_.position_m(t) - w.offset_m); };
        auto dh = [&](double t) { return w.sigma * (body_.velocity_mps(t) - box_.velocity_mps(t)); };
        root[j] = first_safe_root(h, dh, M, search_from_[j], until, time_tol_);
        if (root[j].found) until = root[j].time_s, hit = static_cast<int>(j);
        else capped = capped || root[j].root_free_to_s < until;  // the iteration cap
      }
      for (std::size_t j = 0; j < s_.walls.size(); ++j) search_from_[j] = root[j].root_free_to_s;
    }
    // The end time comes first: the impact found is after it, or every gap is certified free up to it.
    if (s_.end_time_s &&
        (hit >= 0 ? root[static_cast<std::size_t>(hit)].time_s > *s_.end_time_s
                  : *std::min_element(search_from_.begin(), search_from_.begin() + static_cast<long>(s_.walls.size())) >=
                        *s_.end_time_s))
      return reach_end_time();
    if (hit < 0) {
      std::string names = s_.walls[0].name;
      if (s_.walls.size() > 1) names += fmt::format(" or the {}", s_.walls[1].name);
      out_.warnings.push_back(fmt::format("no impact found between t = {:.9g} s and {:.9g} s: the body never reaches "
                                          "the {} there; the run ends",
                                          t_now_, limit, names));
      out_.end_reason = "a flight without impact (see warnings)";
      segment(t_now_, limit);
      t_now_ = limit;
      return false;
    }
    return impact(static_cast<Wall>(hit), root[static_cast<std::size_t>(hit)].time_s);
  }

  /// The run reaches end_time_s before the next impact or release: the state there ends it.
  bool reach_end_time() {
    segment(t_now_, *s_.end_time_s);
    t_now_ = *s_.end_time_s;
    out_.end_reason = fmt::format("the end time {:.9g} s reached", t_now_);
    return false;
  }

  /// The impact on wall `hit` at ti, instantaneous or soft; false: the run ends.
  bool impact(Wall hit, double ti) {
    const SequenceWall& w = wall(hit);
    const double sigma = w.sigma, m = s_.body.mass_kg, M = s_.box.mass_kg, e = s_.restitution;
    segment(t_now_, ti);
    const double X = box_.position_m(ti), V = box_.velocity_mps(ti), u = body_.velocity_mps(ti);
    const double y = body_.position_m(ti);
    SequenceImpact impact{.time_s = ti, .phase = phase(ti), .wall = hit,
                          .impact_speed_mps = std::max(sigma * (V - u), 0.0), .box_displacement_m = X};
    double t_after = ti, u_after = u, V_after = V;
    if (!s_.soft) {
      impact.rebound_speed_mps = e * impact.impact_speed_mps;
      if (dynamic_) {
        u_after = u + M * (1 + e) * (V - u) / (m + M);
        V_after = V - m * (1 + e) * (V - u) / (m + M);
        if (s_.energy) out_.energy.impact_loss_J += 0.5 * (1 - e * e) * m * M / (m + M) * (V - u) * (V - u);
        box_ = OscillatorMotion(s_.box, ti, X, V_after);
      } else {
        u_after = V + e * (V - u);
        if (s_.energy) out_.energy.impact_loss_J += 0.5 * (1 - e * e) * m * (V - u) * (V - u);
      }
    } else if (impact.impact_speed_mps < stick_speed_) {
      impact.rebound_speed_mps = impact.impact_speed_mps;  // a touch too slow for a contact: carried below
      if (!(impact.impact_speed_mps < s_.hertz_speed_limit_mps))  // a touch of a scale far beyond the contact's
        ++beyond_hertz_, fastest_ = std::max(fastest_, impact.impact_speed_mps), speed_limit_ = s_.hertz_speed_limit_mps;
    } else {
      const SoftImpact c = s_.soft(hit, ti, impact.impact_speed_mps, X, V, soft_contact_window_s(s_.frequency_Hz));
      out_.work.add_work(c.work);
      if (!(impact.impact_speed_mps < c.hertz_speed_limit_mps))
        ++beyond_hertz_, fastest_ = std::max(fastest_, impact.impact_speed_mps), speed_limit_ = c.hertz_speed_limit_mps;
      impact.contact_time_s = c.contact_time_s;
      impact.peak_force_N = c.peak_force_N;
      if (!c.separated) {
        out_.warnings.push_back(fmt::format("the contact beginning at t = {:.9g} s did not end within 2 drive "
                                            "cycles: the run ends there",
                                            ti));
        out_.end_reason = "a contact that did not end (see warnings)";
        return false;
      }
      impact.rebound_speed_mps = c.rebound_speed_mps;
      t_after = ti + c.contact_time_s;
      if (dynamic_) box_ = OscillatorMotion(s_.box, t_after, c.X_m, c.V_mps);
      V_after = box_.velocity_mps(t_after);
      u_after = V_after + sigma * impact.rebound_speed_mps;
    }
    const long cycle = static_cast<long>(std::floor(ti * s_.frequency_Hz));
    in_cycle_ = cycle == cycle_ ? in_cycle_ + 1 : 1;
    cycle_ = cycle;
    bool stick = impact.rebound_speed_mps < stick_speed_;
    if (in_cycle_ > max_impacts_per_cycle && !stick) {
      stick = true;
      if (!chatter_warned_)
        out_.warnings.push_back(fmt::format("chatter: more than {} impacts in the drive cycle beginning at t = {:.9g} "
                                            "s; the body is taken as carried by the {} until it is released",
                                            max_impacts_per_cycle, static_cast<double>(cycle) / s_.frequency_Hz,
                                            w.name));
      chatter_warned_ = true;
    }
    if (out_.impacts_run == s_.transient) keeping_ = true;
    if (keeping_) {
      out_.impacts.push_back(impact);
      sample(s_.sampled == ImpactSequenceSpec::Sampled::box ? X : y, ti);
    }
    ++out_.impacts_run;
    t_now_ = t_after;
    if (stick) {
      carry(hit, u_after, V_after);
    } else {
      body_ = OscillatorMotion(s_.body, t_after, box_.position_m(t_after) + w.offset_m, u_after);
      search_from_ = {t_after, t_after};
    }
    sample_now(t_after);
    return true;
  }

  const ImpactSequenceSpec& s_;
  const bool dynamic_;
  double span_s_ = 0, piece_s_ = 0, stick_speed_ = 0, time_tol_ = 0;
  ImpactSequence out_;
  OscillatorMotion box_, body_;
  bool carried_ = false, keeping_ = false, chatter_warned_ = false;
  Wall wall_ = Wall::floor;
  double t_now_ = 0;
  std::array<double, 2> search_from_{0.0, 0.0};
  long cycle_ = -1, in_cycle_ = 0;
  long beyond_hertz_ = 0;  // soft impacts beyond the Hertz scale, the fastest, the scale's limit
  double fastest_ = 0, speed_limit_ = 0;
  double x_min_ = INFINITY, x_max_ = -INFINITY, t_max_ = 0;
};

}  // namespace

ImpactSequence run_impact_sequence(const ImpactSequenceSpec& spec) { return SequenceRun(spec).run(); }

}  // namespace hertzdash
