#include "hertzdash/simulation/run_options.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/omega_n_variant.hpp"
#include "hertzdash/simulation/integrator_table.hpp"
#include "hertzdash/simulation/result_checks.hpp"
#include "hertzdash/simulation/step_resolution.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <utility>

namespace hertzdash {

namespace {

// Which integrators read which setting: the integrator table.
bool reads_step(const IntegratorTraits& r) { return r.step_control == StepControl::fixed_step; }
bool reads_tolerances(const IntegratorTraits& r) { return r.step_control == StepControl::adaptive; }
bool reads_max_step(const IntegratorTraits& r) {
  return r.step_control == StepControl::adaptive && r.variables == Variables::physical;
}
bool reads_cvode_method(const IntegratorTraits& r) { return r.reads_cvode_method; }

std::vector<RunOption> make_run_options() {
  using R = RunOptions;
  using G = RunOption::Group;
  const std::string fixed = integrator_names(reads_step);
  const std::string adaptive = integrator_names(reads_tolerances);
  const std::string timed = integrator_names(reads_max_step);
  const std::string cvode = integrator_names(reads_cvode_method);
  return {
      {"rod", &R::rod, "Rod of Tables 1-3: steel, duralumin-a, duralumin-b, duralumin-c", G::setup},
      {"height", &R::height_m, "Drop height h [m], free fall from rest (default: 0.02)", G::setup, "m"},
      {"impact-velocity", &R::impact_velocity_mps, "Approach speed at contact onset [m/s]; overrides --height", G::setup, "mps"},
      {"mass", &R::mass_kg, "Rod mass [kg] (default: Table 1)", G::setup, "kg"},
      {"restitution", &R::restitution, "Input coefficient of restitution e in (0,1] (default: Table 2; 1 = undamped)",
       G::setup},
      {"ball-E", &R::ball_E_Pa, "Hemisphere Young's modulus [Pa] (default: 2.0e9, assumed)", G::setup, "Pa"},
      {"ball-nu", &R::ball_nu, "Hemisphere Poisson ratio (default: 0.40, assumed)", G::setup},
      {"ball-radius", &R::ball_radius_m, "Hemisphere radius R [m] (default: 0.0127)", G::setup, "m"},
      {"ball-yield-stress", &R::ball_yield_stress_Pa,
       "Hemisphere yield stress Y [Pa]; a Hertz peak pressure above the onset of yield (1.74 Y at nu = 0.4, Johnson) is flagged; inf: no check "
       "(default: 7.0e7, assumed)",
       G::setup, "Pa"},
      {"rod-E", &R::rod_E_Pa, "Rod Young's modulus [Pa]; inf for a rigid flat (default: Table 3)", G::setup, "Pa"},
      {"rod-nu", &R::rod_nu, "Rod Poisson ratio (default: 0.30 steel, 0.33 duralumin, assumed)", G::setup},
      {"gravity", &R::gravity_mps2, "Gravity g [m/s^2], 0 allowed (default: 9.80665)", G::setup, "mps2"},
      {"no-tension", &R::no_tension, "Clamp the contact force at >= 0; contact ends where it reaches zero", G::setup},
      {"zeta", &R::zeta, "Damping ratio from e: paper (eq. 6) or exact (linear oscillator)", G::setup},
      {"omega-n", &R::omega_n,
       "Natural frequency assumption of the paper's law (hongo only): paper (eq. 11, the default), impact-energy, "
       "rebound-energy, self-consistent, contact-time (both iterated to a fixed point), as-printed (the eq. 9 erratum)",
       G::setup},
      {"damping", &R::damping, "Damping law (see `hertzdash models`): " + registered_law_names(), G::setup},
      {"viscous-time-constant", &R::viscous_time_constant_s,
       "Material time constant A [s] >= 0 of the viscoelastic law (kuwabara-kono only): F = K (x^{3/2} + A x^{1/2} "
       "xdot); replaces the calibration from e",
       G::setup, "s"},
      {"reference-velocity", &R::reference_velocity_mps,
       "Approach speed [m/s] > 0 at which the viscoelastic law's restitution is the input e (kuwabara-kono only; "
       "default: the approach speed of the run's first impact)",
       G::setup, "mps"},
      {"rod-model", &R::rod_model,
       "rigid (the paper's model: a rigid rod on a fixed hemisphere) or elastic (the rod as an elastic bar, the "
       "hemisphere on its load cell; docs/elastic-rod.md)",
       G::setup},
      {"rod-elements", &R::rod_elements,
       fmt::format("Finite elements of the elastic rod, an integer in [1, {}] (default: {}, within 2e-6 of converged "
                   "e_effective)",
                   ElasticRodSetup::max_elements, ElasticRodSetup::default_elements),
       G::setup},
      {"rod-damping-ratio", &R::rod_damping_ratio,
       "Damping ratio of the elastic rod's first longitudinal mode, [0, 1) (default: data/assumptions.csv)", G::setup},
      {"cell-stiffness", &R::cell_stiffness_N_per_m,
       "Load cell stiffness [N/m]; inf fixes the hemisphere on a rigid base (default: data/assumptions.csv)",
       G::setup, "N_per_m"},
      {"cell-damping-ratio", &R::cell_damping_ratio,
       "Damping ratio of the hemisphere on the load cell, [0, 1) (default: data/assumptions.csv)", G::setup},
      {"hemisphere-mass", &R::hemisphere_mass_kg, "Hemisphere mass [kg] on the load cell (default: Table 1)",
       G::setup, "kg"},
      {"accelerometer", &R::accelerometer,
       "End face carrying the accelerometer: top (the free end, the default) or bottom (the struck face)", G::setup},
      {"integrator", &R::integrator, "One of: " + integrator_names() + " (default: cvode)", G::solver},
      {"dt", &R::dt_s,
       "Fixed step [s] > 0 and at most t_H / " + std::to_string(min_steps_per_hertz_contact) +
           ", t_H the impact's undamped Hertz contact time (" + fixed +
           "; default: 1e-6; a run needing more than 1e9 steps does not start)",
       G::solver, "s"},
      {"no-event-location", &R::no_event_location,
       "Handle events at the end of the step that crosses them (" + fixed + "; convergence studies)", G::solver},
      {"rtol", &R::rtol,
       "Relative tolerance in (0, 1) (" + adaptive + "; default: 1e-8; above " + fmt::format("{:g}", loose_rtol_limit) +
           " the result carries a loose_tolerance warning)",
       G::solver},
      {"atol", &R::atol,
       "Absolute tolerance relative to the impact's scales, in (0, 1): X for lengths, v0 for speeds, t_H for times "
       "(X, t_H the undamped Hertz maximum compression and contact time at the impact speed v0; " + adaptive +
           "; default: 1e-12)",
       G::solver},
      {"cvode-method", &R::cvode_method, "CVODE method: adams or bdf (" + cvode + "; default: adams)", G::solver},
      {"max-step", &R::max_step_s, "Largest step [s] >= 0; 0 = no limit (" + timed + "; default: 0)", G::solver, "s"},
  };
}

}  // namespace

namespace {

/// The elastic rod and load cell of --rod-model elastic, or nothing for the rigid model (whose
/// options for the elastic one are then errors: they would be silently ignored).
std::optional<ElasticRodSetup> resolve_elastic_rod(const RunOptions& o, const PaperParameters& paper) {
  if (o.rod_model == "rigid") {
    const std::pair<const char*, bool> elastic_only[] = {
        {"--rod-elements", o.rod_elements.has_value()},           {"--rod-damping-ratio", o.rod_damping_ratio.has_value()},
        {"--cell-stiffness", o.cell_stiffness_N_per_m.has_value()}, {"--cell-damping-ratio", o.cell_damping_ratio.has_value()},
        {"--hemisphere-mass", o.hemisphere_mass_kg.has_value()},   {"--accelerometer", o.accelerometer.has_value()}};
    for (const auto& [name, given] : elastic_only)
      if (given)
        throw InvalidParameter("--rod-model", o.rod_model,
                               fmt::format("elastic when {} is given (it describes the elastic rod and load cell)", name));
    return std::nullopt;
  }
  if (o.rod_model != "elastic") throw InvalidParameter("--rod-model", o.rod_model, "one of: rigid, elastic");
  const RodData& rod = paper.rod(o.rod);
  ElasticRodSetup e{.length_m = rod.length_m,
                    .diameter_m = rod.diameter_m,
                    .elements = ElasticRodSetup::default_elements,
                    .rod_damping_ratio = o.rod_damping_ratio.value_or(paper.rig.rod_damping_ratio),
                    .hemisphere_mass_kg = o.hemisphere_mass_kg.value_or(paper.ball.mass_kg),
                    .cell_stiffness_N_per_m = o.cell_stiffness_N_per_m.value_or(paper.rig.cell_stiffness_N_per_m),
                    .cell_damping_ratio = o.cell_damping_ratio.value_or(paper.rig.cell_damping_ratio)};
  if (o.rod_elements) {
    const double n = *o.rod_elements;
    if (!(n >= 1 && n <= ElasticRodSetup::max_elements && n == std::floor(n)))
      throw InvalidParameter("--rod-elements", format_value(n),
                             fmt::format("an integer in [1, {}]", ElasticRodSetup::max_elements));
    e.elements = static_cast<int>(n);
  }
  const std::string face = o.accelerometer.value_or("top");
  if (face == "top") e.accelerometer = Accelerometer::top;
  else if (face == "bottom") e.accelerometer = Accelerometer::bottom;
  else throw InvalidParameter("--accelerometer", face, "one of: top, bottom");
  return e;
}

}  // namespace

const std::vector<RunOption>& run_options() {
  static const std::vector<RunOption> options = make_run_options();
  return options;
}

std::vector<std::string> split_option_list(const std::string& list) {
  std::vector<std::string> items;
  std::size_t begin = 0;
  while (begin <= list.size()) {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    items.push_back(list.substr(begin, end - begin));
    begin = end + 1;
  }
  return items;
}

std::string column_name(const RunOption& option) {
  return python_keyword(option.name) + (option.unit.empty() ? "" : "_" + option.unit);
}

std::string python_keyword(std::string_view option_name) {
  std::string k(option_name);
  std::replace(k.begin(), k.end(), '-', '_');
  return k;
}

const RunOption* find_run_option(std::string_view name) {
  for (const RunOption& o : run_options())
    if (o.name == name || python_keyword(o.name) == name) return &o;
  return nullptr;
}

DropTestSetup resolve_setup(const RunOptions& o, const PaperParameters& paper) {
  DropTestSetup s = paper_setup(paper, o.rod, o.height_m.value_or(default_height_m));
  if (o.impact_velocity_mps) s.impact_velocity_mps = *o.impact_velocity_mps;
  if (o.mass_kg) s.mass_kg = *o.mass_kg;
  if (o.restitution) s.restitution = *o.restitution;
  if (o.ball_E_Pa) s.ball.E_Pa = *o.ball_E_Pa;
  if (o.ball_nu) s.ball.nu = *o.ball_nu;
  if (o.ball_radius_m) s.ball_radius_m = *o.ball_radius_m;
  if (o.ball_yield_stress_Pa) s.ball_yield_stress_Pa = *o.ball_yield_stress_Pa;
  if (o.rod_E_Pa) s.rod.E_Pa = *o.rod_E_Pa;
  if (o.rod_nu) s.rod.nu = *o.rod_nu;
  if (o.gravity_mps2) s.gravity_mps2 = *o.gravity_mps2;
  s.no_tension = o.no_tension;
  if (o.zeta == "paper") s.damping.zeta_form = ZetaForm::paper;
  else if (o.zeta == "exact") s.damping.zeta_form = ZetaForm::exact;
  else throw InvalidParameter("--zeta", o.zeta, "one of: paper, exact");
  s.damping.omega_n = parse_omega_n_variant(o.omega_n.value_or(to_string(OmegaNVariant::paper)));
  s.damping.viscous_time_constant_s = o.viscous_time_constant_s;
  if (o.reference_velocity_mps) {
    require_positive("--reference-velocity", *o.reference_velocity_mps, "m/s");
    s.damping.reference_velocity_mps = *o.reference_velocity_mps;
  }
  s.elastic_rod = resolve_elastic_rod(o, paper);
  validate(s, {.height = o.height_m.has_value(),
               .gravity = o.gravity_mps2.has_value(),
               .mass = o.mass_kg.has_value(),
               .ball_radius = o.ball_radius_m.has_value(),
               .ball_E = o.ball_E_Pa.has_value(),
               .rod_E = o.rod_E_Pa.has_value(),
               .ball_nu = o.ball_nu.has_value(),
               .rod_nu = o.rod_nu.has_value()});
  bool time_constant_law = false;  // rejects an unknown law before any work
  with_damping_law(o.damping, [&]<class Law>(std::type_identity<Law>) { time_constant_law = MaterialTimeConstantLaw<Law>; });
  for (const auto& [name, value] : {std::pair{"--viscous-time-constant", o.viscous_time_constant_s},
                                    std::pair{"--reference-velocity", o.reference_velocity_mps}})
    if (value && !time_constant_law)
      throw InvalidParameter(name, format_value(*value),
                             "given only with a viscoelastic law (kuwabara-kono), whose damping is a material time "
                             "constant; --damping is " + o.damping);
  if (o.viscous_time_constant_s && o.reference_velocity_mps)
    throw InvalidParameter("--reference-velocity", format_value(*o.reference_velocity_mps),
                           "omitted when --viscous-time-constant is given (the reference speed only calibrates A)");
  if (o.omega_n && o.damping != HongoPaper::info.name)
    throw InvalidParameter("--omega-n", *o.omega_n,
                           "given only with --damping " + std::string(HongoPaper::info.name) +
                               " (the omega_n assumption belongs to the paper's law; --damping is " + o.damping + ")");
  return s;
}

SolverSettings resolve_solver(const RunOptions& o) {
  SolverSettings s;
  s.integrator = parse_integrator(o.integrator);
  s.dt_s = o.dt_s.value_or(s.dt_s);
  s.locate_events = !o.no_event_location;
  s.rtol = o.rtol.value_or(s.rtol);
  s.atol = o.atol.value_or(s.atol);
  s.max_step_s = o.max_step_s.value_or(s.max_step_s);
  if (const std::string method = o.cvode_method.value_or("adams"); method == "adams") s.cvode_method = CvodeMethod::adams;
  else if (method == "bdf") s.cvode_method = CvodeMethod::bdf;
  else throw InvalidParameter("--cvode-method", method, "one of: adams, bdf");
  validate(s);
  // A setting the chosen integrator does not read is an error: it would be silently ignored.
  const IntegratorTraits& row = integrator_traits(s.integrator);
  auto text = [](const std::optional<double>& v) { return v ? format_value(*v) : std::string(); };
  const struct {
    const char* option;
    bool given;
    std::string value;
    bool (*reads)(const IntegratorTraits&);
  } given[] = {
      {"--dt", o.dt_s.has_value(), text(o.dt_s), reads_step},
      {"--no-event-location", o.no_event_location, "true", reads_step},
      {"--rtol", o.rtol.has_value(), text(o.rtol), reads_tolerances},
      {"--atol", o.atol.has_value(), text(o.atol), reads_tolerances},
      {"--cvode-method", o.cvode_method.has_value(), o.cvode_method.value_or(""), reads_cvode_method},
      {"--max-step", o.max_step_s.has_value(), text(o.max_step_s), reads_max_step},
  };
  for (const auto& g : given)
    if (g.given && !g.reads(row))
      throw InvalidParameter(g.option, g.value,
                             fmt::format("given only with --integrator {} (the integrators that read it); "
                                         "--integrator is {}",
                                         integrator_names(g.reads), row.name));
  return s;
}

}  // namespace hertzdash
