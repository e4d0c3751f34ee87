#include "hertzdash/simulation/run/impact_simulator.hpp"

#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/omega_n_fixed_point.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace hertzdash {

std::vector<std::string> trace_columns() {
  std::vector<std::string> names;
  for (const TraceColumn& c : trace_column_table) names.emplace_back(c.name);
  return names;
}


ImpactSimulator::ImpactSimulator(const SolverSettings& settings) : settings_(settings) { validate(settings_); }

ImpactSummary ImpactSimulator::run(const DropTestSetup& setup, std::string_view law, std::vector<TraceSample>* trace) {
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
  ImpactSummary s;
  with_damping_law(law, [&]<class Law>(std::type_identity<Law>) { s = run<Law>(setup, trace); });
  return s;
}

IntegratorKind integrator_used(const SolverSettings& solver, const DropTestSetup& setup, std::string_view law,
                               std::string* why) {
  IntegratorKind used = solver.integrator;
  with_damping_law(law, [&]<class Law>(std::type_identity<Law>) {
    used = integrator_used(solver.integrator, impact_needs<Law>(setup), why);
  });
  return used;
}

}  // namespace hertzdash
