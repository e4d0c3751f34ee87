#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/options/declared_choice.hpp"
#include "hertzdash/simulation/options/hertz_scale_refusal.hpp"

#include "hertzdash/model/air_drag.hpp"
#include "hertzdash/model/drop_test_parameters.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/omega_n_variant.hpp"
#include "hertzdash/model/two_spheres.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/run/result_checks.hpp"
#include "hertzdash/simulation/run/step_resolution.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
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
bool reads_cvode_method(const IntegratorTraits& r) { return r.method == IntegratorMethod::cvode; }

using R = RunOptions;
using G = RunOption::Group;
using Setup = const DropTestSetup&;
using V = std::optional<double>;

}  // namespace

std::string help_text(const ParameterDecl& d, KeySpelling spelling) {
  std::string h = spell_key_references(d.help, spelling);
  if (d.type == ParameterType::text && !d.choices.empty()) h += " (one of: " + std::string(d.choices) + ")";
  if (d.type == ParameterType::number) h += "; " + d.range.text(d.unit);
  if (d.type != ParameterType::flag)
    h += fmt::format(" (default: {}{})", d.default_value,
                     d.default_source.empty() ? "" : "; " + spell_key_references(d.default_source, spelling));
  return h;
}

namespace {

using Solver = const SolverSettings&;
using Text = std::optional<std::string>;
using ValueInRun = std::function<Text(Setup, Solver)>;

std::string number_text(double v) { return fmt::format("{}", v); }
std::string flag_text(bool on) { return on ? "true" : "false"; }

/// An option of declaration `d`. Its value in a run is `value_in_run`, or else its value in the
/// set-up (`value_in_setup`, kept as the fit's starting value when `d` is fittable).
RunOption option(const ParameterDecl& d, RunOption::Field field, G group, OptionReaders readers = {},
                 std::function<V(Setup)> value_in_setup = {}, ValueInRun value_in_run = {}) {
  if (!value_in_run && value_in_setup)
    value_in_run = [value_in_setup](Setup s, Solver) -> Text {
      const V v = value_in_setup(s);
      return v ? Text(number_text(*v)) : Text();
    };
  if (!d.fittable) value_in_setup = nullptr;
  return {d,
          std::string(d.key),
          std::move(field),
          help_text(d, KeySpelling::command_line),
          group,
          std::string(d.column_unit),
          std::move(readers),
          std::move(value_in_setup),
          std::move(value_in_run)};
}
/// An option whose value in a run is `value_in_run` alone (no fit starts from it).
RunOption described(const ParameterDecl& d, RunOption::Field field, G group, OptionReaders readers,
                    ValueInRun value_in_run) {
  return option(d, std::move(field), group, std::move(readers), {}, std::move(value_in_run));
}

// Declarations of the options that choose what runs (the rod preset, the law, the rig, the
// integrator) and of the solver settings, whose valid values come from the registries.
const std::string& law_choices() {
  static const std::string names = registered_law_names();
  return names;
}
const std::string& integrator_choices() {
  static const std::string names = integrator_names();
  return names;
}
const ParameterDecl rod_decl{.key = "rod", .type = ParameterType::text,
                             .choices = "steel, duralumin-a, duralumin-b, duralumin-c", .default_value = "steel",
                             .default_source = "the paper's Table 1",
                             .help = "Preset of the falling body, flat and restitution: a rod of Tables 1-3"};
const ParameterDecl rod_model_decl{
    .key = "rod-model", .type = ParameterType::text, .choices = "rigid, elastic", .default_value = "rigid",
    .default_source = "the paper's model",
    .help = "rigid (the paper's model: a rigid rod on a fixed hemisphere) or elastic (the rod as an elastic bar, the "
            "hemisphere on its load cell; docs/elastic-rod.md)"};
const ParameterDecl cvode_method_decl{.key = "cvode-method", .type = ParameterType::text, .choices = "adams, bdf",
                                      .default_value = "adams", .default_source = "non-stiff contact",
                                      .help = "CVODE's linear multistep method"};

// The laws that read the input e: all but those that conserve the energy they store (the
// undamped law, whose restitution is 1 whatever e is).
std::vector<std::string> dissipative_law_names() {
  std::vector<std::string> names;
  for (const RegisteredLaw& law : registered_law_table())
    if (!law.conservative) names.emplace_back(law.info.name);
  return names;
}

// Every law's own inputs, bound to the fields the simulator reads or to law_numbers.
void add_law_options(std::vector<RunOption>& out) {
  std::vector<std::pair<ParameterDecl, std::vector<std::string>>> declared;  // each key once, with its laws
  for (const RegisteredLaw& law : registered_law_table())
    for (const ParameterDecl& d : law.parameters) {
      auto it = std::find_if(declared.begin(), declared.end(), [&](const auto& e) { return e.first.key == d.key; });
      if (it == declared.end()) declared.push_back({d, {}}), it = declared.end() - 1;
      it->second.emplace_back(law.info.name);
    }
  for (auto& entry : declared) {  // no structured binding: clang 14 (make fuzz) cannot capture one
    const ParameterDecl d = entry.first;
    OptionReaders readers{.laws = std::move(entry.second)};
    if (d.key == "zeta")
      out.push_back(described(d, &R::zeta, G::setup, readers,
                              [](Setup s, Solver) -> Text { return to_string(s.damping.zeta_form); }));
    else if (d.key == "omega-n")
      out.push_back(described(d, &R::omega_n, G::setup, readers,
                              [](Setup s, Solver) -> Text { return to_string(s.damping.omega_n); }));
    else if (d.key == "viscous-time-constant")
      out.push_back(option(d, &R::viscous_time_constant_s, G::setup, readers,
                           [](Setup s) { return s.damping.viscous_time_constant_s; }));
    else if (d.key == "reference-velocity")
      out.push_back(described(d, &R::reference_velocity_mps, G::setup, readers, [](Setup s, Solver) -> Text {
        const double v = s.damping.reference_velocity_mps;  // 0: the approach speed
        return v > 0 ? Text(number_text(v)) : Text();
      }));
    else
      out.push_back(option(d, LawNumber{}, G::setup, readers,
                           [d](Setup s) -> V {  // a computed default (NaN) is no starting value
                             const double v = s.damping.number(d);
                             return std::isnan(v) ? V() : V(v);
                           }));
  }
}

std::vector<RunOption> make_run_options() {
  namespace p = drop_test_parameters;
  namespace e = elastic_rod_parameters;
  const OptionReaders elastic{.elastic_rod = true};
  auto elastic_value = [](double ElasticRodSetup::*f) {
    return [f](Setup s) -> V { return s.elastic_rod ? V((*s.elastic_rod).*f) : V(); };
  };
  std::vector<RunOption> o{
      described(rod_decl, &R::rod, G::setup, {}, [](Setup s, Solver) -> Text {
        return s.rod_preset.empty() ? Text() : Text(s.rod_preset);
      }),
      option(p::height, &R::height_m, G::setup, {}, [](Setup s) -> V { return s.height_m; },
             [](Setup s, Solver) -> Text { return s.impact_velocity_mps ? Text() : Text(number_text(s.height_m)); }),
      option(p::impact_velocity, &R::impact_velocity_mps, G::setup, {}, [](Setup s) -> V { return approach_speed(s); }),
      option(p::mass, &R::mass_kg, G::setup, {}, [](Setup s) -> V { return s.mass_kg; }),
      described(p::density, &R::density_kg_per_m3, G::setup, {}, [](Setup, Solver) -> Text { return Text(); }),
      option(p::restitution, &R::restitution, G::setup, {.laws = dissipative_law_names()},
             [](Setup s) -> V { return s.restitution; }),
      option(p::ball_E, &R::ball_E_Pa, G::setup, {}, [](Setup s) -> V { return s.ball.E_Pa; }),
      option(p::ball_nu, &R::ball_nu, G::setup, {}, [](Setup s) -> V { return s.ball.nu; }),
      option(p::ball_radius, &R::ball_radius_m, G::setup, {}, [](Setup s) -> V { return s.ball_radius_m; }),
      described(p::ball_yield_stress, &R::ball_yield_stress_Pa, G::setup, {},
                [](Setup s, Solver) -> Text { return number_text(s.ball_yield_stress_Pa); }),
      option(p::rod_E, &R::rod_E_Pa, G::setup, {}, [](Setup s) -> V { return s.rod.E_Pa; }),
      option(p::rod_nu, &R::rod_nu, G::setup, {}, [](Setup s) -> V { return s.rod.nu; }),
      option(p::gravity, &R::gravity_mps2, G::setup, {}, [](Setup s) -> V { return s.gravity_mps2; }),
      described(p::no_tension, &R::no_tension, G::setup, {},
                [](Setup s, Solver) -> Text { return flag_text(s.no_tension); }),
      // Air drag: described only where it acts (a run without air says nothing of it).
      described(air_drag_parameters::air_density, &R::air_density_kg_per_m3, G::setup, {.flights_only = true},
                [](Setup s, Solver) -> Text {
                  return s.air_drag.active() ? Text(number_text(s.air_drag.air_density_kg_per_m3)) : Text();
                }),
      described(air_drag_parameters::drag_coefficient, &R::drag_coefficient, G::setup, {.flights_only = true},
                [](Setup s, Solver) -> Text {
                  return s.air_drag.active() ? Text(number_text(s.air_drag.drag_coefficient)) : Text();
                }),
  };
  add_law_options(o);
  o.push_back(option({.key = "damping", .type = ParameterType::text, .choices = law_choices(),
                      .default_value = default_damping_law, .default_source = "the paper's law",
                      .help = "Damping law (see `hertzdash models`)"},
                     &R::damping, G::setup));
  o.push_back(described(rod_model_decl, &R::rod_model, G::setup, {},
                        [](Setup s, Solver) -> Text { return s.elastic_rod ? "elastic" : "rigid"; }));
  o.push_back(described(e::elements, &R::rod_elements, G::setup, elastic, [](Setup s, Solver) -> Text {
    return s.elastic_rod ? Text(number_text(s.elastic_rod->elements)) : Text();
  }));
  o.push_back(option(e::rod_damping_ratio, &R::rod_damping_ratio, G::setup, elastic,
                     elastic_value(&ElasticRodSetup::rod_damping_ratio)));
  o.push_back(option(e::cell_stiffness, &R::cell_stiffness_N_per_m, G::setup, elastic,
                     elastic_value(&ElasticRodSetup::cell_stiffness_N_per_m)));
  o.push_back(option(e::cell_damping_ratio, &R::cell_damping_ratio, G::setup, elastic,
                     elastic_value(&ElasticRodSetup::cell_damping_ratio)));
  o.push_back(option(e::hemisphere_mass, &R::hemisphere_mass_kg, G::setup, elastic,
                     elastic_value(&ElasticRodSetup::hemisphere_mass_kg)));
  o.push_back(described(e::accelerometer, &R::accelerometer, G::setup, {.elastic_rod = true, .trace_only = true},
                        [](Setup s, Solver) -> Text {
                          return s.elastic_rod ? Text(to_string(s.elastic_rod->accelerometer)) : Text();
                        }));

  // The solver: which integrators read a setting is the integrator table's.
  static const std::string dt_help = fmt::format(
      "Fixed step [s], at most t_H / {}, t_H the impact's undamped Hertz contact time (a run needing more than 1e9 "
      "steps does not start)",
      min_steps_per_hertz_contact);
  static const std::string rtol_help =
      fmt::format("Relative tolerance (above {:g} the result carries a loose_tolerance warning)", loose_rtol_limit);
  o.push_back(option({.key = "integrator", .type = ParameterType::text, .choices = integrator_choices(),
                      .default_value = "cvode", .default_source = "SUNDIALS CVODE, adaptive",
                      .help = "Integrator (docs/simulate.md)"},
                     &R::integrator, G::solver, {}, {},
                     [](Setup, Solver solver) -> Text { return std::string(to_string(solver.integrator)); }));
  o.push_back(option({.key = "dt", .unit = "s", .column_unit = "s", .range = NumberRange::positive(),
                      .default_value = "1e-6", .default_source = "SolverSettings", .help = dt_help},
                     &R::dt_s, G::solver, {.integrators = reads_step}, {},
                     [](Setup, Solver solver) -> Text { return number_text(solver.dt_s); }));
  o.push_back(option({.key = "no-event-location", .type = ParameterType::flag, .default_value = "off",
                      .help = "Handle events at the end of the step that crosses them (convergence studies)"},
                     &R::no_event_location, G::solver, {.integrators = reads_step}, {},
                     [](Setup, Solver solver) -> Text { return flag_text(!solver.locate_events); }));
  o.push_back(option({.key = "rtol", .range = NumberRange::open(0, 1), .default_value = "1e-8",
                      .default_source = "SolverSettings", .help = rtol_help},
                     &R::rtol, G::solver, {.integrators = reads_tolerances}, {},
                     [](Setup, Solver solver) -> Text { return number_text(solver.rtol); }));
  o.push_back(option({.key = "atol", .range = NumberRange::open(0, 1), .default_value = "1e-12",
                      .default_source = "SolverSettings",
                      .help = "Absolute tolerance relative to the impact's scales: X for lengths, v0 for speeds, t_H "
                              "for times (X, t_H the undamped Hertz maximum compression and contact time at the "
                              "impact speed v0)"},
                     &R::atol, G::solver, {.integrators = reads_tolerances}, {},
                     [](Setup, Solver solver) -> Text { return number_text(solver.atol); }));
  o.push_back(described(cvode_method_decl, &R::cvode_method, G::solver, {.integrators = reads_cvode_method},
                        [](Setup, Solver solver) -> Text { return std::string(to_string(solver.cvode_method)); }));
  o.push_back(option({.key = "max-step", .unit = "s", .column_unit = "s", .range = NumberRange::non_negative(),
                      .default_value = "0", .default_source = "no limit", .help = "Largest step [s]; 0 = no limit"},
                     &R::max_step_s, G::solver, {.integrators = reads_max_step}, {},
                     [](Setup, Solver solver) -> Text { return number_text(solver.max_step_s); }));
  return o;
}

/// The elastic rod and load cell of --rod-model elastic, or nothing for the rigid model.
std::optional<ElasticRodSetup> resolve_elastic_rod(const RunOptions& o, const PaperParameters& paper) {
  if (o.rod_model == "rigid") return std::nullopt;
  if (o.rod_model != "elastic") throw InvalidParameter("rod-model", o.rod_model, "one of: rigid, elastic");
  const RodData& rod = paper.rod(o.rod);
  ElasticRodSetup e{.length_m = rod.length_m,
                    .diameter_m = rod.diameter_m,
                    .elements = ElasticRodSetup::default_elements,
                    .rod_damping_ratio = o.rod_damping_ratio.value_or(paper.rig.rod_damping_ratio),
                    .hemisphere_mass_kg = o.hemisphere_mass_kg.value_or(paper.ball.mass_kg),
                    .cell_stiffness_N_per_m = o.cell_stiffness_N_per_m.value_or(paper.rig.cell_stiffness_N_per_m),
                    .cell_damping_ratio = o.cell_damping_ratio.value_or(paper.rig.cell_damping_ratio)};
  if (o.rod_elements) e.elements = static_cast<int>(*o.rod_elements);  // an integer: check_given_options
  const std::string face = o.accelerometer.value_or("top");
  if (face == "top") e.accelerometer = Accelerometer::top;
  else if (face == "bottom") e.accelerometer = Accelerometer::bottom;
  else throw InvalidParameter("accelerometer", face, "one of: top, bottom");
  return e;
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const std::string& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

}  // namespace

bool OptionReaders::read_by(std::string_view law, bool elastic_rod_run, const IntegratorTraits& integrator,
                            bool follows_flights) const {
  if (!law.empty() && !laws.empty() && std::find(laws.begin(), laws.end(), law) == laws.end()) return false;
  if (elastic_rod && !elastic_rod_run) return false;
  if (flights_only && (!follows_flights || elastic_rod_run)) return false;
  return !integrators || integrators(integrator);
}

std::string OptionReaders::describe() const {
  if (!laws.empty()) return key_reference("damping") + " " + join(laws);
  if (elastic_rod) return key_reference("rod-model") + " elastic";
  if (flights_only)
    return "the flights of the rigid rod's bounce sequence (hertzdash bounce, hertzdash fit --bounce-times)";
  if (integrators) return key_reference("integrator") + " " + integrator_names(integrators);
  return {};
}

const std::vector<RunOption>& run_options() {
  static const std::vector<RunOption> options = make_run_options();
  return options;
}

std::vector<const RunOption*> fittable_options() {
  std::vector<const RunOption*> out;
  for (const RunOption& o : run_options())
    if (o.decl.fittable) out.push_back(&o);
  return out;
}

void set_number(RunOptions& options, const RunOption& o, double value) {
  if (std::holds_alternative<LawNumber>(o.field)) {
    options.law_numbers[o.name] = value;
    return;
  }
  if (const auto* f = std::get_if<std::optional<double> RunOptions::*>(&o.field)) {
    options.**f = value;
    return;
  }
  throw std::logic_error("option " + o.name + " is not a number");
}

void set_text(RunOptions& options, const RunOption& o, const std::string& value) {
  if (const auto* f = std::get_if<std::string RunOptions::*>(&o.field)) options.**f = value;
  else if (const auto* g = std::get_if<std::optional<std::string> RunOptions::*>(&o.field)) options.**g = value;
  else throw std::logic_error("option " + o.name + " is not a text");
}

void set_flag(RunOptions& options, const RunOption& o, bool value) {
  if (const auto* f = std::get_if<bool RunOptions::*>(&o.field)) options.**f = value;
  else throw std::logic_error("option " + o.name + " is not a flag");
}

void clear_option(RunOptions& options, const RunOption& o) {
  static const RunOptions defaults;
  std::visit(
      [&]<class F>(const F& f) {
        if constexpr (std::is_same_v<F, LawNumber>) options.law_numbers.erase(o.name);
        else options.*f = defaults.*f;
      },
      o.field);
}

bool is_given(const RunOptions& options, const RunOption& o) {
  static const RunOptions defaults;
  return std::visit(
      [&]<class F>(const F& f) -> bool {
        if constexpr (std::is_same_v<F, LawNumber>) return options.law_numbers.contains(o.name);
        else return options.*f != defaults.*f;
      },
      o.field);
}

std::string given_text(const RunOptions& options, const RunOption& o) {
  return std::visit(
      [&]<class F>(const F& f) -> std::string {
        if constexpr (std::is_same_v<F, LawNumber>) {
          const auto it = options.law_numbers.find(o.name);
          return it == options.law_numbers.end() ? "" : format_value(it->second);
        } else {
          const auto& v = options.*f;
          using T = std::remove_cvref_t<decltype(v)>;
          if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
          else if constexpr (std::is_same_v<T, std::string>) return v;
          else if constexpr (std::is_same_v<T, std::optional<std::string>>) return v.value_or("");
          else return v ? format_value(*v) : "";
        }
      },
      o.field);
}

bool is_declared_choice(const ParameterDecl& d, const std::string& value) {
  if (d.choices.empty()) return true;
  for (std::string c : split_option_list(std::string(d.choices)))
    if (c.erase(0, c.find_first_not_of(' ')) == value) return true;
  return false;
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

std::string python_keyword(std::string_view option_name) { return spell_key(option_name, KeySpelling::python); }

const RunOption* find_run_option(std::string_view name) {
  for (const RunOption& o : run_options())
    if (o.name == name || python_keyword(o.name) == name) return &o;
  return nullptr;
}

void check_given_options(const RunOptions& o) {
  // The values first, each against its declaration: a bad value is named as such even where
  // nothing would read it.
  for (const RunOption& option : run_options()) {
    if (!is_given(o, option)) continue;
    if (option.decl.type == ParameterType::number) {
      const double v = std::holds_alternative<LawNumber>(option.field)
                           ? o.law_numbers.find(option.name)->second
                           : *(o.*std::get<std::optional<double> RunOptions::*>(option.field));
      require_in_range(option.decl, v);
    } else if (option.decl.type == ParameterType::text) {
      const std::string value = given_text(o, option);
      if (!is_declared_choice(option.decl, value))
        throw InvalidParameter(option.name, value, "one of: " + std::string(option.decl.choices));
    }
  }
  // Then what reads each.
  for (const RunOption& option : run_options())
    if (is_given(o, option)) require_read(o, option, given_text(o, option));
}

std::string trace_only_range(std::string_view what) {
  return fmt::format("given only where a trace is recorded (hertzdash simulate with a trace file, hertzdash fit, "
                     "Python's trace()): it says where the recorded acceleration is taken, and {} records none",
                     what);
}

void refuse_trace_only_options(const RunOptions& o, std::string_view what) {
  for (const RunOption& option : run_options())
    if (option.readers.trace_only && is_given(o, option))
      throw InvalidParameter(option.name, given_text(o, option), trace_only_range(what));
}

void refuse_options_not_read(const RunOptions& o, const RunOptions& defaults, std::span<const std::string_view> read,
                             const std::string& only_with) {
  for (const RunOption& option : run_options()) {
    if (std::find(read.begin(), read.end(), option.name) != read.end()) continue;
    const std::string value = given_text(o, option);
    if (value != given_text(defaults, option)) throw InvalidParameter(option.name, value, "given only with " + only_with);
  }
}

void require_read(const RunOptions& o, const RunOption& option, const std::string& value) {
  const IntegratorTraits& integrator = integrator_traits(parse_integrator(o.integrator));
  const OptionReaders& r = option.readers;
  std::string run;  // what this run has instead, when that is not what reads the option
  if (!r.laws.empty() && std::find(r.laws.begin(), r.laws.end(), o.damping) == r.laws.end())
    run = key_reference("damping") + " is " + o.damping;
  else if (r.elastic_rod && o.rod_model != "elastic")
    run = key_reference("rod-model") + " is " + o.rod_model;
  else if (r.flights_only && !o.follows_flights)
    run = "this command takes no drag in its falls and flights (a single impact integrates its fall in vacuum)";
  else if (r.flights_only && o.rod_model != "rigid")
    run = key_reference("rod-model") + " is " + o.rod_model + ", whose flights are integrated without drag";
  else if (r.integrators && !r.integrators(integrator))
    run = key_reference("integrator") + " is " + std::string(integrator.name);
  if (!run.empty())
    throw InvalidParameter(option.name, value, fmt::format("given only with {} (what reads it); {}", r.describe(), run));
}

std::optional<std::string_view> material_constant_given(const RunOptions& o) {
  if (o.viscous_time_constant_s) return "viscous-time-constant";
  for (const RegisteredLaw& law : registered_law_table())
    if (const ParameterDecl* d = law.material_constant(); d && o.law_numbers.contains(d->key)) return d->key;
  return std::nullopt;
}

DropTestSetup resolve_setup(const RunOptions& o, const PaperParameters& paper) {
  check_given_options(o);  // every given value is within its declared range from here on
  DropTestSetup s = paper_setup(paper, o.rod, o.height_m.value_or(default_height_m));
  if (o.impact_velocity_mps) s.impact_velocity_mps = *o.impact_velocity_mps;
  if (o.mass_kg) s.mass_kg = *o.mass_kg;
  if (o.restitution) s.restitution = *o.restitution;
  if (o.ball_E_Pa) s.ball.E_Pa = *o.ball_E_Pa;
  if (o.ball_nu) s.ball.nu = *o.ball_nu;
  if (o.ball_radius_m) s.ball_radius_m = *o.ball_radius_m;
  if (o.density_kg_per_m3) {  // a dropped ball: the sphere falls
    if (o.mass_kg)
      throw InvalidParameter("density", format_value(*o.density_kg_per_m3),
                             "omitted when `mass` is given (the density gives the ball's mass)");
    s.mass_kg = sphere_mass_kg(s.ball_radius_m, *o.density_kg_per_m3);
  }
  // The default yield stress is the paper's nylon hemisphere's. A sphere whose modulus, Poisson
  // ratio and radius are all given, or a dropped ball (`density`), is a body of the user's own,
  // checked only against a yield stress the user gives. (One or two of them alone are the
  // hemisphere's, as a fit of its modulus or radius gives.)
  if ((o.ball_E_Pa && o.ball_nu && o.ball_radius_m) || o.density_kg_per_m3) s.ball_yield_stress_Pa = INFINITY;
  if (o.ball_yield_stress_Pa) s.ball_yield_stress_Pa = *o.ball_yield_stress_Pa;
  // The rod preset supplies the mass, the flat's material and e: with all of them given it
  // supplies nothing, and the run names no rod.
  const std::optional<std::string_view> constant_given = material_constant_given(o);
  if ((o.mass_kg || o.density_kg_per_m3) && o.rod_E_Pa && o.rod_nu && (o.restitution || constant_given) &&
      o.rod_model == "rigid")
    s.rod_preset.clear();
  if (o.rod_E_Pa) s.rod.E_Pa = *o.rod_E_Pa;
  if (o.rod_nu) s.rod.nu = *o.rod_nu;
  if (o.gravity_mps2) s.gravity_mps2 = *o.gravity_mps2;
  s.no_tension = o.no_tension;
  if (o.air_density_kg_per_m3) s.air_drag.air_density_kg_per_m3 = *o.air_density_kg_per_m3;
  if (o.drag_coefficient) s.air_drag.drag_coefficient = *o.drag_coefficient;
  if (const std::string zeta = o.zeta.value_or("paper"); zeta == "paper") s.damping.zeta_form = ZetaForm::paper;
  else if (zeta == "exact") s.damping.zeta_form = ZetaForm::exact;
  else throw InvalidParameter("zeta", zeta, "one of: paper, exact");
  s.damping.omega_n = parse_omega_n_variant(o.omega_n.value_or(to_string(OmegaNVariant::paper)));
  s.damping.viscous_time_constant_s = o.viscous_time_constant_s;
  if (o.reference_velocity_mps) s.damping.reference_velocity_mps = *o.reference_velocity_mps;
  for (const auto& [key, value] : o.law_numbers) {
    const RunOption* option = find_run_option(key);
    if (!option || !std::holds_alternative<LawNumber>(option->field))
      throw InvalidParameter(key, format_value(value), "a number a damping law declares (`hertzdash models`)");
    s.damping.law_values.emplace_back(option->decl.key, value);
  }
  const std::vector<std::string>& reading_e = find_run_option("restitution")->readers.laws;  // the dissipative laws
  const bool law_reads_e = !constant_given &&
                           std::find(reading_e.begin(), reading_e.end(), o.damping) != reading_e.end();
  s.restitution_of_other_pair = law_reads_e && !o.restitution &&
                                (o.mass_kg || o.density_kg_per_m3 || o.ball_E_Pa || o.ball_nu || o.ball_radius_m ||
                                 o.rod_E_Pa || o.rod_nu);
  s.elastic_rod = resolve_elastic_rod(o, paper);
  try {
    validate(s);
  } catch (const HertzScaleRefused& refused) {
    refuse_hertz_scale(s, refused.scale, o);  // named after what the user gave
  }
  if (o.impact_velocity_mps && o.height_m)
    throw InvalidParameter("height", format_value(*o.height_m),
                           "omitted when `impact-velocity` is given (the run then starts at contact onset with that "
                           "speed; the height only sets it)");
  if (o.drag_coefficient && !s.air_drag.active())
    throw InvalidParameter("drag-coefficient", format_value(*o.drag_coefficient),
                           "given only with `air-density` > 0 (without air there is no drag)");
  if (constant_given && o.reference_velocity_mps)
    throw InvalidParameter("reference-velocity", format_value(*o.reference_velocity_mps),
                           fmt::format("omitted when `{}` is given (the reference speed only calibrates the law's "
                                       "material constant)",
                                       *constant_given));
  if (constant_given && o.restitution)
    throw InvalidParameter("restitution", format_value(*o.restitution),
                           fmt::format("omitted when `{}` is given (the law's damping is then that material "
                                       "constant; e only calibrates it)",
                                       *constant_given));
  return s;
}

SolverSettings resolve_solver(const RunOptions& o) {
  check_given_options(o);
  SolverSettings s;
  s.integrator = parse_integrator(o.integrator);
  s.dt_s = o.dt_s.value_or(s.dt_s);
  s.locate_events = !o.no_event_location;
  s.rtol = o.rtol.value_or(s.rtol);
  s.atol = o.atol.value_or(s.atol);
  s.max_step_s = o.max_step_s.value_or(s.max_step_s);
  if (const std::string method = o.cvode_method.value_or("adams"); method == "adams") s.cvode_method = CvodeMethod::adams;
  else if (method == "bdf") s.cvode_method = CvodeMethod::bdf;
  else throw InvalidParameter("cvode-method", method, "one of: adams, bdf");
  validate(s);
  return s;
}

}  // namespace hertzdash
