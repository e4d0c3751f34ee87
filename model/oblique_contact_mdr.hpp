#pragma once
// An oblique impact of a sphere on a flat whose tangential force is Cattaneo and Mindlin's partial
// slip resolved over the contact area: Coulomb's law holds at every point of the contact, not on
// the total force (model/oblique_contact.hpp's cone). This is the theory of Maw, Barber and
// Fawcett (Wear 38 (1976) 101): a slip annulus at the edge of the contact, where the pressure
// vanishes, from the first instant, and a stuck centre. It is computed by the method of
// dimensionality reduction (MDR: Popov and Hess, Method of Dimensionality Reduction in Contact
// Mechanics and Friction, Springer 2015, ch. 3-4), exact for a paraboloid under any history of
// normal and unidirectional tangential loading: the contact is a row of independent springs on the
// line xi in [-a, a] with the profile g(xi) = xi^2 / R; a spring's normal deflection is
// w(xi) = x - xi^2 / R (a = sqrt(R x), F_n = E* int w dxi = 4/3 E* R^{1/2} x^{3/2}, Hertz) and its
// tangential stiffness 4 G* per unit length (G* Mindlin's, model/tangential/tangential_model.hpp:
// the whole row sticking is 8 G* a, Mindlin's no-slip spring). A spring enters the contact with no
// tangential force, sticks while its force is below mu times its own normal force, slides on that
// limit otherwise, and leaves with its force.
//
// Discretised by symmetry on xi >= 0 into N cells of width h (cell i: [i h, (i + 1) h]); cell i
// carries the tangential force f_i [N] of both halves, its stiffness k_i = 8 G* l_i with l_i its
// length inside the contact, clamp(a - i h, 0, h), so that the row's stiffness is 8 G* a for
// every a (not a staircase), and its limit
//   c_i = mu F_n W_i / W,   W_i = int_cell max(x - xi^2/R, 0) dxi,   W = sum_i W_i = 2 a^3 / (3 R),
// the cone mu F_n shared as MDR's normal springs share the Hertz force (exact for the undamped law;
// for a damped law F_n is the law's, spread like Hertz's pressure). Each cell's force obeys
//   sticking:  df_i/dt = -k_i s  (+ f_i (da/dt) / l_i for the edge cell while the contact shrinks:
//              the part leaving takes its share of the force),
//   sliding:   df_i/dt = sigma_i dc_i/dt  where |f_i| >= c_i and sigma_i (sticking rate) >= dc_i/dt,
// a sweeping process per cell whose switches the adaptive steps resolve (no events: the right-hand
// side is discontinuous across |f_i| = c_i, continuous along a solution); the force on the sphere
// is T = sum_i clamp(f_i, -c_i, c_i). The sphere and the normal contact are
// model/oblique_contact.hpp's (regularising u = x^{1/2}, dt/dtau = 2u; s = w + R omega, s' = T/m_t).
//
// State along tau: (u, v, t, w, omega, W, t_slide, f_0 ... f_{N-1}); W = int T s dt [J], t_slide
// the time during which the whole contact slides (|T| on the cone) [s]. Events (decreasing through
// 0): separation u (stops), the normal force's maximum dF_n/dtau (observes), the observation time
// t_obs - t (stops): model/oblique_contact.hpp's first three, by the same enum.
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/oblique_contact.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace hertzdash {

class MdrObliqueContactSystem {
 public:
  static constexpr int max_cells = 1024;
  static constexpr int dimension = Eigen::Dynamic;
  static constexpr int event_count = 3;
  static constexpr bool smooth_at_events = false;
  using State = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 7 + max_cells, 1>;
  using Events = std::array<double, event_count>;
  enum Index : int { u, v, t, w, omega, W, t_slide, first_cell };

  /// The contact of a sphere of mass m [kg] on stiffness K [N/m^{3/2}] with `cells` cells over the
  /// contact radius of the undamped Hertz impact at v0 (the largest any law reaches), followed for
  /// at most t_obs [s]. The tangential model's own fields are not read: the cells are the model.
  MdrObliqueContactSystem(const NormalForceJet& normal, const TangentialContact& tangential, double K, double mass_kg,
                          const ObliqueOnset& onset, double t_obs_s, int cells)
      : normal_(&normal), mu_(tangential.friction), R_lever_(tangential.radius_m),
        G_(tangential.pair.shear_modulus_Pa), R_(tangential.pair.radius_m), inverse_m_(1 / mass_kg),
        inverse_I_(1 / (tangential.inertia_factor * mass_kg * tangential.radius_m * tangential.radius_m)),
        cells_(cells), onset_(onset), t_obs_s_(t_obs_s) {
    if (cells < 1 || cells > max_cells) throw std::invalid_argument("MdrObliqueContactSystem: cells must be in [1, 1024]");
    const double v0 = onset.normal_speed_mps, X = undamped_hertz_max_deformation_m(K, mass_kg, v0);
    h_ = 1.001 * std::sqrt(R_ * X) / cells;
    const double t_H = undamped_hertz_contact_time_factor() * X / v0;
    const double speed = std::max({v0, std::abs(onset.tangential_speed_mps), std::abs(onset.spin_rad_per_s * R_lever_)});
    const double T_scale = std::clamp(mu_, 1e-3, 1.0) * K * X * std::sqrt(X);
    scale_.resize(first_cell + cells);
    scale_.head<first_cell>() << std::sqrt(X), v0, t_H, speed, speed / R_lever_, 0.5 * mass_kg * speed * speed, t_H;
    scale_.tail(cells).setConstant(T_scale / cells);
  }

  State initial_state() const {
    State y = State::Zero(first_cell + cells_);
    y[v] = onset_.normal_speed_mps;
    y[w] = onset_.tangential_speed_mps;
    y[omega] = onset_.spin_rad_per_s;
    return y;
  }
  State state_scale() const { return scale_; }

  /// The contact point's slip velocity s = w + R omega [m/s].
  double slip_mps(const State& y) const { return y[w] + R_lever_ * y[omega]; }

  /// The tangential force on the sphere T = sum_i clamp(f_i, -c_i, c_i) [N].
  double tangential_force_N(const State& y) const {
    double T = 0;
    for_each_cell(y, normal(y), [&](int i, const Cell& c) { T += std::clamp(y[first_cell + i], -c.limit, c.limit); });
    return T;
  }

  void rhs(double, const State& y, State& dy) const {
    dy.resize(y.size());
    dy.setZero();
    const double uu = std::max(y[u], 0.0), two_u = 2 * uu, s = slip_mps(y);
    const double sigma_friction = s > 0 ? -1.0 : (s < 0 ? 1.0 : 0.0);
    const Normal n = normal(y);
    double T = 0;
    for_each_cell(y, n, [&](int i, const Cell& c) {
      const double f = y[first_cell + i];
      T += std::clamp(f, -c.limit, c.limit);
      // The edge cell shrinking: the part leaving takes its share f (da/dtau) / l.
      const double leaving = c.shrinking ? f * c.edge_rate / c.length : 0.0;
      const double stick = -two_u * c.stiffness * s + leaving;
      const double sigma = f != 0 ? std::copysign(1.0, f) : sigma_friction;
      // On the limit within limit_band of it: an integration error that puts f just inside would
      // otherwise switch it back to sticking, whose rate pushes it out again (chattering).
      const bool at_limit = std::abs(f) >= (1 - limit_band) * c.limit;
      dy[first_cell + i] = at_limit && sigma != 0 && sigma * stick >= c.limit_rate ? sigma * c.limit_rate : stick;
    });
    dy[u] = y[v];
    dy[v] = n.dv;
    dy[t] = two_u;
    dy[w] = two_u * T * inverse_m_;
    dy[omega] = two_u * R_lever_ * T * inverse_I_;
    dy[W] = two_u * T * s;
    // On the cone within the cells' band; at onset (and in tension) the cone is closed and T = 0 on it.
    dy[t_slide] = std::abs(T) >= (1 - 2 * limit_band) * n.cone ? two_u : 0.0;
  }

  void events(double, const State& y, Events& g) const { g = {y[u], normal(y).dF, t_obs_s_ - y[t]}; }

  EventAction handle_event(int which, double, const State&) const {
    return which == static_cast<int>(ObliqueContactEvent::peak_normal_force) ? EventAction::continue_integration
                                                                              : EventAction::stop;
  }

 private:
  /// The normal law at y: dv/dtau, dF_n/dtau, the cone mu F_n (0 in tension) and its rate in tau.
  struct Normal {
    double F, dv, dF, cone, cone_rate;
  };
  Normal normal(const State& y) const {
    const double uu = std::max(y[u], 0.0);
    const ForceJet F = normal_->at(uu, y[v]);
    Normal n{};
    n.F = F.value;
    n.dv = -2 * uu * F.value * inverse_m_;
    n.dF = F.d[0] * y[v] + F.d[1] * n.dv;
    n.cone = mu_ * std::max(F.value, 0.0);
    n.cone_rate = F.value > 0 ? mu_ * n.dF : 0.0;
    return n;
  }

  static constexpr double limit_band = 1e-6;

  /// A cell in contact: its length l_i inside [[m]], stiffness 8 G* l_i [N/m], limit c_i [N] and
  /// the limit's rate in tau, and for the edge cell whether the contact shrinks and da/dtau.
  struct Cell {
    double length, stiffness, limit, limit_rate;
    bool shrinking;
    double edge_rate;
  };
  /// Calls visit(i, cell) for each cell in contact at y, n the normal law there.
  template <class Visit>
  void for_each_cell(const State& y, const Normal& n, Visit&& visit) const {
    const double uu = std::max(y[u], 0.0);
    if (uu <= 0) return;
    const double x = uu * uu, a = std::sqrt(R_) * uu, W_total = 2 * a * a * a / (3 * R_);
    // dx/dtau = 2u v; da/dtau = sqrt(R) v; dW_i/dtau = 2u v l_i, dW/dtau = 2u v a.
    const double xdot = 2 * uu * y[v], da = std::sqrt(R_) * y[v];
    const int active = std::min(cells_, static_cast<int>(std::ceil(a / h_)));
    for (int i = 0; i < active; ++i) {
      const double lo = i * h_, hi = std::min(lo + h_, a);
      if (!(hi > lo)) continue;
      const double length = hi - lo, W_i = x * length - (hi * hi * hi - lo * lo * lo) / (3 * R_), share = W_i / W_total;
      // c_i = mu F W_i / W: dc_i/dtau = mu [dF share + F (dW_i W - W_i dW) / W^2].
      const double rate = n.cone_rate * share + n.cone * xdot * (length * W_total - W_i * a) / (W_total * W_total);
      const bool edge = a < lo + h_;
      visit(i, Cell{length, 8 * G_ * length, n.cone * share, rate, edge && y[v] < 0, da});
    }
  }

  const NormalForceJet* normal_;
  double mu_, R_lever_, G_, R_;
  double inverse_m_, inverse_I_;
  int cells_;
  double h_ = 0;
  ObliqueOnset onset_;
  double t_obs_s_;
  State scale_;
};

}  // namespace hertzdash
