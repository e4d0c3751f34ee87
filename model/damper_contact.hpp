#pragma once
// The soft contact of a body with a wall of the impact damper's box (simulation/shaker/
// two_walls.hpp): the contact force F(x, x') acts on both, the body (mass m) and the primary
// (mass M on the spring k, damping c, driven by F0 sin(w t)), so the primary's motion is part of
// the system, not a prescribed forcing as in model/shaken_contact.hpp.
//
// Floor (sigma = +1): overlap x = X - y; ceiling (sigma = -1): x = y - X - gap. With the
// primary's free acceleration P = (F0 sin(w t) - c X' - k X)/M, the body pushed away from the wall
// by F and the wall by -F:
//   M X'' = M P - sigma F,   m y'' = -m g + sigma F,
//   x'' = sigma (P + g) - F / mu,   mu = m M / (m + M)
// (the floor's: x'' = X'' - y'' = P + g - F/M - F/m). The law's coefficients follow from the
// impact's conditions with the reduced mass mu, the mass of the relative motion. In u = x^{1/2},
// dt/dtau = 2u (Sundman), the drive's phase as S = sin(w t), C = cos(w t):
//   du/dtau = v,   dv/dtau = 2u (sigma (P + g) - F(u^2, v)/mu),   dt/dtau = 2u,
//   dX/dtau = 2u V,   dV/dtau = 2u (P - sigma F / M),   dS/dtau = 2u w C,   dC/dtau = -2u w S,
// a polynomial in the state for a RootPolynomialLaw (the Taylor row takes it). State (u, v, t
// since onset, X, V, S, C); events as model/shaken_contact.hpp's: 0 separation (u = 0, stop),
// 1 peak force (observation), 2 observation time (stop).
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/force_jet.hpp"
#include "hertzdash/model/force_rate.hpp"
#include "hertzdash/model/forced_oscillator.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/ode/ode_system.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

namespace hertzdash {

/// The damper contact's events, in event order.
enum class DamperContactEvent : int { separation, peak_force, observation_time };

template <DampingLaw Law>
class DamperContact {
 public:
  static constexpr int dimension = 7;
  static constexpr int event_count = 3;
  using State = Eigen::Matrix<double, 7, 1>;
  using Events = std::array<double, event_count>;
  static constexpr bool smooth_at_events = RootPolynomialLaw<Law>;

  /// The contact beginning at t_onset_s [s] at relative speed v0 > 0 of the body of mass m_kg
  /// with the wall `sigma` (+1 floor, -1 ceiling) of the primary `o` (X0 [m], V0 [m/s] at onset),
  /// with Hertz stiffness K and input e, observed at most t_obs_s [s].
  DamperContact(double K, double m_kg, double v0_mps, double restitution, const DampingSettings& s,
                double gravity_mps2, const ForcedOscillator& o, double sigma, double t_onset_s, double X0_m,
                double V0_mps, double t_obs_s)
      : law_(ImpactConditions{K, m_kg * o.mass_kg / (m_kg + o.mass_kg), v0_mps, restitution}, s),
        inverse_mu_(1.0 / m_kg + 1.0 / o.mass_kg), inverse_M_(1.0 / o.mass_kg), gravity_mps2_(gravity_mps2),
        F0_(o.force_amplitude_N), c_(o.damping_N_s_per_m()), k_(o.stiffness_N_per_m), omega_(o.omega_rad_per_s),
        sigma_(sigma), theta0_(o.omega_rad_per_s * t_onset_s), t_obs_s_(t_obs_s), v0_mps_(v0_mps), X0_m_(X0_m),
        V0_mps_(V0_mps) {
    const double X = undamped_hertz_max_deformation_m(K, 1.0 / inverse_mu_, v0_mps);
    state_scale_ << std::sqrt(X), v0_mps, undamped_hertz_contact_time_factor() * X / v0_mps,
        std::max(std::abs(X0_m), X), std::max(std::abs(V0_mps), v0_mps), 1.0, 1.0;
  }

  State initial_state() const {
    State y;
    y << 0.0, v0_mps_, 0.0, X0_m_, V0_mps_, std::sin(theta0_), std::cos(theta0_);
    return y;
  }

  const Law& law() const { return law_; }
  State state_scale() const { return state_scale_; }
  double force(const State& y) const { return force_at(y[0], y[1]); }

  void rhs(double, const State& y, State& dy) const {
    const auto [du, dv, dt, dX, dV, dS, dC] = tau_derivatives(y[0], y[1], y[3], y[4], y[5], y[6], force(y));
    dy << du, dv, dt, dX, dV, dS, dC;
  }

  template <class Y>
    requires RootPolynomialLaw<Law>
  auto polynomial_rhs(const Y& y) const {
    return tau_derivatives(y[0], y[1], y[3], y[4], y[5], y[6], law_.force_of_root(y[0], y[1]));
  }

  template <class Y>
    requires RootPolynomialLaw<Law>
  auto polynomial_events(const Y& y) const {
    return std::tuple{y[0], derivative(law_.force_of_root(y[0], y[1])), t_obs_s_ - y[2]};
  }

  void events(double, const State& y, Events& g) const {
    const double u = std::max(y[0], 0.0), v = y[1];
    double F, F_u, F_v;
    if constexpr (RootPolynomialLaw<Law>) {
      const ForceJet jet = law_.force_of_root(ForceJet::root(u), ForceJet::rate(v));
      F = jet.value, F_u = jet.d_u, F_v = jet.d_v;
    } else {
      const double du = 1e-6 * std::max(u, 1e-6 * state_scale_[0]), dv = 1e-6 * v0_mps_;
      F = force_at(u, v);
      F_u = (force_at(u + du, v) - F) / du;
      F_v = (force_at(u, v + dv) - F) / dv;
    }
    const double P = (F0_ * y[5] - c_ * y[4] - k_ * y[3]) * inverse_M_;
    const double dvdtau = 2.0 * u * (sigma_ * (P + gravity_mps2_) - F * inverse_mu_);
    g = {y[0], force_rate(F_u, F_v, v, dvdtau), t_obs_s_ - y[2]};
  }

  EventAction handle_event(int which, double, const State&) const {
    return which == event_index(DamperContactEvent::peak_force) ? EventAction::continue_integration
                                                                 : EventAction::stop;
  }

 private:
  template <class U, class V, class X, class W, class S, class C, class F>
  auto tau_derivatives(const U& u, const V& v, const X& x, const W& V_primary, const S& sin_theta,
                       const C& cos_theta, const F& force) const {
    const auto two_u = 2.0 * u;
    const auto P = (F0_ * sin_theta - c_ * V_primary - k_ * x) * inverse_M_;
    return std::tuple{v, two_u * (sigma_ * (P + gravity_mps2_) - force * inverse_mu_), two_u, two_u * V_primary,
                      two_u * (P - sigma_ * inverse_M_ * force), two_u * (omega_ * cos_theta),
                      two_u * (-omega_ * sin_theta)};
  }

  double force_at(double u, double v) const {
    if constexpr (RootPolynomialLaw<Law>) return law_.force_of_root(u, v);
    else return law_.force(u * u, v);
  }

  Law law_;
  double inverse_mu_, inverse_M_, gravity_mps2_, F0_, c_, k_, omega_, sigma_, theta0_, t_obs_s_, v0_mps_, X0_m_,
      V0_mps_;
  State state_scale_;
};

}  // namespace hertzdash
