#pragma once
// The soft contact of model/contact_system.hpp with its variational equations along the numbers
// an impact begins with: the onset time t_on [s] (through the environment's state at onset, a
// drive's phase), the approach speed v0 [m/s] (through the initial rate and through the law's
// coefficients, fixed at onset from v0) and, for an environment whose other body has a state of
// its own (SprungPrimary: the damper's primary at X0, V0), that state. What it gives: the contact
// time, the rebound speed and the other body's state at separation, and their derivatives with
// respect to the onset's numbers, the block of a soft impact in the monodromy matrix of an impact
// orbit (simulation/orbits/stroboscopic_map.hpp).
//
// Equations. With Y = (u, v, t, z) the regularised state and f(Y; v0) its right-hand side along
// tau (regularized_contact_rates, the same function ContactSystem integrates), the sensitivities
// S_p = dY/dp for p = t_on, v0 (and the other body's onset state z_k, k < K) obey
//   dY/dtau    = f(Y; v0),                      Y(0)    = (0, v0, 0, z0(t_on))
//   dS_p/dtau  = f_Y S_p + df/dp,               S_ton(0) = (0, 0, 0, dz0/dt_on),  S_v0(0) = (0, 1, 0, 0),
//                                               S_zk(0) = e_{3 + k}
// with df/dt_on = df/dz_k = 0 and df/dv0 = -(2u/mu) dF/dv0 e_v (the law's SpeedDerivativeLaw
// hook). f_Y S_p is one evaluation of f on Jet<P> leaves (model/force_jet.hpp), P = 2 + K: Y_i
// carried with its P sensitivities, the law's force_of_root and the environment's rates on jets,
// dF/dv0 added to the force's v0 direction. No differences anywhere.
//
// Separation (u = 0, the event that stops) needs no correction for its own shift: a perturbed
// contact separates at tau_s + dtau_s with dtau_s = -S_u / v, but dt/dtau = 2u and every
// dz/dtau = 2u r vanish there with dv/dtau = 2u (a - F/mu), so t, v and z are stationary in tau at
// separation and
//   d t_c / dp = S_p,t,    d v_sep / dp = -S_p,v,    d z_k,sep / dp = S_p,z_k.
// (In physical time a separation event's saltation term would be needed; the regularisation
// makes it zero.) A second event, t reaching t_obs, stops a contact that does not end.
//
// The law behind one virtual call (ContactForceJets): the system and its integrator are compiled
// once for an environment, not once per law (simulation/run/soft_contact_tangent.cpp).
//
// The environment Env declares, besides ContactSystem's needs,
//   static constexpr int onset_state_dimension;   K: z's first K components are the other body's
//                                                 state at onset, inputs of the contact (else 0)
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
  /// F(u, xdot) [N] with its derivatives along the jets' directions (2: a wall in prescribed
  /// motion; 4: a body of its own, model/contact_environments.hpp).
  virtual Jet<2> force(const Jet<2>& u, const Jet<2>& xdot) const = 0;
  virtual Jet<4> force(const Jet<4>& u, const Jet<4>& xdot) const = 0;
  /// dF/dv0 [N s/m] at fixed (u, xdot).
  virtual double speed_derivative(double u, double xdot) const = 0;
};

/// The law Law, built for one impact's conditions, as ContactForceJets.
template <SpeedDerivativeLaw Law>
class LawForceJets final : public ContactForceJets {
 public:
  LawForceJets(const ImpactConditions& c, const DampingSettings& s) : law_(c, s) {}
  Jet<2> force(const Jet<2>& u, const Jet<2>& xdot) const override { return law_.force_of_root(u, xdot); }
  Jet<4> force(const Jet<4>& u, const Jet<4>& xdot) const override { return law_.force_of_root(u, xdot); }
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
  static constexpr int parameters = 2 + Env::onset_state_dimension;  ///< P: t_on, v0, the other body's state
  static constexpr int dimension = (1 + parameters) * base_dimension;  ///< Y, S_ton, S_v0, S_z...
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
    // S_ton ~ Y / t_H, S_v0 ~ Y / v0, S_zk ~ Y / (z_k's scale).
    scale_.template head<base_dimension>() = base;
    scale_.template segment<base_dimension>(base_dimension) = base / t_H;
    scale_.template segment<base_dimension>(2 * base_dimension) = base / v0_mps;
    for (int k = 0; k < Env::onset_state_dimension; ++k)
      scale_.template segment<base_dimension>((3 + k) * base_dimension) = base / base[3 + k];
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
    for (int k = 0; k < Env::onset_state_dimension; ++k) y[(3 + k) * base_dimension + 3 + k] = 1.0;
    return y;
  }

  State state_scale() const { return scale_; }

  void rhs(double, const State& y, State& dy) const {
    constexpr int D = base_dimension, P = parameters;
    std::array<Jet<P>, D> Y;
    for (int i = 0; i < D; ++i) {
      Jet<P>& leaf = Y[static_cast<std::size_t>(i)];
      leaf.value = y[i];
      for (int p = 0; p < P; ++p) leaf.d[static_cast<std::size_t>(p)] = y[(1 + p) * D + i];
    }
    Jet<P> F = law_->force(Y[0], Y[1]);
    F.d[1] += law_->speed_derivative(y[0], y[1]);
    std::apply([&](const auto&... r) {
      int i = 0;
      auto put = [&](const Jet<P>& rate) {
        dy[i] = rate.value;
        for (int p = 0; p < P; ++p) dy[(1 + p) * D + i] = rate.d[static_cast<std::size_t>(p)];
        ++i;
      };
      (put(r), ...);
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
