#pragma once
// The definition of ImpactSimulator::run<Law> (simulation/run/impact_simulator.hpp): one impact of
// a law known at compile time with every integrator row, the force inlined into each right-hand
// side. The registered laws' runs are compiled once, each in its own generated translation unit
// (simulation/run/law_runs.hpp); include this header only to run a law no registry knows (a law of
// your own: `simulate<MyLaw>(setup)` then compiles here), never beside calls of registered laws
// whose runs you do not want compiled again.
#include "hertzdash/simulation/run/elastic_impact.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/physical_impact.hpp"
#include "hertzdash/simulation/run/regularized_impact.hpp"
#include "hertzdash/simulation/run/result_checks.hpp"
#include "hertzdash/simulation/run/step_resolution.hpp"

#include <type_traits>
#include <vector>

namespace hertzdash {

template <DampingLaw Law>
ImpactSummary ImpactSimulator::run(const DropTestSetup& setup, std::vector<TraceSample>* trace) {
  if constexpr (MaterialTimeConstantLaw<Law>)
    if (!Law::material_constant(setup.damping)) return run<Law>(with_calibrated_time_constant<Law>(setup), trace);
  validate_fixed_step(setup, settings_);
  ImpactSummary s;
  s.integrator_used = integrator_used(settings_.integrator, impact_needs(setup, RootPolynomialLaw<Law>));
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
