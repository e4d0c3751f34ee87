#pragma once
// One drop test of the elastic rod on the load cell (model/elastic_drop_test.hpp) with any
// integrator row in the physical variables. Fills the summary from the accepted steps and
// the fired events: impact and rebound are the centre of mass's velocities, so
// e_effective = -v_cm(separation) / v0 counts the energy left in rod vibration as lost; the
// peak force and deformation are the contact's, and the energy account closes the run.
//
// Fixed-step integrators are explicit: their step is limited by the fastest mode. The run
// computes that limit (elastic_stable_step_s) and uses min(--dt, limit), reporting both.
// The run ends at separation, or 20 undamped Hertz contact times after onset.
#include "hertzdash/model/elastic_drop_test.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace hertzdash {

/// The step an explicit fixed-step method can take on the elastic drop test [s]:
///  - the fastest mode's |lambda| is bounded by Gershgorin on M^-1 K with the contact's
///    tangent stiffness k_t = (3/2) K X^{1/2} at the undamped peak deformation X:
///      w_max^2 <= max(4 (k_e + k_t) / m_e, (k_cell + 2 k_t) / m_h),
///    and |lambda| <= w_max (zeta + sqrt(1 + zeta^2)) with zeta the larger of the rod's
///    damping ratio at w_max (beta w_max / 2) and the cell's;
///  - RK4's stability region reaches |h lambda| >= 2.6 in every direction of the left
///    half-plane (2.83 on the imaginary axis, 2.79 on the negative real one, 2.62 at its
///    narrowest, near 122 degrees), so h = 2.6 / |lambda| is stable;
///  - explicit Euler is unstable for any undamped oscillation (|1 + i w h| > 1): the step
///    keeps the fastest mode's growth exp(T w^2 h / 2) over one contact time T below 1 %.
/// Returns +inf for other methods.
inline double elastic_stable_step_s(const ElasticDropTestModel& m, IntegratorKind kind) {
  const UndampedHertzImpact hertz = undamped_hertz_impact(m.K, m.setup.mass_kg, m.v0_mps);
  const double k_t = 1.5 * m.K * std::sqrt(hertz.max_deformation_m);
  const double k_e = m.bar.element_stiffness_N_per_m(), m_e = m.bar.element_mass_kg();
  double w2 = 4.0 * (k_e + k_t) / m_e;
  double zeta = 0.5 * m.bar.damping_beta_s() * std::sqrt(w2);
  if (!m.cell.rigid_base()) {
    w2 = std::max(w2, (m.cell.stiffness_N_per_m + 2.0 * k_t) / m.cell.hemisphere_mass_kg);
    zeta = std::max({0.5 * m.bar.damping_beta_s() * std::sqrt(w2),
                     m.cell.damping_N_s_per_m / (2.0 * std::sqrt(m.cell.stiffness_N_per_m * m.cell.hemisphere_mass_kg))});
  }
  const double lambda = std::sqrt(w2) * (zeta + std::sqrt(1.0 + zeta * zeta));
  if (kind == IntegratorKind::rk4) return 2.6 / lambda;
  if (kind == IntegratorKind::euler) return 2.0 * std::log(1.01) / (hertz.contact_time_s * lambda * lambda);
  return INFINITY;
}

/// The most steps a fixed-step integrator may spend on one elastic contact: explicit Euler's
/// stable step shrinks like 1/N^2 (about 1.5e-11 s at 20 elements on the default cell), so
/// beyond this the run is refused instead of taking minutes and, with --trace, gigabytes.
inline constexpr double elastic_fixed_step_budget = 5e7;

/// The settings a row integrates the elastic drop test with over `duration_s` [s]: a fixed-step
/// row's step is min(--dt, elastic_stable_step_s), and a run that would need more than
/// elastic_fixed_step_budget steps is refused (InvalidParameter naming --integrator).
inline SolverSettings elastic_solver_settings(const ElasticDropTestModel& model, IntegratorKind kind, bool fixed_step,
                                              const SolverSettings& settings, double duration_s) {
  SolverSettings used = settings;
  if (!fixed_step) return used;
  const double stable_s = elastic_stable_step_s(model, kind);
  used.dt_s = std::min(settings.dt_s, stable_s);
  if (duration_s / used.dt_s > elastic_fixed_step_budget)
    throw InvalidParameter("integrator", to_string(kind),
                           fmt::format("an integrator that resolves this elastic rod's run in at most {:g} steps: at "
                                       "its stability limit {:.3g} s, {} would need {:.3g} (use dopri5 or cvode, fewer "
                                       "`rod-elements` or, for bounce, fewer `bounces`)",
                                       elastic_fixed_step_budget, stable_s, to_string(kind), duration_s / used.dt_s));
  return used;
}

namespace detail {

template <class System>
class ElasticImpactObserver {
 public:
  ElasticImpactObserver(const System& sys, double t_onset_s, ImpactSummary& summary, std::vector<TraceSample>* trace)
      : sys_(&sys), t_onset_s_(t_onset_s), s_(&summary), trace_(trace) {}

  void on_step(double t, const typename System::State& y) {
    const double F = sys_->contact_force_N(y), cell = sys_->load_cell_force_N(y);
    s_->peak_force_N = std::max(s_->peak_force_N, F);
    s_->max_deformation_m = std::max(s_->max_deformation_m, sys_->deformation_m(y));
    s_->elastic_rod->peak_load_cell_force_N = std::max(s_->elastic_rod->peak_load_cell_force_N, cell);
    if (!trace_) return;
    const auto& m = sys_->model();
    TraceSample p;
    p.t_s = t_onset_s_ + t;
    p.x_m = sys_->deformation_m(y);
    p.xdot_mps = sys_->deformation_rate_mps(y);
    p.force_N = F;
    p.accel_mps2 = m.setup.gravity_mps2 - F / m.setup.mass_kg;
    p.rod_displacement_m = m.setup.height_m + sys_->centre_of_mass_displacement_m(y);
    p.rod_velocity_mps = sys_->centre_of_mass_velocity_mps(y);
    p.load_cell_force_N = cell;
    p.accelerometer_mps2 = sys_->accelerometer_mps2(y);
    p.xddot_mps2 = sys_->deformation_acceleration_mps2(y);
    trace_->push_back(p);
  }
  void on_event(int, double t, const typename System::State& y, EventAction action) {
    if (action != EventAction::stop) return;
    s_->separated = true;
    s_->t_separation_s = t_onset_s_ + t;
    s_->separation_deformation_m = std::max(sys_->deformation_m(y), 0.0);
    s_->rebound_velocity_mps = std::max(-sys_->centre_of_mass_velocity_mps(y), 0.0);
    s_->elastic_rod->separation_velocity_mps = -sys_->centre_of_mass_velocity_mps(y);
  }

 private:
  const System* sys_;
  double t_onset_s_;
  ImpactSummary* s_;
  std::vector<TraceSample>* trace_;
};

}  // namespace detail

/// The elastic drop test of a validated set-up (elastic_rod set) with the integrator row's
/// integrate(system, y, t0, t1, settings, observer): fills the fields of `s` that describe
/// the impact, the work and s.elastic_rod (the caller derives contact time and e_effective).
template <DampingLaw Law, class Integrate>
void run_elastic_impact(const DropTestSetup& setup, IntegratorKind kind, bool fixed_step, const SolverSettings& settings,
                        Integrate&& integrate, ImpactSummary& s, std::vector<TraceSample>* trace) {
  const ElasticDropTestModel model(setup);
  ElasticDropTest<Law> sys(model);
  ElasticRodReport& r = s.elastic_rod.emplace();
  r.elements = model.bar.elements();
  r.first_frequency_hz = model.bar.frequency_rad_per_s(1) / (2.0 * std::numbers::pi);
  r.wave_round_trip_s = model.bar.wave_round_trip_s();
  const double contact_s = undamped_hertz_impact(model.K, setup.mass_kg, model.v0_mps).contact_time_s;
  const SolverSettings used = elastic_solver_settings(model, kind, fixed_step, settings, contact_s);
  if (fixed_step) {
    r.stable_step_s = elastic_stable_step_s(model, kind);
    r.step_used_s = used.dt_s;
  }
  s.K = model.K;
  s.impact_velocity_mps = model.v0_mps;
  s.t_onset_s = setup.impact_velocity_mps ? 0.0 : model.v0_mps / setup.gravity_mps2;
  s.law_coefficients = sys.law().coefficients();

  detail::ElasticImpactObserver<ElasticDropTest<Law>> observer(sys, s.t_onset_s, s, trace);
  auto y = sys.initial_state();
  const double t_end = 20.0 * contact_s;
  s.work = integrate(sys, y, 0.0, t_end, used, observer);

  const ElasticEnergies e = sys.energies(y);
  r.energy_in_J = 0.5 * setup.mass_kg * model.v0_mps * model.v0_mps + e.gravity_work_J;
  r.energy_rigid_body_out_J = e.rigid_body_kinetic_J;
  r.energy_rod_vibration_J = e.rod_vibration_J;
  r.energy_cell_J = e.cell_J;
  r.energy_dissipated_contact_J = e.dissipated_contact_J;
  r.energy_dissipated_material_J = e.dissipated_material_J;
  r.energy_balance_error_J = r.energy_in_J - (e.rigid_body_kinetic_J + e.rod_vibration_J + e.cell_J +
                                               e.dissipated_contact_J + e.dissipated_material_J);
}

}  // namespace hertzdash
