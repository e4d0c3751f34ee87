#include "hertzdash/simulation/impact_simulator.hpp"

#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/omega_n_fixed_point.hpp"

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

Parameters describe_run(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver) {
  auto num = [](double v) { return fmt::format("{}", v); };
  Parameters p{{"damping", std::string(law)},
               {"mass_kg", num(setup.mass_kg)},
               {"ball_radius_m", num(setup.ball_radius_m)},
               {"ball_E_Pa", num(setup.ball.E_Pa)},
               {"ball_nu", num(setup.ball.nu)},
               {"ball_yield_stress_Pa", num(setup.ball_yield_stress_Pa)},
               {"rod_E_Pa", num(setup.rod.E_Pa)},
               {"rod_nu", num(setup.rod.nu)},
               {"restitution", num(setup.restitution)},
               {"zeta_form", to_string(setup.damping.zeta_form)},
               {"omega_n_variant", to_string(setup.damping.omega_n)},
               {"height_m", num(setup.height_m)}};
  if (const auto& A = setup.damping.viscous_time_constant_s) p.emplace_back("viscous_time_constant_s", num(*A));
  if (setup.damping.reference_velocity_mps > 0)
    p.emplace_back("reference_velocity_mps", num(setup.damping.reference_velocity_mps));
  for (const auto& [key, value] : setup.damping.law_values) p.emplace_back(spell_key(key, KeySpelling::python), num(value));
  if (setup.impact_velocity_mps) p.emplace_back("impact_velocity_input_mps", num(*setup.impact_velocity_mps));
  p.emplace_back("gravity_mps2", num(setup.gravity_mps2));
  p.emplace_back("no_tension", setup.no_tension ? "true" : "false");
  p.emplace_back("rod_model", setup.elastic_rod ? "elastic" : "rigid");
  if (const auto& e = setup.elastic_rod) {
    p.emplace_back("rod_length_m", num(e->length_m));
    p.emplace_back("rod_diameter_m", num(e->diameter_m));
    p.emplace_back("rod_elements", num(e->elements));
    p.emplace_back("rod_damping_ratio", num(e->rod_damping_ratio));
    p.emplace_back("hemisphere_mass_kg", num(e->hemisphere_mass_kg));
    p.emplace_back("cell_stiffness_N_per_m", num(e->cell_stiffness_N_per_m));
    p.emplace_back("cell_damping_ratio", num(e->cell_damping_ratio));
    p.emplace_back("accelerometer", to_string(e->accelerometer));
  }
  p.emplace_back("integrator", to_string(solver.integrator));
  const IntegratorTraits& row = integrator_traits(solver.integrator);
  if (row.method == IntegratorMethod::cvode) p.emplace_back("cvode_method", to_string(solver.cvode_method));
  if (row.step_control == StepControl::adaptive) {
    p.emplace_back("rtol", num(solver.rtol));
    p.emplace_back("atol", num(solver.atol));
    if (solver.max_step_s > 0) p.emplace_back("max_step_s", num(solver.max_step_s));
  } else {
    p.emplace_back("dt_s", num(solver.dt_s));
    p.emplace_back("locate_events", solver.locate_events ? "true" : "false");
  }
  return p;
}

}  // namespace hertzdash
