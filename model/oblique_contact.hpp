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
// process, exact in continuous time:
//   - inside the cone (sticking): dT/dt = -k_t s, plus a model's share c of the cone's growth,
//     c sigma mu dF_n/dt (normal_coupling, while dF_n/dt > 0), and for a model that rescales,
//     T (da/dt)/a while the overlap falls (rescales_with_contact_radius, a = sqrt(R x));
//   - on the cone (|T| = mu F_n, to 1e-7 of it and of T's scale; sign sigma = sign T, or -sign s
//     where T = 0): the sphere slides,
//     dT/dt = sigma mu dF_n/dt, while the sticking rate pushes outwards faster than the cone grows,
//     sigma (sticking rate) >= mu dF_n/dt; else it sticks again (the first case).
// At onset T = 0 and, but for a law whose dashpot acts at zero overlap (kelvin-voigt), F_n = 0: the
// contact starts on the cone, sliding wherever k_t |s| exceeds
// mu dF_n/dt there (for Mindlin's k_t and Hertz's F_n: |s|/v0 >= mu E*/(4 G*), Maw, Barber and
// Fawcett 1976). dF_n/dt comes from the law's partials (a force jet): the rates are written in
// tau, where dF_n/dtau = F_u v + F_v dv/dtau is finite at onset even for a dashpot in x^{1/2} x'.
//
// State along tau: (u, v, t, T, w, omega, W, t_slide, T*, sigma*, reversed, mu F_n*): W = int T s dt [J],
// the tangential force's work on the sphere (its tangential and spin energy change, an account of
// the integration), t_slide the time on the cone [s], and for a model that remembers reversals
// (Mindlin-Deresiewicz) T* the force where the slip last reversed and the cone there, sigma* the
// slip's sign since then and whether it has reversed (constant between events: the caller sets them at a reversal and
// integrates on, reversal_state()). Events (decreasing through 0): separation u (stops), the normal
// force's maximum dF_n/dtau (observes), the observation time t_obs - t (stops), a reversal of the
// slip sigma* s (stops; a model without memory: off).
// The right-hand side switches between sticking and sliding: integrate it with an error-controlled
// one-step method (dopri5), which steps down across the switch, not an extrapolation method.
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

/// The tangential side of an oblique impact.
struct TangentialContact {
  const TangentialModelInfo* model = nullptr;
  TangentialPair pair;
  double friction = 0;         ///< Coulomb's mu >= 0
  double inertia_factor = 0.4; ///< kappa = I / (m R^2)
  double radius_m = 0;         ///< the sphere's R (its lever arm) [m]
};

/// The onset of an oblique impact: normal speed v0 > 0, tangential w0 and spin omega0.
struct ObliqueOnset {
  double normal_speed_mps = 0, tangential_speed_mps = 0, spin_rad_per_s = 0;
};

enum class ObliqueContactEvent : int { separation, peak_normal_force, observation_time, slip_reversal };

class ObliqueContactSystem {
 public:
  static constexpr int dimension = 12;
  static constexpr int event_count = 4;
  static constexpr bool smooth_at_events = false;  ///< the stick/slip switch is not an event
  using State = Eigen::Matrix<double, dimension, 1>;
  using Events = std::array<double, event_count>;
  enum Index : int { u, v, t, T, w, omega, W, t_slide, T_turn, slip_sign, reversed, cone_turn };

  /// The contact of a sphere of mass m [kg] on stiffness K [N/m^{3/2}] (the undamped Hertz scales
  /// of v0 set the state's), followed for at most t_obs [s].
  ObliqueContactSystem(const NormalForceJet& normal, const TangentialContact& tangential, double K, double mass_kg,
                       const ObliqueOnset& onset, double t_obs_s)
      : normal_(&normal), c_(tangential), inverse_m_(1 / mass_kg),
        inverse_I_(1 / (tangential.inertia_factor * mass_kg * tangential.radius_m * tangential.radius_m)),
        onset_(onset), t_obs_s_(t_obs_s) {
    const double v0 = onset.normal_speed_mps, X = undamped_hertz_max_deformation_m(K, mass_kg, v0);
    const double t_H = undamped_hertz_contact_time_factor() * X / v0;
    const double speed = std::max({v0, std::abs(onset.tangential_speed_mps),
                                   std::abs(onset.spin_rad_per_s * tangential.radius_m)});
    // T ~ mu F_n where the cone binds, ~ F_n's own scale where the spring does (mu > 1).
    const double T_scale = std::clamp(tangential.friction, 1e-3, 1.0) * K * X * std::sqrt(X);
    scale_ << std::sqrt(X), v0, t_H, T_scale, speed, speed / tangential.radius_m, 0.5 * mass_kg * speed * speed, t_H,
        T_scale, 1, 1, T_scale;
  }

  State initial_state() const {
    State y = State::Zero();
    y[v] = onset_.normal_speed_mps;
    y[w] = onset_.tangential_speed_mps;
    y[omega] = onset_.spin_rad_per_s;
    y[slip_sign] = slip_mps(y) < 0 ? -1 : 1;
    return y;
  }

  /// The state after a reversal of the slip at y: T* = T and the cone there, the slip's sign
  /// flipped, reversed.
  State reversal_state(const State& y) const {
    State z = y;
    z[T_turn] = y[T];
    z[cone_turn] = cone_N(normal_->at(std::max(y[u], 0.0), y[v]).value);
    z[slip_sign] = -y[slip_sign];
    z[reversed] = 1;
    return z;
  }
  State state_scale() const { return scale_; }

  /// The contact point's slip velocity s = w + R omega [m/s].
  double slip_mps(const State& y) const { return y[w] + c_.radius_m * y[omega]; }

  void rhs(double, const State& y, State& dy) const {
    const double uu = std::max(y[u], 0.0), two_u = 2 * uu;
    const ForceJet F = normal_->at(uu, y[v]);
    const double dv = -two_u * F.value * inverse_m_;             // dv/dtau
    const double dF = F.d[0] * y[v] + F.d[1] * dv;               // dF_n/dtau
    const double cone = cone_N(F.value), s = slip_mps(y);
    const double Tc = std::clamp(y[T], -cone, cone);
    const TangentialState state{.overlap_m = uu * uu, .force_N = Tc, .cone_N = cone, .turn_force_N = y[T_turn],
                                .turn_cone_N = y[cone_turn], .reversed = y[reversed] != 0};
    // dT/dtau inside the cone: the spring, and a model's share of the cone's change (normal_coupling).
    const double friction_sign = s > 0 ? -1.0 : (s < 0 ? 1.0 : 0.0);
    const double coupled =
        c_.model->normal_coupling && dF > 0 ? c_.model->normal_coupling(state) * friction_sign * c_.friction * dF : 0.0;
    // da/a = dx/(2x) = (v/u) dtau while the overlap falls.
    const double rescaled = c_.model->rescales_with_contact_radius && y[v] < 0 && uu > 0 ? Tc * y[v] / uu : 0.0;
    const double stick = -two_u * c_.model->stiffness_N_per_m(c_.pair, state) * s + coupled + rescaled;
    double dT = stick, sliding = 0;
    if (std::abs(y[T]) >= cone - cone_band * (cone + scale_[T])) {
      const double sigma = y[T] != 0 ? std::copysign(1.0, y[T]) : (s != 0 ? -std::copysign(1.0, s) : 0.0);
      const double cone_rate = c_.friction * (F.value > 0 ? dF : 0.0);
      if (sigma != 0 && sigma * stick >= cone_rate) dT = sigma * cone_rate, sliding = 1;
    }
    dy[u] = y[v];
    dy[v] = dv;
    dy[t] = two_u;
    dy[T] = dT;
    dy[w] = two_u * Tc * inverse_m_;
    dy[omega] = two_u * c_.radius_m * Tc * inverse_I_;
    dy[W] = two_u * Tc * s;
    dy[t_slide] = two_u * sliding;
    dy[T_turn] = dy[slip_sign] = dy[reversed] = dy[cone_turn] = 0;
  }

  void events(double, const State& y, Events& g) const {
    const double uu = std::max(y[u], 0.0);
    const ForceJet F = normal_->at(uu, y[v]);
    g = {y[u], F.d[0] * y[v] + F.d[1] * (-2 * uu * F.value * inverse_m_), t_obs_s_ - y[t],
         c_.model->remembers_reversals ? y[slip_sign] * slip_mps(y) : 1.0};
  }

  EventAction handle_event(int which, double, const State&) const {
    return which == static_cast<int>(ObliqueContactEvent::peak_normal_force) ? EventAction::continue_integration
                                                                              : EventAction::stop;
  }

 private:
  double cone_N(double normal_force_N) const { return c_.friction * std::max(normal_force_N, 0.0); }
  /// A force within this fraction of the cone, or of T's scale (mu K X^{3/2}, mu at most 1), counts as on it: a
  /// step's stages drift off a sliding force by the integration's error (near onset and separation
  /// more than the small cone itself), and inside the cone the spring's rate (k_t s, far steeper
  /// than the cone's) would bounce them back, the step control halving its way through each bounce.
  static constexpr double cone_band = 1e-7;

  const NormalForceJet* normal_;
  TangentialContact c_;
  double inverse_m_, inverse_I_;
  ObliqueOnset onset_;
  double t_obs_s_;
  State scale_;
};

}  // namespace hertzdash
