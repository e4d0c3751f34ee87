#include "hertzdash/simulation/run/impact_simulator.hpp"

#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/damping/registry.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/law_runs.hpp"
#include "hertzdash/simulation/run/omega_n_fixed_point.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <typeinfo>

namespace hertzdash {

std::vector<std::string> trace_columns() {
  std::vector<std::string> names;
  for (const TraceColumn& c : trace_column_table) names.emplace_back(c.name);
  return names;
}

ImpactSimulator::ImpactSimulator(const SolverSettings& settings) : settings_(settings) { validate(settings_); }

// A run that fails says which run it was (law, e, approach speed, integrator): a study or a
// sweep runs thousands, and "did not finish: CVODE took 1000000 steps" alone named none of them.
// Only a plain std::runtime_error is extended; a typed one (DataError, ...) passes unchanged.
ImpactSummary ImpactSimulator::run(const DropTestSetup& setup, std::string_view law,
                                   std::vector<TraceSample>* trace) try {
  if (setup.air_drag.active())  // the fall is integrated without drag: refused, not ignored
    throw InvalidParameter("air-density", format_value(setup.air_drag.air_density_kg_per_m3),
                           "0 for a single impact, whose fall is integrated in vacuum; drag acts in the flights of "
                           "`hertzdash bounce` and `fit --bounce-times` (the rigid rod)");
  if (is_iterated(setup.damping.omega_n)) {
    if (law != HongoPaper::info.name)
      throw InvalidParameter("omega-n", to_string(setup.damping.omega_n),
                             fmt::format("an iterated variant only with `damping` {} (the omega_n assumption belongs "
                                         "to the paper's law; `damping` is {})",
                                         HongoPaper::info.name, law));
    OmegaNFixedPoint r = run_paper_law(*this, setup, {}, trace);
    if (!r.converged)
      throw std::runtime_error(fmt::format("the {} omega_n fixed-point iteration failed after {} iterations: {}",
                                           to_string(setup.damping.omega_n), r.iterations, r.failure));
    r.summary.omega_n_iteration = static_cast<const OmegaNIteration&>(r);
    return r.summary;
  }
  return law_runs(law).run_impact(*this, setup, trace);
} catch (const std::runtime_error& e) {
  if (typeid(e) != typeid(std::runtime_error)) throw;
  throw std::runtime_error(fmt::format("{} (the run of law {} at input e {}, approach speed {:.6g} m/s, integrator {})",
                                       e.what(), law, setup.restitution, approach_speed(setup),
                                       to_string(settings_.integrator)));
}

IntegratorKind integrator_used(const SolverSettings& solver, const DropTestSetup& setup, std::string_view law,
                               std::string* why) {
  return integrator_used(solver.integrator, impact_needs(setup, registered_law(law).root_polynomial), why);
}

}  // namespace hertzdash
