#pragma once
// A drop and the bounces that follow it, and the restitution the paper's method reads from
// them. The paper measured e "by dropping the rod and taking the time intervals between
// impacts"; with onset times t_on[n], the interval ratio
//   e_from_intervals[n] = (t_on[n+2] - t_on[n+1]) / (t_on[n+1] - t_on[n])
// equals the velocity ratio v_r/v0 only if contacts were instantaneous and e did not depend
// on the impact speed. Both are reported, per impact, beside each other.
//
// The rigid model (the paper's): each impact is one ImpactSimulator run at that impact's
// approach speed, gravity on during contact, with any law and integrator; the flights between
// are ballistic and taken in closed form,
//   t_on[n+1] = t_sep[n] + 2 v_r[n] / g,   v0[n+1] = v_r[n]
// (with the tension clamp, contact may end at a depth x_s > 0, which the face must climb out of:
// v0[n+1] = sqrt(v_r^2 - 2 g x_s), t_on[n+1] = t_sep[n] + (v_r + v0[n+1]) / g),
// and with air drag (`air-density`, model/air_drag.hpp) the drag's closed forms instead: the rise
// to the apex H and the fall through H - x_s, the first fall from `height` likewise,
// so no flight is integrated and event-location errors cannot accumulate: the onset time of
// impact n carries only the contact-time and rebound-speed errors of the impacts before it
// (tests/test_bounce_sequence.cpp bounds them; validation/bounce states them).
// The elastic rod (--rod-model elastic): the flights are integrated, since the rod keeps
// ringing and the hemisphere keeps moving on its cell between impacts
// (model/elastic_drop_test.hpp, follow_impacts); speeds are the rod's centre of mass's.
//
// A law with a material time constant (kuwabara-kono) is calibrated once, at the first
// impact's approach speed unless a reference speed is given, and keeps its A through the
// sequence: its e changes from impact to impact, as a material's would.
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/run/calibrate_restitution.hpp"
#include "hertzdash/simulation/run/diagnostic_codes.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

/// The most impacts one sequence follows (the paper's measurement needs three).
inline constexpr int max_bounces = 1000;

struct BounceOptions {
  int impacts = 5;                           ///< impacts to follow (--bounces), >= 1
  double min_rebound_velocity_mps = 1e-3;    ///< end the sequence after a slower rebound [m/s], >= 0
  /// Called with the number of impacts finished so far after each (a front end's progress
  /// line: a long elastic-rod sequence runs for minutes); empty: nothing is called.
  std::function<void(std::size_t impacts_done)> on_impact = {};
};

/// The number of impacts given as a number (the command line, Python): an integer in
/// [1, max_bounces], else InvalidParameter("bounces", ...).
int parse_bounces(double impacts);

/// Throws InvalidParameter naming --bounces or --min-rebound-velocity.
void validate(const BounceOptions& o);

/// One impact of the sequence. Times from the release (or from the first onset when an impact
/// velocity is given); downward positive, speeds positive.
struct BounceImpact {
  double onset_time_s = 0, separation_time_s = 0, contact_time_s = 0;
  double approach_speed_mps = 0, rebound_speed_mps = 0;
  double peak_force_N = 0, max_deformation_m = 0;
  bool separated = false;  ///< false: the rod came to rest on the ball in this impact
  DiagnosticSet diagnostics;  ///< the impact's notes and warnings (simulation/run/result_checks.hpp)
};

struct BounceSequence {
  std::vector<BounceImpact> impacts;
  std::vector<double> onset_times_s;     ///< t_on[n]
  std::vector<double> e_from_intervals;  ///< the paper's measurement, one per three onsets
  std::vector<double> e_velocity_ratio;  ///< v_r[n] / v0[n], per separated impact
  std::string end_reason;                ///< why the sequence ended
  bool flights_integrated = false;       ///< false: ballistic flights in closed form (rigid model)
  IntegratorKind integrator_used = IntegratorKind::cvode;
  IntegrationStats work;                 ///< every impact (and integrated flight)
  /// The elastic rod with a fixed-step integrator: the step taken, min(--dt, stable_step_s) [s],
  /// and the rod's stability limit for that integrator [s] (simulation/run/elastic_impact.hpp); 0
  /// for an adaptive integrator or the rigid model.
  double step_used_s = 0, stable_step_s = 0;
  std::optional<double> viscous_time_constant_s;  ///< the A used, for a law with a material time constant
};

/// The sequence of the validated `setup` with the registered law `law` (gravity > 0 required,
/// InvalidParameter("gravity", ...) otherwise).
BounceSequence run_bounce_sequence(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                                   const BounceOptions& options);

/// Calibration against the observable: the input e whose sequence (three impacts) has the
/// first interval ratio e_from_intervals[0] = target, by calibrate_input_restitution
/// (InvalidParameter("target-interval-restitution", ...) when out of reach).
RestitutionCalibration calibrate_interval_restitution(const DropTestSetup& setup, std::string_view law,
                                                      const SolverSettings& solver, double target);

/// An impact of the sequence of `setup` as an ImpactSummary: the fields the diagnostics and
/// their messages read (K, approach and rebound speeds, peak force and pressure, deformation,
/// separation, diagnostics, integrator_used).
/// For the elastic rod with a fixed step, elastic_rod holds the sequence's steps only (step_used_s,
/// stable_step_s, elements), what the stability and resolution checks read.
ImpactSummary bounce_impact_summary(const BounceImpact& b, const BounceSequence& sequence, const DropTestSetup& setup);

/// The interval ratios of the onset times t (size n gives n - 2 ratios).
std::vector<double> interval_ratios(const std::vector<double>& onset_times_s);

}  // namespace hertzdash
