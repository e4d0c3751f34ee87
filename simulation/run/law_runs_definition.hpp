#pragma once
// The definition of law_runs_of<Law> (simulation/run/law_runs.hpp): every run of a law (the drop
// test's impact, the elastic rod's bounces, the soft contact with every environment), with the
// integrator templates they instantiate. Included only by the generated translation unit of each
// registered law (simulation/run/law_instantiation.cpp.in), which compiles them once.
#include "hertzdash/simulation/run/bounce_sequence.hpp"
#include "hertzdash/simulation/run/elastic_bounces.hpp"
#include "hertzdash/simulation/run/impact_simulator_run.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/law_runs.hpp"
#include "hertzdash/simulation/run/soft_contact_run.hpp"

#include <type_traits>
#include <vector>

namespace hertzdash {

namespace detail {

/// The elastic rod's bounce sequence with the law `Law` (LawRuns::run_elastic_bounces).
template <DampingLaw Law>
void run_elastic_bounce_sequence(const DropTestSetup& setup, const SolverSettings& solver, const BounceOptions& options,
                                 BounceSequence& out) {
  out.integrator_used = integrator_used(solver.integrator, impact_needs(setup, RootPolynomialLaw<Law>));
  IntegratorWorkspace workspace;
  with_integrator_row(out.integrator_used, [&]<class Row>(std::type_identity<Row>) {
    if constexpr (Row::traits.variables == Variables::physical) {
      auto integrate = [&](auto& sys, auto& y, double t0, double t1, const SolverSettings& used, auto& observer) {
        return Row::integrate(sys, y, t0, t1, used, workspace, observer);
      };
      run_elastic_bounces<Law>(setup, Row::traits.kind, Row::traits.step_control == StepControl::fixed_step, solver,
                               options, integrate, out);
    }
  });
}

/// with_calibrated_time_constant<Law> for a law with a material time constant, else nullptr.
template <DampingLaw Law> constexpr DropTestSetup (*time_constant_calibration())(const DropTestSetup&) {
  if constexpr (MaterialTimeConstantLaw<Law>) return &with_calibrated_time_constant<Law>;
  else return nullptr;
}

/// Law::material_constant for a law with a material time constant, else nullptr.
template <DampingLaw Law> constexpr std::optional<double> (*material_constant_getter())(const DampingSettings&) {
  if constexpr (MaterialTimeConstantLaw<Law>) return &Law::material_constant;
  else return nullptr;
}

/// Law::set_material_constant for a law with a material time constant, else nullptr.
template <DampingLaw Law> constexpr void (*material_constant_setter())(DampingSettings&, double) {
  if constexpr (MaterialTimeConstantLaw<Law>) return &Law::set_material_constant;
  else return nullptr;
}

}  // namespace detail

template <DampingLaw Law> const LawRuns& law_runs_of() {
  static constexpr LawRuns runs{
      .run_impact = [](ImpactSimulator& simulator, const DropTestSetup& setup,
                       std::vector<TraceSample>* trace) { return simulator.run<Law>(setup, trace); },
      .calibrated_time_constant = detail::time_constant_calibration<Law>(),
      .material_constant = detail::material_constant_getter<Law>(),
      .set_material_constant = detail::material_constant_setter<Law>(),
      .run_elastic_bounces = &detail::run_elastic_bounce_sequence<Law>,
      .make_soft_contact = {&make_soft_contact_of<Law, HarmonicForcing>, &make_soft_contact_of<Law, SprungPrimary>},
  };
  return runs;
}

}  // namespace hertzdash
