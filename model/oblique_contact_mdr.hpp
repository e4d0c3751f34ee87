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
// length inside the contact, clamp(a - i h, 0, h) (the last cell's a - i h, wherever the edge is;
// h is sized for the undamped Hertz impact's largest contact radius), so that the row's stiffness
// is 8 G* a for every a (not a staircase), and its limit
//   c_i = mu F_n W_i / W,   W_i = int_cell max(x - xi^2/R, 0) dxi,   W = sum_i W_i = 2 a^3 / (3 R),
// the cone mu F_n shared as MDR's normal springs share the Hertz force (exact for the undamped law;
// for a damped law F_n is the law's, spread like Hertz's pressure). Each cell's force obeys
//   sticking:  df_i/dt = -k_i s  (+ f_i (da/dt) / l_i for the edge cell while the contact shrinks:
//              the part leaving takes its share of the force),
//   sliding:   T_i = sigma_i c_i, while sigma_i (sticking rate) >= dc_i/dt,
// a sweeping process per cell, exact in continuous time as model/oblique_contact.hpp's is for the
// whole contact: each cell's mode (0 sticking, or sigma_i sliding) is a state, constant between
// events, so that the right-hand side is smooth between switches (decided on f_i against c_i
// inside a step, the stages of a larger step leave a narrow band around the limit and the steps
// collapse); one event, the least of the cells' switch functions, stops the run at the first
// switch, and settled() switches every cell that is due (a cell entering the contact takes the
// mode of its edge; at onset it slides where the cone is closed and sticks where a dashpot acting
// at zero overlap has opened it). The force on the sphere is
// T = sum_i T_i, T_i = clamp(f_i, -c_i, c_i) sticking and sigma_i c_i sliding. The sphere and the
// normal contact are model/oblique_contact.hpp's (regularising u = x^{1/2}, dt/dtau = 2u;
// s = w + R omega, s' = T/m_t).
//
// State along tau: (u, v, t, w, omega, W, t_slide, f_0 ... f_{N-1}, mode_0 ... mode_{N-1}); W =
// int T s dt [J], t_slide the time during which every cell slides [s]. Events (decreasing through
// 0): separation u (stops), the normal force's maximum dF_n/dtau (observes), the observation time
// t_obs - t (stops), a cell's switch (stops).
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/oblique_contact.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace hertzdash {

enum class MdrContactEvent : int { separation, peak_normal_force, observation_time, cell_switch };

class MdrObliqueContactSystem {
 public:
  static constexpr int max_cells = 512;
  static constexpr int dimension = Eigen::Dynamic;
  static constexpr int event_count = 4;
  static constexpr bool smooth_at_events = false;
  using State = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 7 + 2 * max_cells, 1>;
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
    if (cells < 1 || cells > max_cells) throw std::invalid_argument("MdrObliqueContactSystem: cells must be in [1, max_cells]");
    const double v0 = onset.normal_speed_mps, X = undamped_hertz_max_deformation_m(K, mass_kg, v0);
    h_ = 1.001 * std::sqrt(R_ * X) / cells;
    const double t_H = undamped_hertz_contact_time_factor() * X / v0;
    const double speed = std::max({v0, std::abs(onset.tangential_speed_mps), std::abs(onset.spin_rad_per_s * R_lever_)});
    const double T_scale = std::clamp(mu_, 1e-3, 1.0) * K * X * std::sqrt(X);
    scale_.resize(first_cell + 2 * cells);
    scale_.head<first_cell>() << std::sqrt(X), v0, t_H, speed, speed / R_lever_, 0.5 * mass_kg * speed * speed, t_H;
    scale_.segment(first_cell, cells).setConstant(T_scale / cells);
    scale_.tail(cells).setConstant(1.0);
    // A cell's force rate in tau, dT/dtau = 2u dT/dt ~ 2 u_scale T_cell / t_H.
    rate_unit_ = 2 * scale_[u] * scale_[first_cell] / t_H;
    probe_step_ = 1e-9 * t_H / (2 * scale_[u]);  // the contact lasts about t_H / (2 u_scale) in tau
  }

  State initial_state() const {
    State y = State::Zero(first_cell + 2 * cells_);
    y[v] = onset_.normal_speed_mps;
    y[w] = onset_.tangential_speed_mps;
    y[omega] = onset_.spin_rad_per_s;
    return settled(y);
  }
  State state_scale() const { return scale_; }
  /// 1e-9 of the contact's duration in tau (about t_H / (2 u_scale)): settled()'s probe ahead, and
  /// the least progress of a piece of the run that is not a switch undone at once.
  double probe_step() const { return probe_step_; }

  /// The contact point's slip velocity s = w + R omega [m/s].
  double slip_mps(const State& y) const { return y[w] + R_lever_ * y[omega]; }

  /// y with every cell in the mode its rates call for. A sticking cell at its limit (within
  /// stick_band) whose sticking rate pushes outwards at least as fast as the limit moves slides, its
  /// force set on the limit; a sliding cell whose sticking rate has turned inwards sticks, and so
  /// does a sticking cell at its limit moving inwards, each force set stick_band inside the limit:
  /// every cell's switch function then starts above 0, as the one event, their least, must for any
  /// later switch to be seen. A cell out of the
  /// contact has no force and the mode of the contact's edge (a wrong guess is one more switch).
  /// Where the contact's edge crosses into a cell the rates jump (a fresh cell's, or the share the
  /// part leaving takes), and a mode decided on the rates before the jump is undone just after it,
  /// at the same instant: the run then settles again `ahead`, comparing the rates at a probe
  /// probe_step() along the solution (y + dtau dy/dtau), past the jump.
  State settled(const State& y, bool ahead = false) const {
    State probe = y, dy;
    if (ahead) {
      rhs(0, y, dy);
      probe += probe_step_ * dy;
    }
    // The forces and limits are y's (at onset a cell in contact at the probe has none yet).
    std::array<double, max_cells> limit{};
    const Normal at_y = normal(y);
    for_each_cell(y, at_y, [&](int i, const Cell& c) { limit[i] = c.limit; });
    State z = y;
    const double s = slip_mps(probe), friction = s > 0 ? -1.0 : (s < 0 ? 1.0 : 0.0);
    // With no cell in contact (onset), the first cell enters sliding where the cone is closed (a
    // Hertz-type law: the Maw, Barber and Fawcett criterion then decides at once), but sticking,
    // with no force, where a dashpot acting at zero overlap has opened it: sliding there would put
    // the whole cone mu F_n on a cell of no stiffness, a force no spring had stored.
    double edge_mode = at_y.cone > 0 ? 0.0 : friction;
    int in_contact = 0;
    for_each_cell(probe, normal(probe), [&](int i, const Cell& c) {
      ++in_contact;
      const CellState now = cell_state(probe, i, c, s);
      double& f = z[first_cell + i];
      double& mode = z[first_cell + cells_ + i];
      if (mode == 0 && std::abs(f) >= (1 - stick_band) * limit[i]) {
        const double sigma = f != 0 ? std::copysign(1.0, f) : friction;
        if (sigma != 0 && sigma * now.stick >= c.limit_rate) mode = sigma, f = sigma * limit[i];
        else f = sigma * (1 - 2 * stick_band) * limit[i];  // at the limit, moving inwards: just inside
      } else if (mode != 0 && mode * now.stick < c.limit_rate) {
        f = mode * (1 - 2 * stick_band) * limit[i];
        mode = 0;
      }
      edge_mode = mode;
    });
    for (int i = in_contact; i < cells_; ++i) z[first_cell + i] = 0, z[first_cell + cells_ + i] = edge_mode;
    return z;
  }

  void rhs(double, const State& y, State& dy) const {
    dy.resize(y.size());
    dy.setZero();
    const double two_u = 2 * std::max(y[u], 0.0), s = slip_mps(y);
    const Normal n = normal(y);
    double T = 0;
    bool every_cell_slides = true;  // at onset and in tension, with no cell in contact, the cone is closed
    for_each_cell(y, n, [&](int i, const Cell& c) {
      const CellState cell = cell_state(y, i, c, s);
      T += cell.force;
      dy[first_cell + i] = cell.rate;
      every_cell_slides = every_cell_slides && cell.sliding;
    });
    dy[u] = y[v];
    dy[v] = n.dv;
    dy[t] = two_u;
    dy[w] = two_u * T * inverse_m_;
    dy[omega] = two_u * R_lever_ * T * inverse_I_;
    dy[W] = two_u * T * s;
    dy[t_slide] = every_cell_slides ? two_u : 0.0;
  }

  /// Whether the cells' switch function is above 0 at y, so that the next switch will be seen
  /// (after settled(): where it is not, the run settles again ahead).
  bool switches_armed(const State& y) const {
    Events g;
    events(0, y, g);
    return g[static_cast<int>(MdrContactEvent::cell_switch)] > 0;
  }

  /// The cells' switch function is the least of each cell's, each in its own scale and > 0 while
  /// its mode holds: sticking, (1 - stick_band) c_i - |f_i| over a cell's force scale; sliding,
  /// sigma_i (sticking rate) - dc_i (plus slide_offset of the two rates, against rounding) over a
  /// cell's rate scale; plus onset_margin, so that at onset, where every rate vanishes, a crossing
  /// inside the first step is seen (model/oblique_contact.hpp's margins, for the same reasons).
  void events(double, const State& y, Events& g) const {
    const Normal n = normal(y);
    const double s = slip_mps(y);
    double least = 1;
    for_each_cell(y, n, [&](int i, const Cell& c) {
      const CellState cell = cell_state(y, i, c, s);
      const double mode = y[first_cell + cells_ + i];
      const double g_i = mode == 0 ? ((1 - stick_band) * c.limit - std::abs(y[first_cell + i])) / scale_[first_cell]
                                   : (mode * cell.stick - c.limit_rate +
                                      slide_offset * (std::abs(cell.stick) + std::abs(c.limit_rate))) / rate_unit_;
      least = std::min(least, g_i + onset_margin);
    });
    g = {y[u], n.dF, t_obs_s_ - y[t], least};
  }

  EventAction handle_event(int which, double, const State&) const {
    return which == static_cast<int>(MdrContactEvent::peak_normal_force) ? EventAction::continue_integration
                                                                         : EventAction::stop;
  }

 private:
  static constexpr double stick_band = 1e-8, onset_margin = 1e-10, slide_offset = 1e-6;

  /// The normal law at y (model/oblique_contact.hpp).
  using Normal = NormalContactRates;
  Normal normal(const State& y) const { return normal_contact_rates(*normal_, y[u], y[v], mu_, inverse_m_); }

  /// A cell in contact: its length inside the contact l_i [m], stiffness 8 G* l_i [N/m], limit c_i
  /// [N] and the limit's rate in tau, and for the edge cell whether the contact shrinks and da/dtau.
  struct Cell {
    double length, stiffness, limit, limit_rate;
    bool shrinking;
    double edge_rate;
  };
  /// A cell's force on the sphere T_i [N], f_i's rate in tau, its sticking rate (T_i's rate were it
  /// to stick), and whether it slides.
  struct CellState {
    double force, rate, stick;
    bool sliding;
  };
  /// Cell i's state at y, s the slip there, in the mode its state holds. Sticking: force
  /// clamp(f_i, -c_i, c_i) and rate -2u k_i s, and the edge cell, while the contact shrinks, loses
  /// the share T_i (da/dtau)/l_i of its force that leaves with the part leaving. Sliding: force
  /// sigma_i c_i, the limit itself, and f_i held (settled() sets it where the cell sticks again):
  /// each c_i has a jump in its second derivative where the contact's edge enters or fills the cell,
  /// which the sum of the limits, mu F_n, does not have, and f_i following c_i would carry each
  /// into the step control (40 steps a cell at rtol 1e-11, 8000 over a sliding contact of 200).
  CellState cell_state(const State& y, int i, const Cell& c, double s) const {
    const double f = y[first_cell + i], mode = y[first_cell + cells_ + i], two_u = 2 * std::max(y[u], 0.0);
    const double force = mode != 0 ? mode * c.limit : std::clamp(f, -c.limit, c.limit);
    const double stick = -two_u * c.stiffness * s + (c.shrinking ? force * c.edge_rate / c.length : 0.0);
    return {force, mode != 0 ? 0.0 : stick, stick, mode != 0};
  }

  /// Calls visit(i, cell) for each cell in contact at y, n the normal law there.
  template <class Visit>
  void for_each_cell(const State& y, const Normal& n, Visit&& visit) const {
    const double uu = std::max(y[u], 0.0);
    if (uu <= 0) return;
    const double a = std::sqrt(R_) * uu, W_total = 2 * a * a * a / (3 * R_);
    // dx/dtau = 2u v; da/dtau = sqrt(R) v; dW_i/dtau = 2u v l_i, dW/dtau = 2u v a.
    const double xdot = 2 * uu * y[v], da = std::sqrt(R_) * y[v];
    const int active = std::min(cells_, static_cast<int>(std::ceil(a / h_)));
    for (int i = 0; i < active; ++i) {
      // The last cell reaches the contact's edge wherever it is: a law whose overlap exceeds the
      // undamped Hertz one the cells were sized for (a softer kelvin-voigt spring) widens it,
      // coarser there, but the shares still sum to 1 and the stiffness to 8 G* a.
      const bool last = i == cells_ - 1;
      const double lo = i * h_, hi = last ? a : std::min(lo + h_, a);
      if (!(hi > lo)) continue;
      // W_i = int_lo^hi (a^2 - xi^2)/R dxi = l_i [(a^2 - hi^2) + (a^2 - lo^2) + (a^2 - hi lo)] / (3R), each
      // difference a product: x l_i - (hi^3 - lo^3)/(3R) lost every digit to cancellation in a cell
      // the edge is leaving (l_i ~ 1e-15 m), and with it the cell's switch function.
      const double length = hi - lo;
      const double W_i = length * ((a - hi) * (a + hi) + (a - lo) * (a + lo) + a * (a - hi) + hi * (a - lo)) / (3 * R_);
      const double share = W_i / W_total;
      // c_i = mu F W_i / W: dc_i/dtau = mu [dF share + F (dW_i W - W_i dW) / W^2].
      const double rate = n.cone_rate * share + n.cone * xdot * (length * W_total - W_i * a) / (W_total * W_total);
      const bool edge = last || a < lo + h_;
      visit(i, Cell{length, 8 * G_ * length, n.cone * share, rate, edge && y[v] < 0, da});
    }
  }

  const NormalForceJet* normal_;
  double mu_, R_lever_, G_, R_;
  double inverse_m_, inverse_I_;
  int cells_;
  double h_ = 0, rate_unit_ = 0, probe_step_ = 0;
  ObliqueOnset onset_;
  double t_obs_s_;
  State scale_;
};

}  // namespace hertzdash
