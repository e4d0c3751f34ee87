#pragma once
// An oblique impact of a sphere on a flat: the normal contact of model/contact_system.hpp (any
// damping law, in its regularising variables u = x^{1/2}, dt/dtau = 2u) and a tangential degree
// of freedom with friction and spin (a tangential model of model/tangential/registry.hpp).
//
// The sphere: mass m [kg], radius R [m], moment of inertia I = kappa m R^2 (kappa = 2/5 solid,
// 2/3 a thin shell), centre velocity (w along the surface, v normal, approaching positive), spin
// omega [rad/s] counted so that the contact point slides at s = w + R omega. The tangential
// force T [N] on the sphere along the surface at its contact point gives
//   m w' = T,   I omega' = R T,   so   s' = T / m_t,   m_t = m kappa / (1 + kappa),
// and the normal motion is the head-on contact's, m x'' = -F_n(x, x') (no gravity: the impact is
// over long before gravity matters; the normal law is calibrated at the normal speed v0).
//
// The tangential force is the spring's force T, an incremental spring with stiffness k_t(x) of
// the model, under the Coulomb cone |T| <= mu F_n (F_n clamped at 0 in tension): a sweeping
// process, exact in continuous time, its two modes told apart by a state (stick, or slide with
// the force's sign sigma) that events switch:
//   - inside the cone (sticking): dT/dt = -k_t s, plus a model's share c of the cone's growth,
//     c sigma mu dF_n/dt (normal_coupling, while dF_n/dt > 0), and for a model that rescales,
//     T (da/dt)/a while the overlap falls (rescales_with_contact_radius, a = sqrt(R x));
//   - on the cone (T = sigma mu F_n): the sphere slides, dT/dt = sigma mu dF_n/dt, while the
//     sticking rate pushes outwards faster than the cone grows, sigma (sticking rate) >= mu dF_n/dt.
// The switches are events: sticking ends where |T| reaches the cone (mu F_n - |T| through 0),
// sliding where the sticking rate stops pushing outwards (sigma (sticking rate) - mu dF_n/dt
// through 0); the run stops there, sets the mode (settled_mode(), which also projects T onto the
// cone) and goes on. Each mode's right-hand side is smooth away from onset and separation (a
// tangential dashpot with Mindlin's stiffness grows as x^{1/4}, its rate singular there), so the
// steps need not shrink across a switch.
// At onset T = 0 and, but for a law whose dashpot acts at zero overlap (kelvin-voigt), F_n = 0: the
// contact starts on the cone, sliding wherever k_t |s| exceeds
// mu dF_n/dt there (for Mindlin's k_t and Hertz's F_n: |s|/v0 >= mu E*/(4 G*), Maw, Barber and
// Fawcett 1976). dF_n/dt comes from the law's partials (a force jet): the rates are written in
// tau, where dF_n/dtau = F_u v + F_v dv/dtau is finite at onset even for a dashpot in x^{1/2} x'.
//
// State along tau: (u, v, t, T, w, omega, W, t_slide, T*, sigma*, reversed, mu F_n*, mode): W = int T s dt [J],
// the tangential force's work on the sphere (its tangential and spin energy change, an account of
// the integration), t_slide the time on the cone [s], and for a model that remembers reversals
// (Mindlin-Deresiewicz) T* the force where the slip last reversed and the cone there, sigma* the
// slip's sign since then and whether it has reversed (constant between events: the caller sets them at a reversal and
// integrates on, reversal_state()), mode 0 sticking or sigma sliding (constant between events).
// Events (decreasing through 0): separation u (stops), the normal force's maximum dF_n/dtau
// (observes), the observation time t_obs - t (stops), a reversal of the slip sigma* s (stops; a
// model without memory: off), sticking's end (stops) and sliding's end (stops).
#include "hertzdash/model/force_jet.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/tangential/tangential_model.hpp"
#include "hertzdash/ode/ode_system.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>

namespace hertzdash {

/// The normal law's force and its partials (u = x^{1/2}, xdot) [N, N/m^{1/2}, N s/m], its type erased.
class NormalForceJet {
 public:
  virtual ~NormalForceJet() = default;
  virtual ForceJet at(double u, double xdot) const = 0;
};

/// The normal contact's part of an oblique impact's rates in tau at u = x^{1/2} (clamped at 0) and
/// v = x': the law's force F_n [N], dv/dtau = -2u F_n / m, dF_n/dtau = F_u v + F_v dv/dtau (finite at
/// onset even for a dashpot in x^{1/2} x'), the Coulomb cone mu F_n (0 in tension) and its rate
/// (0 in tension). Shared by the contact under one cone and the contact resolved over its area
/// (model/oblique_contact_mdr.hpp).
struct NormalContactRates {
  double F, dv, dF, cone, cone_rate;
};
inline NormalContactRates normal_contact_rates(const NormalForceJet& normal, double u, double v, double friction,
                                               double inverse_mass) {
  const double uu = std::max(u, 0.0);
  const ForceJet F = normal.at(uu, v);
  NormalContactRates n{};
  n.F = F.value;
  n.dv = -2 * uu * F.value * inverse_mass;
  n.dF = F.d[0] * v + F.d[1] * n.dv;
  n.cone = friction * std::max(F.value, 0.0);
  n.cone_rate = F.value > 0 ? friction * n.dF : 0.0;
  return n;
}

/// The tangential side of an oblique impact.
struct TangentialContact {
  const TangentialModelInfo* model = nullptr;
  TangentialPair pair;
  double friction = 0;         ///< Coulomb's mu >= 0
  double inertia_factor = 0.4; ///< kappa = I / (m R^2)
  double radius_m = 0;         ///< the sphere's R (its lever arm) [m]
  /// zeta_t >= 0: a dashpot beside the spring, D = -eta s with eta = 2 zeta_t sqrt(k_t m_t), so that
  /// a sticking contact's slip is a linear oscillator of damping ratio zeta_t (0: none).
  double damping_ratio = 0;
};

/// The onset of an oblique impact: normal speed v0 > 0, tangential w0 and spin omega0.
struct ObliqueOnset {
  double normal_speed_mps = 0, tangential_speed_mps = 0, spin_rad_per_s = 0;
};

enum class ObliqueContactEvent : int { separation, peak_normal_force, observation_time, slip_reversal, stick_end, slide_end };

class ObliqueContactSystem {
 public:
  static constexpr int dimension = 13;
  static constexpr int event_count = 6;
  static constexpr bool smooth_at_events = false;
  using State = Eigen::Matrix<double, dimension, 1>;
  using Events = std::array<double, event_count>;
  enum Index : int { u, v, t, T, w, omega, W, t_slide, T_turn, slip_sign, reversed, cone_turn, mode };

  /// The contact of a sphere of mass m [kg] on stiffness K [N/m^{3/2}] (the undamped Hertz scales
  /// of v0 set the state's), followed for at most t_obs [s].
  ObliqueContactSystem(const NormalForceJet& normal, const TangentialContact& tangential, double K, double mass_kg,
                       const ObliqueOnset& onset, double t_obs_s)
      : normal_(&normal), c_(tangential), inverse_m_(1 / mass_kg),
        inverse_I_(1 / (tangential.inertia_factor * mass_kg * tangential.radius_m * tangential.radius_m)),
        m_t_(mass_kg * tangential.inertia_factor / (1 + tangential.inertia_factor)),
        onset_(onset), t_obs_s_(t_obs_s) {
    const double v0 = onset.normal_speed_mps, X = undamped_hertz_max_deformation_m(K, mass_kg, v0);
    const double t_H = undamped_hertz_contact_time_factor() * X / v0;
    const double speed = std::max({v0, std::abs(onset.tangential_speed_mps),
                                   std::abs(onset.spin_rad_per_s * tangential.radius_m)});
    // T ~ mu F_n where the cone binds, ~ F_n's own scale where the spring does (mu > 1).
    const double T_scale = std::clamp(tangential.friction, 1e-3, 1.0) * K * X * std::sqrt(X);
    scale_ << std::sqrt(X), v0, t_H, T_scale, speed, speed / tangential.radius_m, 0.5 * mass_kg * speed * speed, t_H,
        T_scale, 1, 1, T_scale, 1;
  }

  State initial_state() const {
    State y = State::Zero();
    y[v] = onset_.normal_speed_mps;
    y[w] = onset_.tangential_speed_mps;
    y[omega] = onset_.spin_rad_per_s;
    y[slip_sign] = slip_mps(y) < 0 ? -1 : 1;
    return settled_mode(y, true);
  }

  /// y in the mode its rates call for: sliding (with the sign of T + D, or of the friction where it
  /// is 0) where the force is on the cone (or `on_cone`: an event put it there) and the sticking
  /// rate pushes outwards at least as fast as the cone grows, else sticking. Either way a force
  /// T + D at or beyond the cone is projected onto it (T = sigma mu F_n - D): a dashpot acts at
  /// onset where the cone is still closed. At onset (`onset`) the rates all vanish with the
  /// overlap: they are compared at u = 1e-6 of the overlap's scale instead, where their ratio is
  /// already the limit's.
  State settled_mode(const State& y, bool onset = false, bool on_cone = false) const {
    const Rates here = rates(y);  // at y itself, not the probe
    State z = y;
    if (onset) z[u] = 1e-6 * scale_[u];
    const Rates r = onset ? rates(z) : here;
    State out = y;
    const double total = y[T] + here.damping_N;
    const double sigma = total != 0 ? std::copysign(1.0, total) : r.friction_sign;
    const bool at_cone = on_cone || std::abs(total) >= here.cone;
    const bool pushing = r.stick != 0 || r.cone_rate != 0;
    out[mode] = at_cone && sigma != 0 && pushing && sigma * r.stick >= r.cone_rate ? sigma : 0.0;
    if (at_cone && sigma != 0) out[T] = sigma * here.cone - here.damping_N;
    return out;
  }

  /// The state after a reversal of the slip at y: T* = T and the cone there, the slip's sign
  /// flipped, reversed.
  State reversal_state(const State& y) const {
    State z = y;
    const Rates r = rates(y);
    z[cone_turn] = r.cone;
    z[T] = z[T_turn] = r.force - r.damping_N;  // the spring's force
    z[slip_sign] = -y[slip_sign];
    z[reversed] = 1;
    return settled_mode(z);
  }

  /// The state where sliding ends: the force T + D on the cone, sticking.
  State stuck_state(const State& y) const {
    State z = y;
    const Rates r = rates(y);
    z[T] = r.force - r.damping_N;
    z[mode] = 0;
    return z;
  }
  State state_scale() const { return scale_; }

  /// The contact point's slip velocity s = w + R omega [m/s].
  double slip_mps(const State& y) const { return y[w] + c_.radius_m * y[omega]; }

  void rhs(double, const State& y, State& dy) const {
    const double uu = std::max(y[u], 0.0), two_u = 2 * uu;
    const Rates r = rates(y);
    const double sliding = y[mode] != 0 ? 1.0 : 0.0, s = slip_mps(y);
    dy[u] = y[v];
    dy[v] = r.dv;
    dy[t] = two_u;
    // Sliding, the spring's force follows the cone less the dashpot's: T + D = sigma mu F_n.
    dy[T] = sliding != 0 ? y[mode] * r.cone_rate - r.damping_rate : r.spring_rate;
    dy[w] = two_u * r.force * inverse_m_;
    dy[omega] = two_u * c_.radius_m * r.force * inverse_I_;
    dy[W] = two_u * r.force * s;
    dy[t_slide] = two_u * sliding;
    dy[T_turn] = dy[slip_sign] = dy[reversed] = dy[cone_turn] = dy[mode] = 0;
  }

  void events(double, const State& y, Events& g) const {
    const Rates r = rates(y);
    // An event is a crossing from > 0, and a switch's function starts near 0 where the last switch
    // (or onset) left it. Sticking ends where |T| comes within 1e-8 of the cone: a spring that
    // softens to nothing there (mindlin-deresiewicz's theta = 0) reaches it only as (1 - |T|/cone)^{1/3}
    // vanishes and would never cross it; near onset, where the cone is small against T's scale, a
    // margin of 1e-10 of that scale keeps the function > 0 at the start so that a crossing inside
    // the first step is seen. Sliding ends where the sticking rate falls 1e-6 of the rates below the
    // cone's: on a softened spring both rates are the cone's, and the rounding of their difference
    // would otherwise switch back and forth; at onset, where both rates vanish, a margin of 1e-10
    // of the rates' scale again lets a crossing inside the first step be seen (a linear spring
    // slides for an instant at onset, where the cone is still closed, then sticks). T + D is
    // projected onto the cone at each switch. After sliding ends, sticking's function starts at
    // -1e-8 of the cone (plus the margin): the rates then point inwards, so it rises through 0
    // before it can fall through it.
    const double rate_scale = std::abs(r.stick) + std::abs(r.cone_rate);
    g = {y[u], r.dF, t_obs_s_ - y[t], c_.model->remembers_reversals ? y[slip_sign] * slip_mps(y) : 1.0,
         y[mode] == 0 ? r.cone * (1 - stick_band) - std::abs(y[T] + r.damping_N) + onset_margin * scale_[T] : 1.0,
         y[mode] != 0 ? y[mode] * r.stick - r.cone_rate + slide_offset * rate_scale + onset_margin * rate_unit() : 1.0};
  }

  EventAction handle_event(int which, double, const State&) const {
    return which == static_cast<int>(ObliqueContactEvent::peak_normal_force) ? EventAction::continue_integration
                                                                              : EventAction::stop;
  }

 private:
  static constexpr double stick_band = 1e-8, onset_margin = 1e-10, slide_offset = 1e-6;

  /// The scale of T's rates in tau, dT/dtau = 2u dT/dt ~ 2 u_scale T_scale / t_H.
  double rate_unit() const { return 2 * scale_[u] * scale_[T] / scale_[t]; }

  /// The rates in tau at y: dv/dtau, dF_n/dtau, the cone mu F_n and its rate (0 in tension); the
  /// dashpot's force D = -eta s and its rate; the tangential force on the sphere (sliding, sigma mu
  /// F_n exactly: T's state follows it, but its integration error would put a kink into the
  /// right-hand side through a clamp; sticking, T + D within the cone); the spring's rate while
  /// sticking (the spring, a model's coupling and rescaling) and the force's, spring and dashpot
  /// (`stick`, what the cone is compared with); the friction's direction -sign s.
  struct Rates {
    double dv, dF, cone, cone_rate, damping_N, damping_rate, force, spring_rate, stick, friction_sign;
  };
  Rates rates(const State& y) const {
    const double uu = std::max(y[u], 0.0), two_u = 2 * uu;
    const NormalContactRates n = normal_contact_rates(*normal_, y[u], y[v], c_.friction, inverse_m_);
    Rates r{};
    r.dv = n.dv;
    r.dF = n.dF;
    r.cone = n.cone;
    r.cone_rate = n.cone_rate;
    const double s = slip_mps(y);
    // The spring's force within the cone (sliding: sigma mu F_n less the dashpot's).
    TangentialState state{.overlap_m = uu * uu, .force_N = std::clamp(y[T], -r.cone, r.cone), .cone_N = r.cone,
                          .turn_force_N = y[T_turn], .turn_cone_N = y[cone_turn], .reversed = y[reversed] != 0};
    const double k = c_.model->stiffness_N_per_m(c_.pair, state);
    double eta = 0, deta = 0;
    if (c_.damping_ratio > 0 && k > 0) {
      eta = 2 * c_.damping_ratio * std::sqrt(k * m_t_);
      // deta/dtau = eta (dk/dtau) / (2k), dk/dtau = (dk/du) v: the overlap's share of k's change.
      if (uu > 0) {
        const double du = 1e-6 * uu;
        TangentialState up = state, down = state;
        up.overlap_m = (uu + du) * (uu + du), down.overlap_m = (uu - du) * (uu - du);
        const double dk_du = (c_.model->stiffness_N_per_m(c_.pair, up) - c_.model->stiffness_N_per_m(c_.pair, down)) / (2 * du);
        deta = eta * dk_du * y[v] / (2 * k);
      }
    }
    r.damping_N = -eta * s;
    r.force = y[mode] != 0 ? y[mode] * r.cone : std::clamp(y[T] + r.damping_N, -r.cone, r.cone);
    state.force_N = y[mode] != 0 ? y[mode] * r.cone - r.damping_N : state.force_N;
    const double Tc = state.force_N;
    // The friction's direction, -sign s; T's rate inside the cone: the spring, and a model's share
    // of the cone's change (normal_coupling).
    r.friction_sign = s > 0 ? -1.0 : (s < 0 ? 1.0 : 0.0);
    const double coupled =
        c_.model->normal_coupling && r.dF > 0 ? c_.model->normal_coupling(state) * r.friction_sign * c_.friction * r.dF : 0.0;
    // da/a = dx/(2x) = (v/u) dtau while the overlap falls.
    const double rescaled = c_.model->rescales_with_contact_radius && y[v] < 0 && uu > 0 ? Tc * y[v] / uu : 0.0;
    r.spring_rate = -two_u * k * s + coupled + rescaled;
    // dD/dtau = -(deta/dtau) s - eta ds/dtau, ds/dtau = 2u F (1/m + R^2/I).
    r.damping_rate = -deta * s - eta * two_u * r.force * (inverse_m_ + c_.radius_m * c_.radius_m * inverse_I_);
    r.stick = r.spring_rate + r.damping_rate;
    return r;
  }

  const NormalForceJet* normal_;
  TangentialContact c_;
  double inverse_m_, inverse_I_, m_t_;  ///< m_t = m kappa/(1 + kappa): s' = T / m_t
  ObliqueOnset onset_;
  double t_obs_s_;
  State scale_;
};

}  // namespace hertzdash
