#pragma once
// One drop test, end to end: validated set-up -> system (model) -> integrator ->
// trajectory and events -> summary. The integrator is one setting, so comparing
// integrators on the same model is one flag; which integrator actually runs (after
// the table's fall-backs) is reported in the summary.
//
// Other systems fit the same pattern: the integrator rows integrate any OdeSystem of any
// size, and IntegratorWorkspace keeps one CVODE memory per system size. A body model is a
// system in model/ plus a run_..._impact beside physical_impact.hpp that builds it and
// observes it into a summary, as the elastic rod on the load cell does
// (model/elastic_drop_test.hpp, elastic_impact.hpp); a sequence of impacts is a system whose
// separation event restarts instead of stopping, observed impact by impact.
#include "hertzdash/model/damping/registry.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/run/elastic_impact.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/physical_impact.hpp"
#include "hertzdash/simulation/run/regularized_impact.hpp"
#include "hertzdash/simulation/run/result_checks.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"
#include "hertzdash/simulation/run/step_resolution.hpp"
#include "hertzdash/simulation/run/viscous_time_constant.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>
#include <type_traits>
#include <vector>

namespace hertzdash {

/// Runs impacts; keeps its integrators' memory across runs (CVodeReInit), so a sweep
/// pays the solver set-up once. One per thread.
class ImpactSimulator {
 public:
  explicit ImpactSimulator(const SolverSettings& settings);  ///< validates the settings

  /// Run the drop test with the registered law `law` (validated set-up required). The
  /// iterated omega_n variants of the paper's law run to their fixed point
  /// (simulation/run/omega_n_fixed_point.hpp), reported in summary.omega_n_iteration; they
  /// need law = the paper's (else InvalidParameter("omega-n", ...)), and an iteration
  /// that does not converge throws std::runtime_error saying why (the impact is undefined).
  ImpactSummary run(const DropTestSetup& setup, std::string_view law, std::vector<TraceSample>* trace = nullptr);

  /// The same for a law known at compile time: the force inlines into the integrator.
  /// The omega_n variant is used as given (an iterated one needs damping.omega_n_rad_per_s).
  template <DampingLaw Law>
  ImpactSummary run(const DropTestSetup& setup, std::vector<TraceSample>* trace = nullptr);

 private:
  SolverSettings settings_;
  IntegratorWorkspace workspace_;
};

/// What the impact of `setup` with the law `Law` asks of an integrator.
template <DampingLaw Law>
ImpactNeeds impact_needs(const DropTestSetup& setup) {
  return {.tension_clamp = setup.no_tension, .elastic_rod = setup.elastic_rod.has_value(),
          .root_polynomial_law = RootPolynomialLaw<Law>};
}

/// The integrator that runs the registered law `law` on `setup` when `solver` asks for
/// solver.integrator: the table's fall-backs (see integrator_used above; `why` likewise).
IntegratorKind integrator_used(const SolverSettings& solver, const DropTestSetup& setup, std::string_view law,
                               std::string* why = nullptr);

/// One impact with a law known at compile time, for instance a law of your own that no
/// registry knows (it needs only the DampingLaw concept, model/damping/damping_law.hpp):
///   const ImpactSummary s = simulate<MyLaw>(setup, {.integrator = IntegratorKind::gbs8_regularized});
/// Validates the set-up (InvalidParameter). A sweep keeps one ImpactSimulator instead.
template <DampingLaw Law>
ImpactSummary simulate(const DropTestSetup& setup, const SolverSettings& settings = {},
                       std::vector<TraceSample>* trace = nullptr) {
  validate(setup);
  ImpactSimulator simulator(settings);
  return simulator.run<Law>(setup, trace);
}

/// `setup` with the viscous time constant of the law `Law` calibrated from its input e at the
/// reference speed (simulation/run/viscous_time_constant.hpp). The last calibration of each thread
/// is remembered (keyed by K, m, the reference speed, e and the tension clamp: what the
/// calibration of kuwabara-kono depends on), so a sweep over heights with one
/// --reference-velocity calibrates once; without one, each height is calibrated at its own speed
/// and the law returns e at every height.
template <MaterialTimeConstantLaw Law>
DropTestSetup with_calibrated_time_constant(const DropTestSetup& setup) {
  const DropTestSetup c = viscous_calibration_setup(setup);
  const double K = hertz_stiffness(c), v = *c.impact_velocity_mps;
  struct Remembered {
    double K, mass_kg, v_mps, e;
    bool no_tension;
    double A_s;
  };
  thread_local std::optional<Remembered> last;
  DropTestSetup out = setup;
  if (last && last->K == K && last->mass_kg == c.mass_kg && last->v_mps == v && last->e == c.restitution &&
      last->no_tension == c.no_tension) {
    out.damping.viscous_time_constant_s = last->A_s;
    return out;
  }
  const double X = hertz_impact_scale_m(K, c.mass_kg, v);
  SolverSettings accurate;
  accurate.integrator = IntegratorKind::gbs8_regularized;
  accurate.rtol = 1e-12;
  accurate.atol = 1e-12;  // of the impact's scales
  ImpactSimulator simulator(accurate);
  DropTestSetup trial = c;
  const double A = solve_viscous_time_constant_s(
      [&](double A_s) {
        trial.damping.viscous_time_constant_s = A_s;
        const ImpactSummary r = simulator.run<Law>(trial);
        return r.separated ? r.e_effective : 0.0;
      },
      c.restitution, X / v);
  last = Remembered{K, c.mass_kg, v, c.restitution, c.no_tension, A};
  out.damping.viscous_time_constant_s = A;
  return out;
}

template <DampingLaw Law>
ImpactSummary ImpactSimulator::run(const DropTestSetup& setup, std::vector<TraceSample>* trace) {
  if constexpr (MaterialTimeConstantLaw<Law>)
    if (!setup.damping.viscous_time_constant_s) return run<Law>(with_calibrated_time_constant<Law>(setup), trace);
  validate_fixed_step(setup, settings_);
  ImpactSummary s;
  s.integrator_used = integrator_used(settings_.integrator, impact_needs<Law>(setup));
  with_integrator_row(s.integrator_used, [&]<class Row>(std::type_identity<Row>) {
    auto integrate = [&](auto& sys, auto& y, double t0, double t1, auto& observer) {
      return Row::integrate(sys, y, t0, t1, settings_, workspace_, observer);
    };
    if constexpr (Row::traits.variables == Variables::regularized) {
      run_regularized_impact<Law>(setup, integrate, s, trace);
    } else if (setup.elastic_rod) {
      auto integrate_with = [&](auto& sys, auto& y, double t0, double t1, const SolverSettings& used, auto& observer) {
        return Row::integrate(sys, y, t0, t1, used, workspace_, observer);
      };
      run_elastic_impact<Law>(setup, Row::traits.kind, Row::traits.step_control == StepControl::fixed_step, settings_,
                              integrate_with, s, trace);
    } else {
      run_physical_impact<Law>(setup, integrate, s, trace);
    }
  });
  s.peak_contact_pressure_Pa = hertz_peak_pressure_Pa(s.K, setup.ball_radius_m, s.max_deformation_m);
  if (s.separated) {
    s.contact_time_s = s.t_separation_s - s.t_onset_s;
    s.e_effective = s.rebound_velocity_mps / s.impact_velocity_mps;
  }
  require_finite_results(s);
  require_physical_restitution(s, settings_, Law::info, !ConservativeLaw<Law>);
  s.diagnostics = impact_diagnostics(s, setup, settings_);
  return s;
}

}  // namespace hertzdash
