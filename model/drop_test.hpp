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
//   2 peak_force: in contact g = dF/dt = F_x x' + F_v x'' (observation), by
//     contact_force_rate (model/force_rate.hpp). Where F <= 0 no peak can occur and g = -1 (F is identically zero once a
//     heavily damped Hunt-Crossley law reaches 1 + chi x' = 0 to roundoff).
//   3 force_zero: with the tension clamp, g = F (separation where the force
//     reaches zero, stop); else inactive
// At onset the law's coefficients are fixed from that impact's approach speed.
//
// Scales (state_scale, the integrators' absolute tolerances, ode/ode_system.hpp): x ~ X,
// the undamped Hertz maximum compression at the impact speed, and x' ~ v0, the impact
// speed (model/hertz.hpp, undamped_hertz_impact); before the first contact the approach
// speed of the set-up, from each onset on that impact's own.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/force_rate.hpp"
#include "hertzdash/ode/ode_system.hpp"  // the ODE-system vocabulary (EventAction), shared with integrators/

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

/// The drop test's events, in event order (event_index gives the integrators' index).
enum class DropTestEvent : int { contact, max_compression, peak_force, force_zero };

/// The system integrators see: the model plus the per-run workspace (mode, the
/// law calibrated for the current impact).
template <DampingLaw Law>
class DropTest {
 public:
  static constexpr int dimension = 2;
  static constexpr int event_count = 4;
  using State = Eigen::Matrix<double, 2, 1>;
  using Events = std::array<double, event_count>;

  explicit DropTest(const DropTestModel& model) : model_(model) {  ///< keeps a copy
    set_state_scale(approach_speed(model.setup));
  }

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
  /// (X [m], v0 [m/s]) of the coming or current impact (see "Scales" above).
  State state_scale() const { return state_scale_; }

  /// Contact force [N], compressive positive; zero in flight.
  double contact_force(const State& y) const { return law_ ? force_at(std::max(y[0], 0.0), y[1]) : 0.0; }

  void rhs(double, const State& y, State& dy) const {
    dy[0] = y[1];
    dy[1] = model_.gravity_mps2 - contact_force(y) / model_.mass_kg;
  }

  void events(double, const State& y, Events& g) const {
    if (!law_) {
      g = {-y[0], 1.0, 1.0, 1.0};
      return;
    }
    const double x = std::max(y[0], 0.0), v = y[1];
    const double F_law = law_->force(x, v);  // unclamped
    const double F = model_.setup.no_tension ? std::max(F_law, 0.0) : F_law;
    const double a = model_.gravity_mps2 - F / model_.mass_kg;
    const double dFdt = contact_force_rate([this](double xi, double vi) { return force_at(xi, vi); }, x, v, a,
                                           x_scale_m_, v_scale_mps_);
    // A peak force is positive: where F <= 0, g2 = -1 (no root). Heavily damped
    // Hunt-Crossley laws reach 1 + chi x' = 0 to roundoff, where F and dF/dt are
    // identically zero and CVODE's root finder would stop on a flat zero.
    g = {y[0], y[1], F > 0 ? dFdt : -1.0, model_.setup.no_tension ? F_law : 1.0};
  }

  EventAction handle_event(int which, double, const State& y) {
    if (which == event_index(DropTestEvent::contact) && !law_) {
      begin_contact(y);
      return EventAction::restart;
    }
    if (which == event_index(DropTestEvent::contact) || which == event_index(DropTestEvent::force_zero)) {
      law_.reset();
      return EventAction::stop;
    }
    return EventAction::continue_integration;
  }

 private:
  void begin_contact(const State& y) {
    const double v0 = y[1];
    law_.emplace(ImpactConditions{model_.K, model_.mass_kg, v0, model_.setup.restitution}, model_.setup.damping);
    // Scales of the impact: X* = (m v0^2 / K)^{2/5} and v0.
    x_scale_m_ = hertz_impact_scale_m(model_.K, model_.mass_kg, v0);
    v_scale_mps_ = v0;
    set_state_scale(v0);
  }

  /// The scales of an impact at approach speed v0 [m/s].
  void set_state_scale(double v0) {
    state_scale_ << undamped_hertz_max_deformation_m(model_.K, model_.mass_kg, v0), v0;
  }

  /// The law's force at x >= 0, with the tension clamp applied.
  double force_at(double x, double v) const {
    const double F = law_->force(x, v);
    return model_.setup.no_tension ? std::max(F, 0.0) : F;
  }

  DropTestModel model_;
  std::optional<Law> law_;
  double x_scale_m_ = 0.0, v_scale_mps_ = 0.0;  ///< per impact, for difference steps
  State state_scale_;                           ///< per impact, for absolute tolerances
};

}  // namespace hertzdash
