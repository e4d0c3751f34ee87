#pragma once
// The soft contact of model/contact_system.hpp with its variational equations along the two
// numbers an impact begins with: the onset time t_on [s] (through the environment's state at
// onset, a drive's phase) and the approach speed v0 [m/s] (through the initial rate and through
// the law's coefficients, fixed at onset from v0). What it gives: the contact time and the
// rebound speed, and their derivatives with respect to (t_on, v0), the 2x2 block of a soft
// impact in the monodromy matrix of an impact orbit (simulation/orbits/stroboscopic_map.hpp).
//
// Equations. With Y = (u, v, t, z) the regularised state and f(Y; v0) its right-hand side along
// tau (regularized_contact_rates, the same function ContactSystem integrates), the sensitivities
// S_p = dY/dp for p = t_on, v0 obey
//   dY/dtau    = f(Y; v0),                      Y(0)    = (0, v0, 0, z0(t_on))
//   dS_p/dtau  = f_Y S_p + df/dp,               S_ton(0) = (0, 0, 0, dz0/dt_on),  S_v0(0) = (0, 1, 0, 0)
// with df/dt_on = 0 and df/dv0 = -(2u/mu) dF/dv0 e_v (the law's SpeedDerivativeLaw hook). f_Y S_p
// is one evaluation of f on Jet<2> leaves (model/force_jet.hpp): Y_i carried with (S_ton,i,
// S_v0,i), the law's force_of_root and the environment's rates on jets, dF/dv0 added to the
// force's v0 direction. No differences anywhere.
//
// Separation (u = 0, the event that stops) needs no correction for its own shift: a perturbed
// contact separates at tau_s + dtau_s with dtau_s = -S_u / v, but dt/dtau = 2u and dv/dtau =
// 2u (a - F/mu) vanish there, so t and v are stationary in tau at separation and
//   d t_c / dp = S_p,t,    d v_sep / dp = -S_p,v.
// (In physical time a separation event's saltation term would be needed; the regularisation
// makes it zero.) A second event, t reaching t_obs, stops a contact that does not end.
//
// The law behind one virtual call (ContactForceJets): the system and its integrator are compiled
// once for an environment, not once per law (simulation/run/soft_contact_tangent.cpp).
//
// The environment Env declares, besides ContactSystem's needs,
//   std::array<double, extra_dimension> initial_extra_onset_derivative() const;   dz0/dt_on [1/s]
#include "hertzdash/model/contact_system.hpp"
#include "hertzdash/model/force_jet.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/ode/ode_system.hpp"

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>

namespace hertzdash {

/// A law's force on jets and dF/dv0 (SpeedDerivativeLaw), its type erased.
class ContactForceJets {
 public:
  virtual ~ContactForceJets() = default;
  /// F(u, xdot) [N] with its derivatives along the jets' directions.
  virtual Jet<2> force(const Jet<2>& u, const Jet<2>& xdot) const = 0;
  /// dF/dv0 [N s/m] at fixed (u, xdot).
  virtual double speed_derivative(double u, double xdot) const = 0;
};

/// The law Law, built for one impact's conditions, as ContactForceJets.
template <SpeedDerivativeLaw Law>
class LawForceJets final : public ContactForceJets {
 public:
  LawForceJets(const ImpactConditions& c, const DampingSettings& s) : law_(c, s) {}
  Jet<2> force(const Jet<2>& u, const Jet<2>& xdot) const override { return law_.force_of_root(u, xdot); }
  double speed_derivative(double u, double xdot) const override { return law_.force_speed_derivative(u, xdot); }

 private:
  Law law_;
};

/// The contact's events in the tangent system, in event order.
enum class TangentContactEvent : int { separation, observation_time };

template <class Env>
class ContactTangentSystem {
 public:
  static constexpr int base_dimension = 3 + Env::extra_dimension;  ///< D: (u, v, t, z)
  static constexpr int dimension = 3 * base_dimension;             ///< Y, S_ton, S_v0
  static constexpr int event_count = 2;
  static constexpr bool smooth_at_events = true;  ///< the force_of_root laws' contact (ContactSystem)
  using State = Eigen::Matrix<double, dimension, 1>;
  using Events = std::array<double, event_count>;

  /// The contact of an impact at v0 [m/s] of mass m [kg] (mu from the environment) on stiffness K
  /// [N/m^{3/2}], the law `law` built for it, followed for at most t_obs [s].
  ContactTangentSystem(const ContactForceJets& law, const Env& env, double K, double mass_kg, double v0_mps,
                       double t_obs_s)
      : law_(&law), env_(env), inverse_mass_(1.0 / env.reduced_mass_kg(mass_kg)), v0_mps_(v0_mps), t_obs_s_(t_obs_s) {
    const double X = undamped_hertz_max_deformation_m(K, env.reduced_mass_kg(mass_kg), v0_mps);
    const double t_H = undamped_hertz_contact_time_factor() * X / v0_mps;
    Eigen::Matrix<double, base_dimension, 1> base;
    base.template head<3>() << std::sqrt(X), v0_mps, t_H;
    const auto z = env.extra_scale(X, v0_mps);
    for (int i = 0; i < Env::extra_dimension; ++i) base[3 + i] = z[static_cast<std::size_t>(i)];
    // S_ton ~ Y / t_H, S_v0 ~ Y / v0.
    scale_ << base, base / t_H, base / v0_mps;
  }

  /// Onset: Y(0), S_ton(0), S_v0(0) (see above).
  State initial_state() const {
    State y = State::Zero();
    y[1] = v0_mps_;
    const auto z = env_.initial_extra();
    const auto dz = env_.initial_extra_onset_derivative();
    for (int i = 0; i < Env::extra_dimension; ++i) {
      y[3 + i] = z[static_cast<std::size_t>(i)];
      y[base_dimension + 3 + i] = dz[static_cast<std::size_t>(i)];
    }
    y[2 * base_dimension + 1] = 1.0;
    return y;
  }

  State state_scale() const { return scale_; }

  void rhs(double, const State& y, State& dy) const {
    constexpr int D = base_dimension;
    std::array<Jet<2>, D> Y;
    for (int i = 0; i < D; ++i) Y[static_cast<std::size_t>(i)] = {y[i], {y[D + i], y[2 * D + i]}};
    Jet<2> F = law_->force(Y[0], Y[1]);
    F.d[1] += law_->speed_derivative(y[0], y[1]);
    std::apply([&](const auto&... r) {
      int i = 0;
      ((dy[i] = r.value, dy[D + i] = r.d[0], dy[2 * D + i] = r.d[1], ++i), ...);
    }, regularized_contact_rates(env_, Y, F, inverse_mass_));
  }

  void events(double, const State& y, Events& g) const { g = {y[0], t_obs_s_ - y[2]}; }
  EventAction handle_event(int, double, const State&) const { return EventAction::stop; }

 private:
  const ContactForceJets* law_;
  Env env_;
  double inverse_mass_, v0_mps_, t_obs_s_;
  State scale_;
};

}  // namespace hertzdash
