// One declaration per input (model/parameter.hpp, simulation/run_options.hpp) and every front
// end generated from it. Checked here: the command line's options, the case-file keys, the fit's
// names and bounds and docs/parameters.md against the declarations; the refusals' keys in each
// spelling; and that no option is silently ignored: over the whole matrix of option x law x rig
// x integrator, an option is either read (the run's description, the provenance header of every
// output, changes with it) or refused with exit-status-2 InvalidParameter naming it and what
// reads it. The Python keywords are compared in tests/python/test_python_module.py.
#include "hertzdash/simulation/impact_simulator.hpp"
#include "hertzdash/simulation/integrator_table.hpp"
#include "hertzdash/simulation/parameter_reference.hpp"
#include "hertzdash/simulation/run_options.hpp"
#include "hertzdash/simulation/run_reports.hpp"
#include "hertzdash/simulation/sweep_case.hpp"
#include "hertzdash/simulation/trace_fit.hpp"
#include "tests/cli_runner.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

using namespace hertzdash;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

const PaperParameters& paper() {
  static const PaperParameters p = load_paper_parameters();
  return p;
}

// The options that choose what runs; every run reads them, and the matrix varies them.
bool is_selection(const RunOption& o) {
  return o.name == "rod" || o.name == "damping" || o.name == "rod-model" || o.name == "integrator";
}

// A valid value of option o that differs from its default, set into `options`:
// - a fittable number: 1.1 times its default in the run, where that is finite and not zero (a
//   10 % change keeps every default impact of the paper's rods inside the Hertz model's domain:
//   X stays far below R);
// - the other numbers, by their meaning: a yield stress of 1e8 Pa, 2 elements, a reference speed
//   of 1 m/s, a step of 1e-7 s (below t_H / 1000 of every default impact, ~1.2e-3 s), tolerances
//   of 1e-6 and 1e-10, a largest step of 1e-5 s, a time constant of 1 us, a linear contact
//   stiffness of 1e6 N/m (the matched one, m v0^2 / X^2, is ~7e5 N/m for the steel rod at 20 mm);
// - a text: a choice other than the default; a flag: on.
void set_sample(RunOptions& options, const RunOption& o) {
  switch (o.decl.type) {
    case ParameterType::flag: set_flag(options, o, true); return;
    case ParameterType::text: {
      const std::vector<std::string> choices = split_option_list(std::string(o.decl.choices));
      for (std::string c : choices) {
        c.erase(0, c.find_first_not_of(' '));
        if (c != o.decl.default_value && c != "self-consistent" && c != "contact-time") {
          set_text(options, o, c);
          return;
        }
      }
      FAIL("no second choice for " << o.name);
      return;
    }
    case ParameterType::number: break;
  }
  if (o.value_in_setup) {
    RunOptions reading = options;
    reading.rod_model = "elastic";  // the elastic rod's inputs have their defaults only there
    if (!o.readers.laws.empty()) reading.damping = o.readers.laws.front();
    const std::optional<double> v = o.value_in_setup(resolve_setup(reading, paper()));
    if (v && std::isfinite(*v) && *v != 0) {
      set_number(options, o, std::min(1.1 * *v, std::nextafter(o.decl.range.hi, 0.0)));
      return;
    }
  }
  const std::map<std::string, double> by_meaning{{"ball-yield-stress", 1e8}, {"rod-elements", 2},
                                                 {"reference-velocity", 1.0}, {"dt", 1e-7},
                                                 {"rtol", 1e-6},              {"atol", 1e-10},
                                                 {"max-step", 1e-5},          {"viscous-time-constant", 1e-6},
                                                 {"linear-stiffness", 1e6},   {"rod-damping-ratio", 0.01},
                                                 {"cell-damping-ratio", 0.05}};
  const auto it = by_meaning.find(o.name);
  if (it == by_meaning.end()) FAIL("no sample value for " << o.name);
  set_number(options, o, it->second);
}

// Whether o's readers read it in this run.
bool read_in(const RunOption& o, const RunOptions& run) {
  const OptionReaders& r = o.readers;
  if (!r.laws.empty() && std::find(r.laws.begin(), r.laws.end(), run.damping) == r.laws.end()) return false;
  if (r.elastic_rod && run.rod_model != "elastic") return false;
  if (r.integrators && !r.integrators(integrator_traits(parse_integrator(run.integrator)))) return false;
  return true;
}

Parameters description(const RunOptions& o) {
  return describe_run(resolve_setup(o, paper()), o.damping, resolve_solver(o));
}

}  // namespace

TEST_CASE("docs/parameters.md is the program's parameter reference", "[parameters]") {
  const std::string page = test::slurp(std::filesystem::path(HERTZDASH_SOURCE_DIR) / "docs" / "parameters.md");
  CHECK(page == parameter_reference_markdown());
  const test::CliResult r = test::run_cli("parameters");
  REQUIRE(r.exit_code == 0);
  CHECK(r.out == page);
}

TEST_CASE("every option is declared once, with a key, a help text and a valid default", "[parameters]") {
  std::set<std::string> keys;
  for (const RunOption& o : run_options()) {
    INFO(o.name);
    CHECK(keys.insert(o.name).second);
    CHECK(is_parameter_key(o.name));
    CHECK(o.name == o.decl.key);
    CHECK(!o.decl.help.empty());
    CHECK(!o.decl.default_value.empty());
    CHECK((o.decl.type == ParameterType::text) == !o.decl.choices.empty());
    CHECK(o.unit == o.decl.column_unit);
    // A fittable option has its value in a resolved set-up, the fit's starting point.
    CHECK(o.decl.fittable == static_cast<bool>(o.value_in_setup));
  }
}

TEST_CASE("the command line's options are the declarations", "[parameters][cli]") {
  for (const char* command : {"simulate", "restitution", "bounce", "fit"}) {
    const test::CliResult r = test::run_cli(std::string(command) + " --help");
    REQUIRE(r.exit_code == 0);
    for (const RunOption& o : run_options()) {
      INFO(command << " --" << o.name);
      // fit runs its own model (RK4 at a fixed step resolved per contact): no solver options.
      const bool takes = std::string(command) != "fit" || o.group == RunOption::Group::setup;
      CHECK((r.out.find("--" + o.name + " ") != std::string::npos) == takes);
    }
  }
}

TEST_CASE("a case file takes every option under its key", "[parameters][sweep]") {
  for (const RunOption& o : run_options()) {
    if (is_selection(o)) continue;
    RunOptions expected;
    set_sample(expected, o);
    const std::string value = given_text(expected, o);
    const std::string toml = o.decl.type == ParameterType::text ? "\"" + value + "\"" : value;
    INFO(o.name << " = " << toml);
    const SweepCase c = parse_sweep_case("[base]\n" + o.name + " = " + toml + "\n", "case.toml");
    CHECK(is_given(c.base, o));
    CHECK(given_text(c.base, o) == value);
  }
}

TEST_CASE("the fit's parameters are the fittable declarations, bounded by their ranges", "[parameters][fit]") {
  for (const RunOption& o : run_options()) {
    INFO(o.name);
    if (!o.decl.fittable) {
      CHECK_THROWS_AS(parse_fit_parameters(o.name), InvalidParameter);
      continue;
    }
    const std::vector<FitParameter> p = parse_fit_parameters(o.name);
    REQUIRE(p.size() == 1);
    CHECK(p[0].option == o.name);
    CHECK(p[0].lower == o.decl.range.lo);
    CHECK(p[0].upper == o.decl.range.hi);
  }
}

TEST_CASE("a refusal carries its key, value and range, and each front end spells the key", "[parameters]") {
  RunOptions o;
  o.ball_E_Pa = -1;
  try {
    resolve_setup(o, paper());
    FAIL("ball-E = -1 was accepted");
  } catch (const InvalidParameter& e) {
    CHECK(e.key == "ball-E");
    CHECK(e.value == "-1");
    CHECK(e.valid_range == "a finite number > 0 (Pa)");
    CHECK(e.message(KeySpelling::command_line) == "invalid --ball-E = -1: must be a finite number > 0 (Pa)");
    CHECK(e.message(KeySpelling::python) == "invalid ball_E = -1: must be a finite number > 0 (Pa)");
    CHECK(std::string(e.what()) == "invalid ball-E = -1: must be a finite number > 0 (Pa)");
  }
  // A reference to another option in the range is spelled likewise; other quoted text is kept.
  const InvalidParameter e("height", "0", "> 0 with `gravity` > 0 (see `hertzdash models`)");
  CHECK(e.message(KeySpelling::command_line) == "invalid --height = 0: must be > 0 with --gravity > 0 (see `hertzdash models`)");
  CHECK(e.message(KeySpelling::python) == "invalid height = 0: must be > 0 with gravity > 0 (see `hertzdash models`)");
  // Text that is no key is shown as it is.
  CHECK(spell_key("rod length (Table 1)", KeySpelling::command_line) == "rod length (Table 1)");
}

TEST_CASE("no option is ignored: option x law x rig x integrator, each read or refused", "[parameters]") {
  std::size_t read = 0, refused = 0;
  for (const RunOption& o : run_options()) {
    if (is_selection(o)) continue;
    for (const LawInfo& law : registered_laws())
      for (const char* rig : {"rigid", "elastic"})
        for (const IntegratorTraits& integrator : all_integrator_traits) {
          RunOptions base;
          base.damping = std::string(law.name);
          base.rod_model = rig;
          base.integrator = std::string(integrator.name);
          RunOptions with = base;
          set_sample(with, o);
          INFO(o.name << " = " << given_text(with, o) << " with damping " << law.name << ", rod-model " << rig
                      << ", integrator " << integrator.name);
          if (read_in(o, with)) {
            // Read: the run's description (every output's header) changes with it.
            CHECK(description(with) != description(base));
            ++read;
          } else {
            // Refused, naming the option and what reads it.
            try {
              description(with);
              FAIL("accepted and ignored");
            } catch (const InvalidParameter& e) {
              CHECK(e.key == o.name);
              CHECK_THAT(e.valid_range, StartsWith("given only with " + o.readers.describe()));
            }
            ++refused;
          }
        }
  }
  // Both sides of the matrix are exercised (the law, rig and integrator options are refused
  // somewhere, the set-up's options read everywhere).
  CHECK(read > 0);
  CHECK(refused > 0);
}

TEST_CASE("restitution reads the wall's moduli, refuses what it cannot read", "[parameters]") {
  // kuwabara-kono with a given time constant A: its restitution depends on the contact's
  // stiffness through the damping number beta = A (K/m)^{2/5} v0^{1/5}, and
  // 1 - e = C1 beta - C2 beta^2 + ... (model/damping/laws/kuwabara_kono.hpp). A nylon wall
  // (rod-E = 2e9 Pa) roughly halves K against the default rigid wall, so
  //   (1 - e_wall) / (1 - e_rigid) = (K_wall / K_rigid)^{2/5} (1 + O((C2/C1) |beta_w - beta_r|)),
  // beta ~ 0.06 at A = 1e-5 s here, so the second-order term is below 2 %.
  RunOptions o;
  o.damping = "kuwabara-kono";
  o.viscous_time_constant_s = 1e-5;
  const RestitutionRun rigid = run_restitution(o, paper(), std::nullopt);
  RunOptions wall = o;
  wall.rod_E_Pa = 2e9;
  const RestitutionRun soft = run_restitution(wall, paper(), std::nullopt);
  REQUIRE(std::isinf(rigid.setup.rod.E_Pa));
  REQUIRE(soft.setup.rod.E_Pa == 2e9);
  const double beta_ratio = std::pow(hertz_stiffness(soft.setup) / hertz_stiffness(rigid.setup), 0.4);
  CHECK(beta_ratio < 0.8);
  CHECK((1 - soft.e_effective) / (1 - rigid.e_effective) == Approx(beta_ratio).epsilon(0.02));

  auto refused_key = [&](RunOptions bad) {
    try {
      run_restitution(bad, paper(), std::nullopt);
    } catch (const InvalidParameter& e) {
      return e.key;
    }
    return std::string("(accepted)");
  };
  RunOptions nu_only = o;  // against the rigid wall its Poisson ratio does not enter
  nu_only.rod_nu = 0.3;
  CHECK(refused_key(nu_only) == "rod-nu");
  RunOptions elastic = o;  // the contact phase alone has no elastic rod
  elastic.rod_model = "elastic";
  CHECK(refused_key(elastic) == "rod-model");
  RunOptions gravity = o;  // no fall to turn into a speed, no gravity in contact
  gravity.impact_velocity_mps = 1.0;
  gravity.gravity_mps2 = 9.81;
  CHECK(refused_key(gravity) == "gravity");
}
