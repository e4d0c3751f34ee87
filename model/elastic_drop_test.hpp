#pragma once
// The drop test as it was built (--rod-model elastic): an elastic rod (model/elastic_bar.hpp)
// strikes the hemisphere on its load cell (model/load_cell.hpp) through the Hertz spring and
// any registered damping law, the same contact as the rigid model (model/drop_test.hpp).
//
// The integration starts at contact onset: before it the rod falls freely and unstrained
// (uniform gravity strains nothing), so every node arrives with the approach speed
// v0 = sqrt(2 g h) (or the given impact velocity). Downward positive, displacements from
// the onset configuration:
//   m_j u_j'' = m_j g + f_j(u, u') - delta_{jN} F,            j = 0 (top) .. N (struck face)
//   m_h w''   = F - k_cell w - c_cell w'                      (w = 0 on a rigid base)
//   x = u_N - w, x' = u_N' - w',  F = law.force(x, x')        (the rigid model's force)
// with f the bar's internal force. The law is calibrated at onset exactly as in the rigid
// model (rod mass m, approach speed v0, input e), so the two models differ only in the
// bodies, never in the contact. Two more states integrate the work the contact absorbs,
// D_c' = F x' (dissipated; it includes energy still stored in the contact if the tension
// clamp ends contact at x > 0), and the material dissipation D_m' = v^T (beta K) v + c_cell w'^2.
//
// State layout (runtime size 2 (N + 1) + 4): (u_0, v_0, u_1, v_1, ..., u_N, v_N, w, w', D_c,
// D_m). The dynamics couple each entry to entries at most 3 positions away (the integral
// rows aside, which feed back into nothing), so CVODE's BDF uses a band solver.
//
// Events (g_i fires when decreasing through zero), in the order of the rigid model's:
//   0 contact: in contact g = x (separation: stop, or restart into flight when more impacts
//     are followed); in flight g = -x (onset: restart into contact)
//   1 max_compression: in contact g = x' (observation)
//   2 peak_force: in contact g = dF/dt where F > 0, else -1 (observation)
//   3 force_zero: in contact with the tension clamp g = F (ends contact like 0); else inactive
// Scales (state_scale, the integrators' absolute tolerances, ode/ode_system.hpp), of the
// current or last impact at approach speed v0: displacements u_j and w ~ X, the undamped
// Hertz maximum compression at v0 (model/hertz.hpp); velocities v_j and w' ~ v0; the
// dissipated energies D_c and D_m ~ (1/2) m v0^2, the impact's kinetic energy.
// By default the run ends at the first separation. follow_impacts(n, v_min) follows the
// flights and the next n - 1 impacts (the rod still ringing, the hemisphere still moving on
// its cell); each impact calibrates the law afresh from its approach speed x' at onset, as the
// rigid model does, and the sequence ends early when a rebound (centre-of-mass speed) is slower
// than v_min.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/elastic_bar.hpp"
#include "hertzdash/model/force_rate.hpp"
#include "hertzdash/model/load_cell.hpp"
#include "hertzdash/ode/ode_system.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

namespace hertzdash {

/// Constant parameters of the elastic drop test, derived once from a validated set-up
/// whose elastic_rod is set.
struct ElasticDropTestModel {
  explicit ElasticDropTestModel(const DropTestSetup& s)
      : setup(s),
        K(hertz_stiffness(s)),
        v0_mps(approach_speed(s)),
        bar(s.elastic_rod->length_m, std::numbers::pi * s.elastic_rod->diameter_m * s.elastic_rod->diameter_m / 4.0,
            s.mass_kg, s.rod.E_Pa, s.elastic_rod->elements, s.elastic_rod->rod_damping_ratio),
        cell(s.elastic_rod->hemisphere_mass_kg, s.elastic_rod->cell_stiffness_N_per_m,
             s.elastic_rod->cell_damping_ratio) {}
  DropTestSetup setup;
  double K;        ///< Hertz stiffness [N/m^{3/2}]
  double v0_mps;   ///< approach speed at onset [m/s]
  ElasticBar bar;
  LoadCell cell;
};

/// The elastic drop test's events, in event order.
enum class ElasticDropTestEvent : int { contact, max_compression, peak_force, force_zero };

/// The energies of the elastic drop test at one state [J] (see the header comment).
struct ElasticEnergies {
  double rigid_body_kinetic_J;   ///< (1/2) m v_cm^2
  double rod_vibration_J;        ///< kinetic energy relative to the centre of mass plus strain energy
  double cell_J;                 ///< hemisphere kinetic plus cell spring energy
  double dissipated_contact_J;   ///< D_c
  double dissipated_material_J;  ///< D_m
  double gravity_work_J;         ///< g sum m_j u_j: work of gravity on the rod since onset
};

template <DampingLaw Law>
class ElasticDropTest {
 public:
  static constexpr int dimension = Eigen::Dynamic;
  static constexpr int max_dimension = 2 * (ElasticRodSetup::max_elements + 1) + 4;
  static constexpr int event_count = 4;
  static constexpr int jacobian_half_bandwidth = 3;
  using State = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, max_dimension, 1>;
  using Events = std::array<double, event_count>;

  /// In contact at onset, calibrated for the approach speed v0.
  explicit ElasticDropTest(const ElasticDropTestModel& model) : model_(model), N_(model.bar.elements()) {
    if (N_ < 1 || N_ > ElasticRodSetup::max_elements)  // the state's inline capacity
      throw std::invalid_argument("ElasticDropTest: elements outside [1, ElasticRodSetup::max_elements]");
    begin_contact(model.v0_mps);
  }

  /// Follow `impacts` impacts in all (>= 1; 1 is the default) through the flights between
  /// them, ending early at a separation whose centre-of-mass rebound speed is below
  /// min_rebound_mps [m/s].
  void follow_impacts(int impacts, double min_rebound_mps) {
    impacts_ = impacts;
    min_rebound_mps_ = min_rebound_mps;
  }

  const ElasticDropTestModel& model() const { return model_; }
  bool in_contact() const { return in_contact_; }
  /// The law of the current impact (in contact), or of the last one.
  const Law& law() const { return *law_; }
  int size() const { return 2 * (N_ + 1) + 4; }
  /// The characteristic magnitude of each state component (see "Scales" above).
  State state_scale() const {
    const double X = undamped_hertz_max_deformation_m(model_.K, model_.setup.mass_kg, v_scale_mps_);
    State s(size());
    for (int j = 0; j <= N_; ++j) s[u(j)] = X, s[v(j)] = v_scale_mps_;
    s[w()] = X;
    s[wdot()] = v_scale_mps_;
    s[dissipated_contact()] = s[dissipated_material()] = 0.5 * model_.setup.mass_kg * v_scale_mps_ * v_scale_mps_;
    return s;
  }

  /// At onset: every node at the approach speed, nothing strained, the hemisphere at rest.
  State initial_state() const {
    State y = State::Zero(size());
    for (int j = 0; j <= N_; ++j) y[v(j)] = model_.v0_mps;
    return y;
  }

  double deformation_m(const State& y) const { return y[u(N_)] - y[w()]; }
  double deformation_rate_mps(const State& y) const { return y[v(N_)] - y[wdot()]; }
  /// Contact force [N], compressive positive (zero where the faces are apart, and in flight).
  double contact_force_N(const State& y) const {
    return in_contact_ ? force_at(std::max(deformation_m(y), 0.0), deformation_rate_mps(y)) : 0.0;
  }
  /// What the load cell measures beyond its preload [N]: the contact force on a rigid base.
  double load_cell_force_N(const State& y) const {
    return model_.cell.rigid_base() ? contact_force_N(y) : model_.cell.force_N(y[w()], y[wdot()]);
  }
  /// Acceleration of node j [m/s^2], downward positive.
  double node_acceleration_mps2(const State& y, int j) const {
    double f = model_.bar.node_internal_force_N([&](int i) { return y[u(i)]; }, [&](int i) { return y[v(i)]; }, j);
    if (j == N_) f -= contact_force_N(y);
    return model_.setup.gravity_mps2 + f / model_.bar.node_mass_kg(j);
  }
  /// x'' = u_N'' - w'' [m/s^2].
  double deformation_acceleration_mps2(const State& y) const {
    return node_acceleration_mps2(y, N_) - hemisphere_acceleration_mps2(y, contact_force_N(y));
  }
  /// The accelerometer's reading: the acceleration of the end face it is on [m/s^2].
  double accelerometer_mps2(const State& y) const {
    return node_acceleration_mps2(y, model_.setup.elastic_rod->accelerometer == Accelerometer::top ? 0 : N_);
  }
  double centre_of_mass_displacement_m(const State& y) const { return mass_weighted(y, 0) / model_.bar.mass_kg(); }
  double centre_of_mass_velocity_mps(const State& y) const { return mass_weighted(y, 1) / model_.bar.mass_kg(); }

  ElasticEnergies energies(const State& y) const {
    const ElasticBar& b = model_.bar;
    double kinetic = 0;
    for (int j = 0; j <= N_; ++j) kinetic += 0.5 * b.node_mass_kg(j) * y[v(j)] * y[v(j)];
    const double v_cm = centre_of_mass_velocity_mps(y);
    const double rigid = 0.5 * b.mass_kg() * v_cm * v_cm;
    return {rigid,
            kinetic - rigid + b.strain_energy_J([&](int j) { return y[u(j)]; }),
            model_.cell.energy_J(y[w()], y[wdot()]),
            y[dissipated_contact()],
            y[dissipated_material()],
            model_.setup.gravity_mps2 * mass_weighted(y, 0)};
  }

  void rhs(double, const State& y, State& dy) const {
    dy.resize(y.size());
    const double xdot = deformation_rate_mps(y);
    const double F = contact_force_N(y);
    const ElasticBar& b = model_.bar;
    b.internal_force([&](int j) { return y[u(j)]; }, [&](int j) { return y[v(j)]; },
                     [&](int j) -> double& { return dy[v(j)]; });
    dy[v(N_)] -= F;
    for (int j = 0; j <= N_; ++j) {
      dy[u(j)] = y[v(j)];
      dy[v(j)] = model_.setup.gravity_mps2 + dy[v(j)] / b.node_mass_kg(j);
    }
    const LoadCell& c = model_.cell;
    dy[w()] = c.rigid_base() ? 0.0 : y[wdot()];
    dy[wdot()] = hemisphere_acceleration_mps2(y, F);
    dy[dissipated_contact()] = F * xdot;
    dy[dissipated_material()] = b.dissipation_rate_W([&](int j) { return y[v(j)]; }) +
                                (c.rigid_base() ? 0.0 : c.damping_N_s_per_m * y[wdot()] * y[wdot()]);
  }

  void events(double, const State& y, Events& g) const {
    if (!in_contact_) {
      g = {-deformation_m(y), 1.0, 1.0, 1.0};
      return;
    }
    const double x = std::max(deformation_m(y), 0.0), xdot = deformation_rate_mps(y);
    const double F_law = law_->force(x, xdot);
    const double F = model_.setup.no_tension ? std::max(F_law, 0.0) : F_law;
    const double xddot = node_acceleration_mps2(y, N_) - hemisphere_acceleration_mps2(y, F);
    const double dFdt = contact_force_rate([this](double xi, double vi) { return force_at(xi, vi); }, x, xdot, xddot,
                                           x_scale_m_, v_scale_mps_);
    g = {deformation_m(y), xdot, F > 0 ? dFdt : -1.0, model_.setup.no_tension ? F_law : 1.0};
  }

  EventAction handle_event(int which, double, const State& y) {
    const bool contact_event = which == event_index(ElasticDropTestEvent::contact);
    if (!in_contact_) {
      if (!contact_event) return EventAction::continue_integration;
      begin_contact(deformation_rate_mps(y));
      return EventAction::restart;
    }
    if (!contact_event && which != event_index(ElasticDropTestEvent::force_zero)) return EventAction::continue_integration;
    in_contact_ = false;
    ++impacts_done_;
    const bool more = impacts_done_ < impacts_ && -centre_of_mass_velocity_mps(y) >= min_rebound_mps_;
    return more ? EventAction::restart : EventAction::stop;
  }

 private:
  static int u(int j) { return 2 * j; }
  static int v(int j) { return 2 * j + 1; }
  int w() const { return 2 * (N_ + 1); }
  int wdot() const { return w() + 1; }
  int dissipated_contact() const { return w() + 2; }
  int dissipated_material() const { return w() + 3; }

  /// Contact from now on, the law calibrated for the approach speed v [m/s] (x' at onset).
  void begin_contact(double v) {
    law_.emplace(ImpactConditions{model_.K, model_.setup.mass_kg, v, model_.setup.restitution}, model_.setup.damping);
    in_contact_ = true;
    x_scale_m_ = hertz_impact_scale_m(model_.K, model_.setup.mass_kg, v);
    v_scale_mps_ = v;
  }

  /// The law's force at x >= 0 (in contact), with the tension clamp applied.
  double force_at(double x, double xdot) const {
    const double F = law_->force(x, xdot);
    return model_.setup.no_tension ? std::max(F, 0.0) : F;
  }
  /// w'' = (F - k_cell w - c_cell w') / m_h [m/s^2] under contact force F; 0 on a rigid base.
  double hemisphere_acceleration_mps2(const State& y, double F) const {
    const LoadCell& c = model_.cell;
    return c.rigid_base() ? 0.0 : (F - c.force_N(y[w()], y[wdot()])) / c.hemisphere_mass_kg;
  }
  /// sum m_j u_j (which = 0) or sum m_j v_j (which = 1).
  double mass_weighted(const State& y, int which) const {
    double s = 0;
    for (int j = 0; j <= N_; ++j) s += model_.bar.node_mass_kg(j) * y[2 * j + which];
    return s;
  }

  ElasticDropTestModel model_;
  int N_;
  std::optional<Law> law_;   ///< the law of the current (in contact) or last impact
  bool in_contact_ = false;
  double x_scale_m_ = 0, v_scale_mps_ = 0;  ///< this impact's deformation and speed scales, for difference steps
  int impacts_ = 1, impacts_done_ = 0;
  double min_rebound_mps_ = 0;
};

}  // namespace hertzdash
