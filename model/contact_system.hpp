#pragma once
// One contact of the body with another body, in regularising variables, written once for every
// damping law and every environment (what the other body does: model/contact_environments.hpp).
//
// Why regularising variables: in the physical variables the right-hand side x'' = a - F(x, x')/m
// has a force that is not smooth at x = 0: K x^{3/2} has an unbounded second derivative, and the
// paper's dashpot x^{1/2} x' an unbounded first derivative. Along the motion x ~ v0 t, so the
// solution carries powers t^{7/2} (spring) and t^{5/2} (dashpot) at onset and the same in
// (t_sep - t) at separation, and a p-th order one-step method loses order there whatever the
// step (see validation/convergence).
//
// The relative motion: the overlap x >= 0 [m], its rate v = x' [m/s] (positive while
// approaching), the compressive force F(x, x') >= 0 [N] of the law, and the environment's
// forcing a(x, v, z) [m/s^2] (the relative acceleration without the contact force), reduced mass
// mu [kg] and extra state z with dz/dt = r(x, v, z, F):
//   x'' = a - F(x, x')/mu
// The change of variables: u = x^{1/2} and a new independent variable tau with dt/dtau = 2u (a
// Sundman time transformation):
//   du/dtau = v
//   dv/dtau = 2u (a - F(u^2, v)/mu)
//   dt/dtau = 2u
//   dz/dtau = 2u r
// For every law whose force is a polynomial in (x^{1/2}, x') -- Hertz, the paper's law, the
// Hunt-Crossley family, Kelvin-Voigt -- F(u^2, v) is a polynomial in (u, v), and so are a and r
// of every environment (a wall's or a drive's phase is carried as sin and cos in z), so this
// system is smooth on the whole contact, onset (u = 0, v = v0) and separation (u = 0 again,
// v < 0) included. Uniform steps in tau are steps in t graded like (t - t_on)^{1/2} near onset
// and separation.
//
// State (u [m^{1/2}], v [m/s], t [s] since onset, z...); tau [s/m^{1/2}]. Events (decreasing
// through 0), in ContactEvent's order:
//   0 separation: g = u (stop)
//   1 max_compression: g = v (observation), if the environment lands it; else g = 1
//   2 peak_force: g = dF/dtau = F_u u' + F_v v' from the state's partials: exact for a law
//     that declares force_of_root (one evaluation on ForceJet, model/force_jet.hpp), else
//     forward differences with relative steps 1e-6 (3 force evaluations per call: the
//     events are evaluated after every step), whose O(1e-6) relative truncation
//     moves the root by O(1e-6) of the tau scale and, F being stationary there, the
//     peak force by O(1e-12) relative. A difference along tau instead is exactly zero
//     over a span at the undamped turning point, where a root finder meets a flat zero.
//   3 observation time: g = t_obs - t, if an observation time is set, else g = 1 (stop if the
//     environment says so, else observation)
// An event that is off (g = 1) never fires, so an environment pays for it one constant.
// Scales (state_scale, the integrators' absolute tolerances, ode/ode_system.hpp): u ~ X^{1/2},
// v ~ v0, t ~ t_H, with X and t_H the undamped Hertz maximum compression and contact time at v0
// and mu (model/hertz.hpp), z as the environment says.
//
// The environment Env (model/contact_environments.hpp) declares:
//   static constexpr int extra_dimension;               the size of z
//   static constexpr bool lands_max_compression;        event 1 on
//   static constexpr bool stops_at_observation_time;    event 3 stops
//   double reduced_mass_kg(double m) const;             mu for the body's mass m [kg]
//   auto rates(const Y& y, const F& force, double inverse_mu) const;
//       std::tuple{a, r...} at the state y (any scalar type: y[0] = u, y[1] = v, y[3 + i] = z_i)
//   std::array<double, extra_dimension> initial_extra() const;       z at onset
//   std::array<double, extra_dimension> extra_scale(double X, double v0) const;
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/force_jet.hpp"
#include "hertzdash/model/force_rate.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/ode/ode_system.hpp"  // the ODE-system vocabulary (EventAction), shared with integrators/

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <tuple>

namespace hertzdash {

/// Where a regularised contact's integration in tau [s/m^{1/2}] ends: beyond its events (separation,
/// or t reaching the observation window t_obs [s]) for a contact whose u stays above 1e-7 of its
/// scale X^{1/2} on average (dt/dtau = 2u). `scale` is the system's state_scale() (u, v, t, ...).
template <class Scale>
double regularised_tau_end(double t_obs_s, const Scale& scale) {
  return 1e7 * (t_obs_s + scale[2]) / (2.0 * scale[0]);
}

/// The regularised equations (see above), (du, dv, dt, dz...)/dtau as a tuple, at the state y
/// with the force F there, of the environment env and 1/mu = inverse_mass [1/kg], over any scalar
/// type (double, power series, jets): the one right-hand side of ContactSystem and of its
/// variational equations (model/contact_tangent_system.hpp).
template <class Env, class Y, class F>
auto regularized_contact_rates(const Env& env, const Y& y, const F& force, double inverse_mass) {
  const auto two_u = 2.0 * y[0];
  return std::apply([&](const auto& a, const auto&... r) {
    return std::tuple{y[1], two_u * (a - force * inverse_mass), two_u, (two_u * r)...};
  }, env.rates(y, force, inverse_mass));
}

/// The contact's events, in event order (event_index gives the integrators' index).
enum class ContactEvent : int { separation, max_compression, peak_force, observation_time };

template <DampingLaw Law, class Env>
class ContactSystem {
 public:
  static constexpr int dimension = 3 + Env::extra_dimension;
  static constexpr int event_count = 4;
  using State = Eigen::Matrix<double, dimension, 1>;
  using Events = std::array<double, event_count>;
  /// Smooth through onset and separation (u = 0) when the law's force is a polynomial in u.
  static constexpr bool smooth_at_events = RootPolynomialLaw<Law>;

  /// The contact of an impact at approach speed c.v0_mps of the body of mass c.mass_kg with the
  /// environment `env`; t_obs_s: optional time after onset [s] at which event 3 fires. The law's
  /// coefficients follow from c with the environment's reduced mass.
  ContactSystem(const ImpactConditions& c, const DampingSettings& s, const Env& env,
                std::optional<double> t_obs_s = std::nullopt)
      : law_(ImpactConditions{c.K, env.reduced_mass_kg(c.mass_kg), c.v0_mps, c.restitution}, s), env_(env),
        inverse_mass_(1.0 / env.reduced_mass_kg(c.mass_kg)), t_obs_s_(t_obs_s), v0_mps_(c.v0_mps) {
    // The impact's scales (one pow per impact): X^{1/2}, v0 and t_H, also the difference steps'.
    const double X = undamped_hertz_max_deformation_m(c.K, env.reduced_mass_kg(c.mass_kg), c.v0_mps);
    state_scale_.template head<3>() << std::sqrt(X), c.v0_mps, undamped_hertz_contact_time_factor() * X / c.v0_mps;
    const auto z = env.extra_scale(X, c.v0_mps);
    for (int i = 0; i < Env::extra_dimension; ++i) state_scale_[3 + i] = z[i];
  }

  /// Onset: u = 0, v = v0, t = 0, the environment's z.
  State initial_state() const {
    State y;
    y.template head<3>() << 0.0, v0_mps_, 0.0;
    const auto z = env_.initial_extra();
    for (int i = 0; i < Env::extra_dimension; ++i) y[3 + i] = z[i];
    return y;
  }

  const Law& law() const { return law_; }
  /// (X^{1/2} [m^{1/2}], v0 [m/s], t_H [s], z's scales) (see "Scales" above).
  State state_scale() const { return state_scale_; }
  double force(const State& y) const { return force_at(y[0], y[1]); }

  void rhs(double, const State& y, State& dy) const {
    std::apply([&](const auto&... d) {
      int i = 0;
      ((dy[i++] = d), ...);
    }, tau_derivatives(y, force(y)));
  }

  /// The same right-hand side over any scalar type (t = y[2] does not enter: autonomous), as
  /// (du, dv, dt, dz...)/dtau, for a law that writes its force as a polynomial in u: the Taylor
  /// integrator evaluates it on power series.
  template <class Y>
    requires RootPolynomialLaw<Law>
  auto polynomial_rhs(const Y& y) const {
    return tau_derivatives(y, law_.force_of_root(y[0], y[1]));
  }

  /// The events over the same scalar types, for the Taylor integrator's location on the
  /// series: (u, v, dF/dtau, t_obs - t), the rate as the series' own derivative, an event that
  /// is off as the constant 1. `derivative(s)` (the derivative of a series along tau,
  /// integrators/power_series.hpp) is the scalar type's own, found by argument-dependent lookup.
  template <class Y>
    requires RootPolynomialLaw<Law>
  auto polynomial_events(const Y& y) const {
    constexpr double v_on = Env::lands_max_compression ? 1.0 : 0.0;
    const double t_obs = t_obs_s_.value_or(1.0), t_sign = t_obs_s_ ? -1.0 : 0.0;  // as events(): 1 if unset
    return std::tuple{y[0], (1.0 - v_on) + v_on * y[1], derivative(law_.force_of_root(y[0], y[1])),
                      t_obs + t_sign * y[2]};
  }

  void events(double, const State& y, Events& g) const {
    const double u = std::max(y[0], 0.0), v = y[1];
    double F, F_u, F_v;
    if constexpr (RootPolynomialLaw<Law>) {
      const ForceJet jet = law_.force_of_root(root_leaf(u), rate_leaf(v));
      F = jet.value, F_u = jet.d[0], F_v = jet.d[1];
    } else {
      const double du = 1e-6 * std::max(u, 1e-6 * state_scale_[0]), dv = 1e-6 * v0_mps_;
      F = force_at(u, v);
      F_u = (force_at(u + du, v) - F) / du;
      F_v = (force_at(u, v + dv) - F) / dv;
    }
    const double dvdtau = 2.0 * u * (std::get<0>(env_.rates(y, F, inverse_mass_)) - F * inverse_mass_);
    g = {y[0], Env::lands_max_compression ? v : 1.0, force_rate(F_u, F_v, v, dvdtau),
         t_obs_s_ ? *t_obs_s_ - y[2] : 1.0};
  }

  EventAction handle_event(int which, double, const State&) const {
    const bool stops = which == event_index(ContactEvent::separation) ||
                       (Env::stops_at_observation_time && which == event_index(ContactEvent::observation_time));
    return stops ? EventAction::stop : EventAction::continue_integration;
  }

 protected:
  /// Event 3 at t_obs_s [s] after onset, for a system built on this one (before integrating).
  void set_observation_time_s(double t_obs_s) { t_obs_s_ = t_obs_s; }

 private:
  template <class Y, class F> auto tau_derivatives(const Y& y, const F& force) const {
    return regularized_contact_rates(env_, y, force, inverse_mass_);
  }

  /// The force at (u, v) [N]: the law's polynomial in u if it declares one
  /// (RootPolynomialLaw; smooth through u = 0), else force(u^2, v).
  double force_at(double u, double v) const {
    if constexpr (RootPolynomialLaw<Law>) return law_.force_of_root(u, v);
    else return law_.force(u * u, v);
  }

  Law law_;
  Env env_;
  double inverse_mass_;  ///< 1/mu [1/kg]: a product in the right-hand side, not a division
  std::optional<double> t_obs_s_;
  double v0_mps_;
  State state_scale_;
};

}  // namespace hertzdash
