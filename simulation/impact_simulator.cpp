#include "simulation/impact_simulator.hpp"

#include "model/invalid_parameter.hpp"

#include <fmt/format.h>

namespace hertzdash {

const char* to_string(IntegratorKind k) {
  switch (k) {
    case IntegratorKind::euler: return "euler";
    case IntegratorKind::rk4: return "rk4";
    case IntegratorKind::cvode: return "cvode";
    case IntegratorKind::dopri5: return "dopri5";
    case IntegratorKind::dopri5_regularized: return "dopri5-regularized";
    case IntegratorKind::cvode_regularized: return "cvode-regularized";
    case IntegratorKind::gbs8_regularized: return "gbs8-regularized";
  }
  return "?";
}

std::string integrator_names() {
  std::string names;
  for (IntegratorKind k : all_integrator_kinds) names += (names.empty() ? "" : ", ") + std::string(to_string(k));
  return names;
}

IntegratorKind parse_integrator(std::string_view name, const std::string& option) {
  for (IntegratorKind k : all_integrator_kinds)
    if (name == to_string(k)) return k;
  throw InvalidParameter(option, std::string(name), "one of: " + integrator_names());
}

void validate(const SolverSettings& s) {
  // Tolerances of an adaptive integrator; a regularised path steps in tau
  // (dt = 2 x^{1/2} dtau), not in time, so it takes no largest step.
  auto adaptive = [&](double rtol, double atol, double max_step) {
    require_positive("--rtol", rtol, "-");
    require_positive("--atol", atol, "m, m/s");
    require_non_negative("--max-step", max_step, "s");
    if (is_regularized(s.integrator) && max_step != 0)
      throw InvalidParameter("--max-step", fmt::format("{}", max_step),
                             fmt::format("0 (no limit) with {}, whose steps are in tau, not in time", to_string(s.integrator)));
  };
  switch (s.integrator) {
    case IntegratorKind::cvode:
    case IntegratorKind::cvode_regularized: adaptive(s.cvode.rtol, s.cvode.atol, s.cvode.max_step); break;
    case IntegratorKind::dopri5:
    case IntegratorKind::dopri5_regularized: adaptive(s.dopri5.rtol, s.dopri5.atol, s.dopri5.max_step); break;
    case IntegratorKind::gbs8_regularized: adaptive(s.gbs8.rtol, s.gbs8.atol, s.gbs8.max_step); break;
    case IntegratorKind::euler:
    case IntegratorKind::rk4: require_positive("--dt", s.fixed_step.dt, "s"); break;
  }
}

std::vector<std::string> trace_columns() {
  return {"t_s", "x_m", "xdot_mps", "force_N", "accel_mps2", "rod_displacement_m", "rod_velocity_mps"};
}

ImpactSimulator::ImpactSimulator(const SolverSettings& settings) : settings_(settings) {}
ImpactSimulator::~ImpactSimulator() = default;

ImpactSummary ImpactSimulator::run(const DropTestSetup& setup, std::string_view law, std::vector<TraceSample>* trace) {
  ImpactSummary s;
  with_damping_law(law, [&]<class Law>(std::type_identity<Law>) { s = run<Law>(setup, trace); });
  return s;
}

Parameters describe_run(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver) {
  auto num = [](double v) { return fmt::format("{}", v); };
  Parameters p{{"damping", std::string(law)},
               {"mass_kg", num(setup.mass_kg)},
               {"ball_radius_m", num(setup.ball_radius_m)},
               {"ball_E_Pa", num(setup.ball.E_Pa)},
               {"ball_nu", num(setup.ball.nu)},
               {"rod_E_Pa", num(setup.rod.E_Pa)},
               {"rod_nu", num(setup.rod.nu)},
               {"restitution", num(setup.restitution)},
               {"zeta_form", to_string(setup.damping.zeta_form)},
               {"omega_n_variant", to_string(setup.damping.omega_n)},
               {"height_m", num(setup.height_m)}};
  if (setup.impact_velocity_mps) p.emplace_back("impact_velocity_input_mps", num(*setup.impact_velocity_mps));
  p.emplace_back("gravity_mps2", num(setup.gravity_mps2));
  p.emplace_back("no_tension", setup.no_tension ? "true" : "false");
  p.emplace_back("integrator", to_string(solver.integrator));
  if (solver.integrator == IntegratorKind::cvode || solver.integrator == IntegratorKind::cvode_regularized) {
    p.emplace_back("cvode_method", to_string(solver.cvode.method));
    p.emplace_back("rtol", num(solver.cvode.rtol));
    p.emplace_back("atol", num(solver.cvode.atol));
    if (solver.cvode.max_step > 0) p.emplace_back("max_step_s", num(solver.cvode.max_step));
  } else if (solver.integrator == IntegratorKind::dopri5 || solver.integrator == IntegratorKind::dopri5_regularized) {
    p.emplace_back("rtol", num(solver.dopri5.rtol));
    p.emplace_back("atol", num(solver.dopri5.atol));
    if (solver.dopri5.max_step > 0) p.emplace_back("max_step_s", num(solver.dopri5.max_step));
  } else if (solver.integrator == IntegratorKind::gbs8_regularized) {
    p.emplace_back("rtol", num(solver.gbs8.rtol));
    p.emplace_back("atol", num(solver.gbs8.atol));
  } else {
    p.emplace_back("dt_s", num(solver.fixed_step.dt));
    p.emplace_back("locate_events", solver.fixed_step.locate_events ? "true" : "false");
  }
  return p;
}

}  // namespace hertzdash
