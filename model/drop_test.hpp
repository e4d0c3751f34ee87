#pragma once
// The drop test as an ODE system, eqs. (1), (2), (4) of Hongo et al.
//
// State y = (x, xdot): x = u - h is the normal deformation of eq. (4) (rod
// displacement u measured downward from the release point, minus the drop
// height h), negative while there is a gap; xdot = udot, downward positive.
//   flight:   x'' = g
//   contact:  x'' = g - F(x, x')/m,   F = law.force(x, x')  (compressive positive)
// so that eq. (1) reads u'' = P/m + g with P = -F.
//
// Events (g_i fires when decreasing through zero):
//   0 contact: in flight g = -x (gap closes: onset, restart); in contact g = x
//     (deformation returns to zero: separation, stop)
//   1 max_compression: in contact g = x' (observation)
//   2 peak_force: in contact g = dF/dt = F_x x' + F_xdot x'' (observation), the
//     partial derivatives by central differences with steps 1e-3 X* in x and
//     1e-3 v0 in x' (X* = (m v0^2/K)^{2/5} the deformation scale). Their relative
//     truncation error O(1e-6) moves the root by O(1e-6) of the contact time, which
//     changes the peak force only by O(1e-12) relative (F is stationary there).
//     Differencing in x and x' separately (rather than along the trajectory) keeps
//     g nonzero on both sides of its root even where the peak force coincides with
//     the maximum compression (undamped law without gravity): a difference along
//     the trajectory is exactly zero over a span of roundoff there, which CVODE's
//     root finder rejects ("root found at and very near t").
//   3 force_zero: with the tension clamp, g = F (separation where the force
//     reaches zero, stop); else inactive
// At onset the law's coefficients are fixed from that impact's approach speed.
#include "integrators/ode_system.hpp"  // the OdeSystem vocabulary only (EventAction); no integrator
#include "model/damping/damping_law.hpp"
#include "model/drop_test_setup.hpp"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace hertzdash {

/// Constant parameters of a drop test, derived once from a validated set-up.
struct DropTestModel {
  explicit DropTestModel(const DropTestSetup& s)
      : setup(s), K(hertz_stiffness(s)), mass_kg(s.mass_kg), gravity_mps2(s.gravity_mps2) {}
  DropTestSetup setup;
  double K;              ///< Hertz stiffness [N/m^{3/2}]
  double mass_kg;
  double gravity_mps2;
};

enum DropTestEvent : int { contact_event = 0, max_compression_event = 1, peak_force_event = 2, force_zero_event = 3 };

/// The system integrators see: the model plus the per-run workspace (mode, the
/// law calibrated for the current impact).
template <DampingLaw Law>
class DropTest {
 public:
  static constexpr int dimension = 2;
  static constexpr int event_count = 4;
  using State = Eigen::Matrix<double, 2, 1>;
  using Events = std::array<double, event_count>;

  explicit DropTest(const DropTestModel& model) : model_(model) {}

  /// Initial state: released from rest at height h, or (with an impact velocity)
  /// at contact onset, already calibrated for that impact.
  State initial_state() {
    State y;
    if (model_.setup.impact_velocity_mps) {
      y << 0.0, *model_.setup.impact_velocity_mps;
      begin_contact(y);
    } else {
      y << -model_.setup.height_m, 0.0;
    }
    return y;
  }

  bool in_contact() const { return law_.has_value(); }
  const Law& law() const { return *law_; }
  const DropTestModel& model() const { return model_; }

  /// Contact force [N], compressive positive; zero in flight.
  double contact_force(const State& y) const {
    if (!law_) return 0.0;
    const double F = law_->force(std::max(y[0], 0.0), y[1]);
    return model_.setup.no_tension ? std::max(F, 0.0) : F;
  }

  void rhs(double, const State& y, State& dy) const {
    dy[0] = y[1];
    dy[1] = model_.gravity_mps2 - contact_force(y) / model_.mass_kg;
  }

  void events(double, const State& y, Events& g) const {
    if (!law_) {
      g = {-y[0], 1.0, 1.0, 1.0};
      return;
    }
    const double a = model_.gravity_mps2 - contact_force(y) / model_.mass_kg;
    const double dx = fd_step_m_, dv = fd_step_mps_;
    const double F_x = (contact_force(State{y[0] + dx, y[1]}) - contact_force(State{y[0] - dx, y[1]})) / (2 * dx);
    const double F_v = (contact_force(State{y[0], y[1] + dv}) - contact_force(State{y[0], y[1] - dv})) / (2 * dv);
    const double dFdt = F_x * y[1] + F_v * a;
    g = {y[0], y[1], dFdt, model_.setup.no_tension ? law_->force(std::max(y[0], 0.0), y[1]) : 1.0};
  }

  EventAction handle_event(int which, double, const State& y) {
    if (which == contact_event && !law_) {
      begin_contact(y);
      return EventAction::restart;
    }
    if (which == contact_event || which == force_zero_event) {
      law_.reset();
      return EventAction::stop;
    }
    return EventAction::continue_integration;
  }

 private:
  void begin_contact(const State& y) {
    const double v0 = y[1];
    law_.emplace(ImpactConditions{model_.K, model_.mass_kg, v0, model_.setup.restitution}, model_.setup.damping);
    // Deformation scale X* = (m v0^2 / K)^{2/5} and speed scale v0.
    fd_step_m_ = 1e-3 * std::pow(model_.mass_kg * v0 * v0 / model_.K, 0.4);
    fd_step_mps_ = 1e-3 * v0;
  }

  const DropTestModel& model_;
  std::optional<Law> law_;
  double fd_step_m_ = 0.0;    ///< central-difference step in x for F_x [m]
  double fd_step_mps_ = 0.0;  ///< central-difference step in x' for F_xdot [m/s]
};

}  // namespace hertzdash
