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
//
// run<Law> is declared here and defined in simulation/run/impact_simulator_run.hpp: each
// registered law's run is compiled once, in that law's own generated translation unit
// (simulation/run/law_runs.hpp), and a call of it from anywhere else links to that one. A law no
// registry knows is run by including impact_simulator_run.hpp where it is called.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/damping/registry.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"
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
  /// Defined in simulation/run/impact_simulator_run.hpp; compiled once for each registered law.
  template <DampingLaw Law>
  ImpactSummary run(const DropTestSetup& setup, std::vector<TraceSample>* trace = nullptr);

 private:
  SolverSettings settings_;
  IntegratorWorkspace workspace_;
};

/// What the impact of `setup` asks of an integrator, with a law that is a RootPolynomialLaw or not.
inline ImpactNeeds impact_needs(const DropTestSetup& setup, bool root_polynomial_law) {
  return {.tension_clamp = setup.no_tension, .elastic_rod = setup.elastic_rod.has_value(),
          .root_polynomial_law = root_polynomial_law};
}

/// The integrator that runs the registered law `law` on `setup` when `solver` asks for
/// solver.integrator: the table's fall-backs (see integrator_used above; `why` likewise).
IntegratorKind integrator_used(const SolverSettings& solver, const DropTestSetup& setup, std::string_view law,
                               std::string* why = nullptr);

/// One impact with a law known at compile time, for instance a law of your own that no
/// registry knows (it needs only the DampingLaw concept, model/damping/damping_law.hpp; include
/// simulation/run/impact_simulator_run.hpp for it):
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
    Law::set_material_constant(out.damping, last->A_s);
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
        Law::set_material_constant(trial.damping, A_s);
        const ImpactSummary r = simulator.run<Law>(trial);
        return r.separated ? r.e_effective : 0.0;
      },
      c.restitution, Law::material_constant_scale(X, v));
  last = Remembered{K, c.mass_kg, v, c.restitution, c.no_tension, A};
  Law::set_material_constant(out.damping, A);
  return out;
}

}  // namespace hertzdash
