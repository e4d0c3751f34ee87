// `hertzdash export` and `hertzdash conformance` (simulation/reports/export_report.hpp).
#include "hertzdash/simulation/reports/export_report.hpp"

#include "hertzdash/model/damping/registry.hpp"
#include "hertzdash/simulation/options/command_options.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/reports/report_json.hpp"

#include <fmt/format.h>

namespace hertzdash {

namespace {

constexpr auto pair = EngineImpactKind::sphere_sphere;
constexpr auto wall = EngineImpactKind::sphere_wall;

/// The law's material constant as a column, spelled as the run's recorded inputs spell it
/// ("viscous_time_constant_s").
std::string material_constant_column(const std::string& law) {
  return column_name(*find_run_option(registered_law(law).material_constant()->key));
}

Parameters deck_parameters(const EngineExport& e) {
  const EngineContact& c = e.contact;
  auto g = [](double x) { return fmt::format("{:.10g}", x); };
  Parameters p{{"engine", to_string(e.model->engine)},
               {"engine_model", std::string(e.model->key)},
               {"hertzdash_law", c.law},
               {"relation", std::string(e.model->relation)},
               {"sphere_radius_m", g(c.radius_m)},
               {"sphere_mass_kg", g(c.mass_kg)},
               {"sphere_density_kg_per_m3", g(c.density_kg_per_m3())},
               {"sphere_E_Pa", g(c.sphere.E_Pa)},
               {"sphere_nu", g(c.sphere.nu)},
               {"wall_E_Pa", g(c.wall.E_Pa)},
               {"wall_nu", g(c.wall.nu)},
               {"restitution", g(c.restitution)}};
  if (c.material_constant > 0) {
    p.emplace_back(material_constant_column(c.law), g(c.material_constant));
    p.emplace_back("calibration_speed_mps", g(c.calibration_speed_mps));
  }
  p.emplace_back("speed_mps", g(c.speed_mps));
  p.emplace_back("steps_per_contact", std::to_string(e.steps_per_contact));
  for (EngineImpactKind k : {pair, wall}) {
    const std::string n = k == pair ? "sphere_sphere" : "sphere_wall";
    p.emplace_back(n + "_restitution", g(c.predicted(k).restitution));
    p.emplace_back(n + "_contact_time_s", g(c.predicted(k).contact_time_s));
    p.emplace_back(n + "_peak_force_N", g(c.predicted(k).peak_force_N));
  }
  return p;
}

/// The run options an engine deck reads: the bodies, the approach speed and the law with its own
/// inputs (resolve_setup has checked those against the law). Every other one given is refused by
/// name (refuse_options_not_read): the engines' contacts allow tension and fly nothing, the elastic
/// rod is the paper's own, and hertzdash's prediction runs its own accurate solver, not the
/// solver options.
void refuse_options_engines_do_not_read(const RunOptions& o) {
  std::vector<std::string_view> read{"rod",   "height", "impact-velocity", "mass",  "density", "restitution", "ball-E",
                                     "ball-nu", "ball-radius", "rod-E",    "rod-nu", "gravity", "damping"};
  for (const RunOption& option : run_options())
    if (!option.readers.laws.empty()) read.push_back(option.name);
  refuse_options_not_read(o, RunOptions{}, read,
                          "a run of hertzdash's own contact (simulate, restitution): the engines' decks take the bodies, "
                          "the approach speed and the law (docs/engines.md)");
}

}  // namespace

int steps_per_contact_option(std::string_view command, std::optional<double> given) {
  const ParameterDecl& d = command_option(command, "steps-per-contact");
  const double steps = given.value_or(d.default_number);
  if (!d.range.contains(steps)) throw InvalidParameter("steps-per-contact", format_value(steps), d.range.text(d.unit));
  return static_cast<int>(steps);
}

std::array<std::string, 3> engine_deck_files(Engine engine) {
  const std::string_view extension = engine_program(engine).deck_extension;
  return {fmt::format("sphere_sphere{}", extension), fmt::format("sphere_wall{}", extension),
          fmt::format("contact_lines{}", extension)};
}

std::vector<std::pair<std::string, std::string>> EngineExport::files() const {
  const auto names = engine_deck_files(model->engine);
  return {{names[0], pair_deck.text}, {names[1], wall_deck.text}, {names[2], contact_lines}};
}

EngineExport export_engine_decks(const RunOptions& options, const PaperParameters& paper, Engine engine,
                                 const std::string& model_key, int steps_per_contact) {
  EngineExport e;
  const DropTestSetup setup = resolve_setup(options, paper);  // the inputs' own checks first
  refuse_options_engines_do_not_read(options);
  e.model = &engine_model(engine, model_key, options.damping);
  e.contact = make_engine_contact(setup, options.damping, e.model->tension_clamped);
  e.steps_per_contact = steps_per_contact;
  const Parameters p = deck_parameters(e);
  const std::string engine_name = to_string(engine);
  e.pair_deck = engine_deck(*e.model, e.contact, pair, steps_per_contact,
                            provenance_header(engine_name + " input deck: two spheres head-on (hertzdash export)", p));
  e.wall_deck = engine_deck(*e.model, e.contact, wall, steps_per_contact,
                            provenance_header(engine_name + " input deck: a sphere on a wall at z = 0 (hertzdash export)", p));
  e.contact_lines = provenance_header(engine_name + " contact lines for an input of your own (hertzdash export)", p) +
                    engine_contact_lines(*e.model, e.contact);
  return e;
}

std::string export_text(const EngineExport& e) {
  const EngineContact& c = e.contact;
  std::string s = fmt::format("hertzdash export: {} model {} ({})\n", to_string(e.model->engine), e.model->key, e.model->syntax);
  s += fmt::format("  equals       hertzdash law '{}': {}\n", c.law, e.model->relation);
  s += fmt::format("  spheres      R = {:.6g} m, m = {:.6g} kg (rho = {:.6g} kg/m^3), E = {:.6g} Pa, nu = {:.6g}\n", c.radius_m,
                   c.mass_kg, c.density_kg_per_m3(), c.sphere.E_Pa, c.sphere.nu);
  s += fmt::format("  wall         E = {:.6g} Pa, nu = {:.6g}\n", c.wall.E_Pa, c.wall.nu);
  s += fmt::format("  law          e = {:.6g}", c.restitution);
  if (c.material_constant > 0)
    s += fmt::format(", {} = {:.6g} (calibrated on the spheres at {:.6g} m/s)", material_constant_column(c.law),
                     c.material_constant, c.calibration_speed_mps);
  s += "\n";
  s += fmt::format("  {:<14} {:>12} {:>14} {:>14} {:>14}\n", "impact", "speed_mps", "restitution", "contact_time_s",
                   "peak_force_N");
  for (EngineImpactKind k : {pair, wall}) {
    const EngineImpactResult& r = c.predicted(k);
    s += fmt::format("  {:<14} {:>12.6g} {:>14.9f} {:>14.6e} {:>14.6g}\n", to_string(k), c.speed_mps, r.restitution,
                     r.contact_time_s, r.peak_force_N);
  }
  s += fmt::format("  timestep_s   {:.6g} (sphere-sphere), {:.6g} (sphere-wall): {} steps per contact\n", e.pair_deck.timestep_s,
                   e.wall_deck.timestep_s, e.steps_per_contact);
  return s;
}

nlohmann::ordered_json to_json(const EngineExport& e) {
  const EngineContact& c = e.contact;
  nlohmann::ordered_json j;
  j["engine"] = to_string(e.model->engine);
  j["engine_model"] = e.model->key;
  j["hertzdash_law"] = c.law;
  j["relation"] = e.model->relation;
  j["restitution"] = c.restitution;
  if (c.material_constant > 0) {
    j[material_constant_column(c.law)] = c.material_constant;
    j["calibration_speed_mps"] = c.calibration_speed_mps;
  }
  j["speed_mps"] = c.speed_mps;
  j["sphere_density_kg_per_m3"] = c.density_kg_per_m3();
  j["steps_per_contact"] = e.steps_per_contact;
  for (EngineImpactKind k : {pair, wall}) {
    const EngineImpactResult& r = c.predicted(k);
    const EngineDeck& d = k == pair ? e.pair_deck : e.wall_deck;
    j["impacts"].push_back({{"impact", to_string(k)},
                            {"deck", engine_deck_files(e.model->engine)[k == pair ? 0 : 1]},
                            {"restitution", r.restitution},
                            {"contact_time_s", r.contact_time_s},
                            {"peak_force_N", r.peak_force_N},
                            {"timestep_s", d.timestep_s},
                            {"steps", d.steps}});
  }
  j["git_revision"] = git_revision();
  return j;
}

EngineConformance run_engine_conformance(const RunOptions& options, const PaperParameters& paper, Engine engine,
                                         int steps_per_contact) {
  const DropTestSetup setup = resolve_setup(options, paper);  // the inputs' own checks first
  refuse_options_engines_do_not_read(options);
  if (options.damping != default_damping_law)
    throw InvalidParameter("damping", options.damping,
                           "omitted: conformance runs every model of the engine with the law it equals");
  if (options.reference_velocity_mps)
    throw InvalidParameter("reference-velocity", format_value(*options.reference_velocity_mps),
                           "omitted: conformance calibrates each law at the approach speed (`impact-velocity`)");
  return {engine, approach_speed(setup), steps_per_contact, engine_conformance(engine, setup, steps_per_contact)};
}

std::string conformance_text(const EngineConformance& c) {
  std::string s = fmt::format(
      "hertzdash conformance: {}, each model against the law it equals, calibrated at {:.6g} m/s; {} and {} steps per "
      "contact\n",
      to_string(c.engine), c.reference_speed_mps, c.steps_per_contact, c.steps_per_contact / 2);
  s += fmt::format("  {:<22} {:<14} {:<13} {:>9} {:>8} {:>12} {:>12} {:>10} {:>6} {:>12}  {}\n", "engine_model",
                   "hertzdash_law", "impact", "speed_mps", "e_asked", "e_hertzdash", "e_engine", "|de|", "order", "e_typed_in",
                   "engine input");
  for (const ConformanceRow& r : c.rows)
    s += fmt::format("  {:<22} {:<14} {:<13} {:>9.4g} {:>8.4g} {:>12.9f} {:>12.9f} {:>10.3e} {:>6.3f} {:>12}  {} = {:.6g}\n",
                     r.engine_model, r.hertzdash_law, to_string(r.impact), r.speed_mps, r.e_asked, r.hertzdash.restitution,
                     r.engine.restitution, std::abs(r.engine.restitution - r.hertzdash.restitution), r.observed_order,
                     std::isnan(r.e_engine_given_e_asked) ? std::string("-") : fmt::format("{:.6f}", r.e_engine_given_e_asked),
                     r.engine_input.name, r.engine_input.value);
  s += "  e_typed_in: the engine's e with e_asked typed in as its damping input (where that input is a restitution)\n";
  return s;
}

nlohmann::ordered_json to_json(const EngineConformance& c) {
  nlohmann::ordered_json j;
  j["engine"] = to_string(c.engine);
  j["reference_speed_mps"] = c.reference_speed_mps;
  j["steps_per_contact"] = c.steps_per_contact;
  j["rows"] = nlohmann::ordered_json::array();
  for (const ConformanceRow& r : c.rows)
    j["rows"].push_back({{"engine_model", r.engine_model},
                         {"hertzdash_law", r.hertzdash_law},
                         {"impact", to_string(r.impact)},
                         {"speed_mps", r.speed_mps},
                         {"e_asked", r.e_asked},
                         {"e_hertzdash", r.hertzdash.restitution},
                         {"e_engine", r.engine.restitution},
                         {"e_engine_half_steps", r.e_engine_half_steps},
                         {"observed_order", r.observed_order},
                         {"e_engine_given_e_asked", report_detail::number_or_null(r.e_engine_given_e_asked)},
                         {"e_hertzdash_given_e_asked", report_detail::number_or_null(r.e_hertzdash_given_e_asked)},
                         {"engine_input", {{"name", r.engine_input.name}, {"value", r.engine_input.value}}},
                         {"contact_time_s", r.hertzdash.contact_time_s},
                         {"contact_time_engine_s", r.engine.contact_time_s},
                         {"peak_force_N", r.hertzdash.peak_force_N},
                         {"peak_force_engine_N", r.engine.peak_force_N},
                         {"timestep_s", r.timestep_s}});
  j["git_revision"] = git_revision();
  return j;
}

}  // namespace hertzdash
