#pragma once
// What one impact produces: the summary every run reports, and the samples of the
// contact phase a run records on request.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/run/diagnostic_codes.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

/// How the fixed point of an iterated omega_n variant was found (simulation/run/omega_n_fixed_point.hpp).
struct OmegaNIteration {
  int iterations = 0;           ///< simulations run
  bool converged = false;
  double relative_change = 0;   ///< |w_k - w_{k-1}| / w_k at the last iteration
  double contraction = 0;       ///< last observed |dG| / |dw| (< 1 for a contraction)
  std::string failure;          ///< why it stopped unconverged (empty if converged)
};

/// What the elastic rod (--rod-model elastic) adds to a summary. The energy account runs
/// from contact onset to separation and closes:
///   energy_in = rigid_body_out + rod_vibration + cell + dissipated_contact
///               + dissipated_material + balance_error.
struct ElasticRodReport {
  int elements = 0;                      ///< finite elements N
  double first_frequency_hz = 0;         ///< the discrete rod's first free-free longitudinal frequency
  double wave_round_trip_s = 0;          ///< 2 L / c
  double stable_step_s = 0;              ///< fixed-step integrators: the stability-limited step (0: adaptive)
  double step_used_s = 0;                ///< fixed-step integrators: min(--dt, stable_step_s) (0: adaptive)
  double peak_load_cell_force_N = 0;     ///< largest force the load cell measured
  double separation_velocity_mps = 0;    ///< the centre of mass's velocity at separation, upward positive
                                         ///< (negative: it left the hemisphere still moving down)
  double energy_in_J = 0;                ///< (1/2) m v0^2 plus the work of gravity on the rod during contact
  double energy_rigid_body_out_J = 0;    ///< (1/2) m v_cm^2 at separation
  double energy_rod_vibration_J = 0;     ///< kinetic (relative to the centre of mass) plus strain, at separation
  double energy_cell_J = 0;              ///< hemisphere and cell spring, at separation
  double energy_dissipated_contact_J = 0;   ///< work absorbed by the contact law
  double energy_dissipated_material_J = 0;  ///< rod material damping plus cell damping
  double energy_balance_error_J = 0;     ///< in minus the sum of the five above
};

/// The result of one impact. Velocities are speeds (>= 0).
struct ImpactSummary {
  double K = 0;                        ///< Hertz stiffness [N/m^{3/2}]
  double impact_velocity_mps = 0;      ///< approach speed at contact onset
  double rebound_velocity_mps = 0;     ///< rebound speed at separation (0 if none)
  double e_effective = 0;              ///< rebound / approach speed
  double peak_force_N = 0;             ///< largest contact force
  double max_deformation_m = 0;        ///< largest x
  double peak_contact_pressure_Pa = 0; ///< Hertz peak pressure at the largest x (hertz_peak_pressure_Pa)
  double contact_time_s = 0;           ///< separation minus onset time
  double t_onset_s = 0, t_separation_s = 0;
  double separation_deformation_m = 0; ///< x at separation: > 0 only where the tension clamp ended contact before x = 0
  bool separated = false;              ///< false if the rod came to rest on the ball
  IntegrationStats work;               ///< steps and right-hand-side evaluations, whole run
  std::vector<NamedValue> law_coefficients;
  IntegratorKind integrator_used = IntegratorKind::cvode;  ///< set by ImpactSimulator::run: the one asked for, or its fall-back
  std::optional<OmegaNIteration> omega_n_iteration;  ///< iterated omega_n variants only
  std::optional<ElasticRodReport> elastic_rod;       ///< --rod-model elastic only; the velocities above are the centre of mass's
  DiagnosticSet diagnostics;  ///< set by ImpactSimulator::run: the result's notes and warnings (simulation/run/result_checks.hpp)
};

/// One sample of the contact phase (the --trace columns). Downward positive; for the elastic
/// rod, "rod" means its centre of mass.
struct TraceSample {
  double t_s;
  double x_m, xdot_mps;       ///< deformation x and its rate
  double force_N;             ///< contact force, compressive positive
  double accel_mps2;          ///< the rod's (centre-of-mass) acceleration, g - F/m
  double rod_displacement_m;  ///< from the release point
  double rod_velocity_mps;
  double load_cell_force_N;   ///< what the load cell measures beyond its preload (rigid base: force_N)
  double accelerometer_mps2;  ///< acceleration of the accelerometer's end face (rigid rod: accel_mps2)
  double xddot_mps2;          ///< x'' (rigid rod on a fixed hemisphere: accel_mps2); not a column
};

/// The --trace columns (the measured-trace format, data/measurements/README.md, and the model's
/// own columns, model_trace_columns()): name and value, in column order. Time and rod
/// displacement count from `onset`, the trace's first sample (contact onset), as a measurement's do;
/// force_N and accel_mps2 are what the load cell and the accelerometer read.
struct TraceColumn {
  const char* name;
  double (*value)(const TraceSample& s, const TraceSample& onset);
};
inline constexpr std::array<TraceColumn, 9> trace_column_table{{
    {"t_s", [](const TraceSample& s, const TraceSample& onset) { return s.t_s - onset.t_s; }},
    {"force_N", [](const TraceSample& s, const TraceSample&) { return s.load_cell_force_N; }},
    {"accel_mps2", [](const TraceSample& s, const TraceSample&) { return s.accelerometer_mps2; }},
    {"velocity_mps", [](const TraceSample& s, const TraceSample&) { return s.rod_velocity_mps; }},
    {"displacement_m",
     [](const TraceSample& s, const TraceSample& onset) { return s.rod_displacement_m - onset.rod_displacement_m; }},
    {"x_m", [](const TraceSample& s, const TraceSample&) { return s.x_m; }},
    {"xdot_mps", [](const TraceSample& s, const TraceSample&) { return s.xdot_mps; }},
    {"contact_force_N", [](const TraceSample& s, const TraceSample&) { return s.force_N; }},
    {"rod_accel_mps2", [](const TraceSample& s, const TraceSample&) { return s.accel_mps2; }},
}};
std::vector<std::string> trace_columns();

/// A sample of the rigid model, whose instruments read the contact force and the rod's acceleration.
inline TraceSample rigid_trace_sample(double t_s, double x_m, double xdot_mps, double force_N, double accel_mps2,
                                      double rod_displacement_m, double rod_velocity_mps) {
  return {t_s, x_m, xdot_mps, force_N, accel_mps2, rod_displacement_m, rod_velocity_mps, force_N, accel_mps2, accel_mps2};
}

}  // namespace hertzdash
