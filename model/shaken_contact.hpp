#pragma once
// The contact of a body with a harmonically moving wall (model/wall_motion.hpp) in the
// regularising variables of model/regularized_contact.hpp, for the shaker.
//
// Relative coordinate: the overlap x = s(t) - y(t) (wall height s, body height y, upward
// positive), compressive force F(x, x') >= 0 pushing the body up: m y'' = -m g + F, so
//   x'' = g + s''(t) - F(x, x')/m,   s''(t) = -A w^2 sin(w t)
// the drop test's equation (model/drop_test.hpp, x'' = g - F/m) with the wall's acceleration as
// a prescribed, time-dependent forcing. In u = x^{1/2}, dt/dtau = 2u (Sundman), the wall's phase
// carried as the pair S = sin(w t), C = cos(w t) (dS/dtau = 2u w C, dC/dtau = -2u w S):
//   du/dtau = v
//   dv/dtau = 2u (g - A w^2 S - F(u^2, v)/m)
//   dt/dtau = 2u,   dS/dtau = 2u w C,   dC/dtau = -2u w S
// so the right-hand side stays a polynomial in the state for every law whose force is a
// polynomial in (u, v) (RootPolynomialLaw): the Taylor row takes it like the others, and the
// system is smooth through onset and separation as the drop test's regularised contact is.
// A separate system type, not a forcing added to RegularizedContact: the drop test keeps its
// three-variable system and pays nothing for the wall.
//
// State (u [m^{1/2}], v [m/s], t [s] since onset, S, C); tau [s/m^{1/2}]. Events (decreasing
// through 0):
//   0 separation: g = u (stop)
//   1 peak_force: g = dF/dtau = F_u u' + F_v v' (observation; exact for a RootPolynomialLaw, by
//     the force's jet, model/force_jet.hpp, else forward differences as RegularizedContact's)
//   2 observation time: g = t_obs - t (stop: the body has not left the wall by then)
// Scales (the integrators' absolute tolerances): u ~ X^{1/2}, v ~ v0, t ~ t_H, S, C ~ 1, with X
// and t_H the undamped Hertz maximum compression and contact time at the impact speed v0.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/force_jet.hpp"
#include "hertzdash/model/force_rate.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/wall_motion.hpp"
#include "hertzdash/ode/ode_system.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <tuple>

namespace hertzdash {

/// The shaken contact's events, in event order.
enum class ShakenContactEvent : int { separation, peak_force, observation_time };

template <DampingLaw Law>
class ShakenContact {
 public:
  static constexpr int dimension = 5;
  static constexpr int event_count = 3;
  using State = Eigen::Matrix<double, 5, 1>;
  using Events = std::array<double, event_count>;
  static constexpr bool smooth_at_events = RootPolynomialLaw<Law>;

  /// The contact of an impact at relative speed c.v0_mps > 0 beginning at time t_onset_s [s] on
  /// the wall `wall`, observed at most t_obs_s [s] after onset.
  ShakenContact(const ImpactConditions& c, const DampingSettings& s, double gravity_mps2,
                const HarmonicWallMotion& wall, double t_onset_s, double t_obs_s)
      : law_(c, s), inverse_mass_(1.0 / c.mass_kg), gravity_mps2_(gravity_mps2),
        wall_accel_mps2_(wall.peak_acceleration_mps2()), omega_(wall.omega_rad_per_s()),
        theta0_(omega_ * t_onset_s), t_obs_s_(t_obs_s), v0_mps_(c.v0_mps) {
    const double X = undamped_hertz_max_deformation_m(c.K, c.mass_kg, c.v0_mps);
    state_scale_ << std::sqrt(X), c.v0_mps, undamped_hertz_contact_time_factor() * X / c.v0_mps, 1.0, 1.0;
  }

  /// Onset: u = 0, v = v0, t = 0, the wall's phase w t_onset.
  State initial_state() const {
    State y;
    y << 0.0, v0_mps_, 0.0, std::sin(theta0_), std::cos(theta0_);
    return y;
  }

  const Law& law() const { return law_; }
  State state_scale() const { return state_scale_; }
  double force(const State& y) const { return force_at(y[0], y[1]); }

  void rhs(double, const State& y, State& dy) const {
    const auto [du, dv, dt, dS, dC] = tau_derivatives(y[0], y[1], y[3], y[4], force(y));
    dy << du, dv, dt, dS, dC;
  }

  /// The right-hand side over any scalar type, for the Taylor integrator.
  template <class Y>
    requires RootPolynomialLaw<Law>
  auto polynomial_rhs(const Y& y) const {
    return tau_derivatives(y[0], y[1], y[3], y[4], law_.force_of_root(y[0], y[1]));
  }

  /// The events over the same scalar types: (u, dF/dtau, t_obs - t).
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
    const double dvdtau = 2.0 * u * (gravity_mps2_ - wall_accel_mps2_ * y[3] - F * inverse_mass_);
    g = {y[0], force_rate(F_u, F_v, v, dvdtau), t_obs_s_ - y[2]};
  }

  EventAction handle_event(int which, double, const State&) const {
    return which == event_index(ShakenContactEvent::peak_force) ? EventAction::continue_integration
                                                                : EventAction::stop;
  }

 private:
  template <class U, class V, class S, class C, class F>
  auto tau_derivatives(const U& u, const V& v, const S& sin_theta, const C& cos_theta, const F& force) const {
    const auto two_u = 2.0 * u;
    return std::tuple{v, two_u * (gravity_mps2_ - wall_accel_mps2_ * sin_theta - force * inverse_mass_), two_u,
                      two_u * (omega_ * cos_theta), two_u * (-omega_ * sin_theta)};
  }

  double force_at(double u, double v) const {
    if constexpr (RootPolynomialLaw<Law>) return law_.force_of_root(u, v);
    else return law_.force(u * u, v);
  }

  Law law_;
  double inverse_mass_, gravity_mps2_, wall_accel_mps2_, omega_, theta0_, t_obs_s_, v0_mps_;
  State state_scale_;
};

}  // namespace hertzdash
