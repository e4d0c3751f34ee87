// One declaration per input (model/parameter.hpp, simulation/options/run_options.hpp) and every front
// end generated from it. Checked here: the command line's options, the fit's names and bounds
// and docs/parameters.md against the declarations (the case-file keys in
// tests/test_sweep_case_keys.cpp, built with TOML only); the refusals' keys in each
// spelling; and that no option is silently ignored: over the whole matrix of option x law x rig
// x integrator, an option is either read (the run's description, the provenance header of every
// output, changes with it) or refused with exit-status-2 InvalidParameter naming it and what
// reads it. The Python keywords are compared in tests/python/test_python_module.py.
#include "hertzdash/io/decimal_number.hpp"
#include "hertzdash/model/drop_test_parameters.hpp"
#include "hertzdash/simulation/fit/trace_fit.hpp"
#include "hertzdash/simulation/reports/parameter_reference.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "tests/cli_runner.hpp"
#include "tests/parameter_samples.hpp"

#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <string>

using namespace hertzdash;
using Catch::Matchers::Contains;
using Catch::Matchers::StartsWith;

namespace {

using test::is_selection;
using test::paper;
using test::set_sample;

// Whether o's readers read it in this run.
bool read_in(const RunOption& o, const RunOptions& run) {
  return o.readers.read_by(run.damping, run.rod_model == "elastic", integrator_traits(parse_integrator(run.integrator)),
                           run.follows_flights);
}

Parameters description(const RunOptions& o) {
  return describe_run(resolve_setup(o, paper()), o.damping, resolve_solver(o));
}

// f(o) for the run options o that select each registered law x rod model x integrator.
template <class F> void for_each_law_rod_integrator(F f) {
  for (const LawInfo& law : registered_laws())
    for (const char* rod_model : {"rigid", "elastic"})
      for (const IntegratorTraits& integrator : all_integrator_traits) {
        RunOptions o;
        o.damping = std::string(law.name);
        o.rod_model = rod_model;
        o.integrator = std::string(integrator.name);
        f(o);
      }
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

TEST_CASE("every input the model declares is an option, bound to its declaration", "[parameters]") {
  // The drop test's, the elastic rod's and each law's declarations (model/) against the table:
  // an input declared in the model but not bound in simulation/options/run_options.cpp could be given
  // by no front end.
  std::vector<ParameterDecl> declared(std::begin(drop_test_parameters::all), std::end(drop_test_parameters::all));
  declared.insert(declared.end(), std::begin(elastic_rod_parameters::all), std::end(elastic_rod_parameters::all));
  for (const RegisteredLaw& law : registered_law_table())
    for (const ParameterDecl& d : law.parameters) declared.push_back(d);
  REQUIRE(declared.size() > 12);
  for (const ParameterDecl& d : declared) {
    INFO(d.key);
    const RunOption* o = find_run_option(d.key);
    REQUIRE(o != nullptr);
    CHECK(o->decl.help == d.help);
    CHECK(o->decl.unit == d.unit);
    CHECK(o->decl.type == d.type);
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
      // An integer is shown as one (issue 32: --rod-elements read FLOAT).
      if (takes && o.decl.type == ParameterType::number)
        CHECK(r.out.find("--" + o.name + (o.decl.range.kind == NumberRange::Kind::integer ? " INT" : " FLOAT")) !=
              std::string::npos);
    }
    // Grouped by what reads them, each heading once (issue 32: the elastic rod's mixed in).
    for (const char* heading : {"Drop test:", "Damping law:", "Elastic rod and load cell (--rod-model elastic):"}) {
      INFO(command << ": " << heading);
      CHECK(r.out.find(heading) != std::string::npos);
    }
    CHECK((r.out.find("Solver:") != std::string::npos) == (std::string(command) != "fit"));
  }
}

// Issue 46: `shaker --help` and `fit --help` ran past 60 lines, each option's help a paragraph.
// A command's help is one line per option: the declaration's first clause and its default
// without the default's source; the long form is `hertzdash parameters`' (the usage line says so).
TEST_CASE("a command's help fits a screen: one short line per option, the long form in `parameters`", "[parameters][cli]") {
  for (const char* command : {"shaker", "fit"}) {
    INFO(command);
    const test::CliResult r = test::run_cli(std::string(command) + " --help");
    REQUIRE(r.exit_code == 0);
    CHECK(std::count(r.out.begin(), r.out.end(), '\n') <= 45);
    CHECK(r.out.find("(each option in full: hertzdash parameters)") != std::string::npos);
    // --mass's declaration: "Mass of the falling body [kg]: the paper's rod, or a dropped ball; a
    // finite number > 0 (kg) (default: Table 1; the paper's Table 1 (the rod's mass))".
    CHECK(r.out.find("Mass of the falling body [kg] (default: Table 1)\n") != std::string::npos);
    // A text option's valid values stay: "(one of: steel, ...)"; a long list is counted.
    CHECK(r.out.find("(one of: steel, duralumin-a, duralumin-b, duralumin-c) (default: steel)\n") != std::string::npos);
    CHECK(r.out.find("Damping law (see `hertzdash models`) (one of 15 values) (default: hongo)\n") != std::string::npos);
    // The inputs of one law are folded into one line of names when the help runs long.
    CHECK(r.out.find("Inputs of one law (--damping LAW): --zeta TEXT, --omega-n TEXT") != std::string::npos);
  }
  // The parameters command prints the long form the footer points to.
  const test::CliResult full = test::run_cli("parameters");
  REQUIRE(full.exit_code == 0);
  CHECK(full.out.find("the paper's Table 1 (the rod's mass)") != std::string::npos);
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
    for_each_law_rod_integrator([&](const RunOptions& base) {
          RunOptions with = base;
          set_sample(with, o);
          INFO(o.name << " = " << given_text(with, o) << " with damping " << base.damping << ", rod-model "
                      << base.rod_model << ", integrator " << base.integrator);
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
        });
  }
  // Both sides of the matrix are exercised (the law, rig and integrator options are refused
  // somewhere, the set-up's options read everywhere).
  CHECK(read > 0);
  CHECK(refused > 0);
}

TEST_CASE("the run description lists each option the run reads, under its column name", "[parameters]") {
  // Every output's header and the JSON's "inputs" are made from the option table: for each law,
  // rig and integrator, an option appears (as its Python keyword and unit, `ball_E_Pa`) exactly
  // when the run reads it and holds a value of it (a law's computed default is none).
  std::size_t runs = 0;
  for_each_law_rod_integrator([&](const RunOptions& run) {
        const DropTestSetup setup = resolve_setup(run, paper());
        const SolverSettings solver = resolve_solver(run);
        const Parameters d = describe_run(setup, run.damping, solver);
        ++runs;
        for (const RunOption& o : run_options()) {
          if (!o.value_in_run) continue;
          const std::string name = column_name(o);
          const auto listed = std::find_if(d.begin(), d.end(), [&](const auto& entry) { return entry.first == name; });
          INFO(name << " with damping " << run.damping << ", rod-model " << run.rod_model << ", integrator "
                    << run.integrator);
          const bool expected = read_in(o, run) && o.value_in_run(setup, solver).has_value();
          CHECK((listed != d.end()) == expected);
          if (expected && listed != d.end()) CHECK(listed->second == *o.value_in_run(setup, solver));
        }
        CHECK(std::count_if(d.begin(), d.end(), [](const auto& e) { return e.first == "damping"; }) == 1);
      });
  CHECK(runs == registered_laws().size() * 2 * all_integrator_traits.size());
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

TEST_CASE("no option is ignored by restitution: each read or refused", "[parameters]") {
  // The command's own dimension of the matrix: restitution runs the contact phase alone, so it
  // sets the wall and gravity itself. Each option, given with a law, rig and integrator that read
  // it, either changes the contact that runs (its description) or is refused naming the option.
  auto restitution_contact = [](const RunOptions& o) {
    const RestitutionRun r = run_restitution(o, paper(), std::nullopt);
    return describe_run(r.setup, r.law, r.solver);
  };
  std::size_t read = 0, refused = 0;
  for (const RunOption& o : run_options()) {
    if (is_selection(o)) continue;
    RunOptions base;
    if (!o.readers.laws.empty()) base.damping = o.readers.laws.front();
    if (o.readers.elastic_rod) base.rod_model = "elastic";
    if (o.readers.integrators)
      for (const IntegratorTraits& row : all_integrator_traits)
        if (o.readers.integrators(row)) {
          base.integrator = std::string(row.name);
          break;
        }
    RunOptions with = base;
    set_sample(with, o);
    INFO(o.name << " = " << given_text(with, o));
    try {
      const Parameters given = restitution_contact(with);
      CHECK(given != restitution_contact(base));
      ++read;
    } catch (const InvalidParameter& e) {
      // Refused by name: the option itself, or the elastic rod it needs (restitution has none).
      CHECK((e.key == o.name || (o.readers.elastic_rod && e.key == "rod-model")));
      ++refused;
    }
  }
  CHECK(read > 0);
  CHECK(refused > 0);
}

TEST_CASE("no option is ignored: each set-up option a run reads changes what simulate reports", "[parameters]") {
  // The matrix above decides "read" by the run's description, which lists every input whether
  // the physics uses it or not. Here each set-up option given with a law and rig that read it
  // must change simulate's report itself (every number of its JSON but the inputs, and the trace
  // it records): an option the model receives and then ignores fails here. CVODE at its defaults.
  // One physical no-op is exempt: the tension clamp (no-tension) changes nothing for a law whose
  // force never turns tensile in the impact (the undamped law; the Hunt-Crossley family where
  // 1 + chi xdot >= 1 - a(e) > 0 on rebound, a(e) < 1 as at the paper's e), so it is not asked to
  // change every law's report; tests/test_tension_clamp.cpp checks the clamp where it acts.
  auto report = [](const RunOptions& o) {
    const SimulateRun r = run_simulate(o, paper(), true);
    nlohmann::ordered_json j = to_json(r);
    j.erase("inputs");
    j.erase("git_revision");
    std::string text = j.dump();
    for (const TraceSample& t : r.trace)
      for (const TraceColumn& c : trace_column_table) text += fmt::format(" {}", c.value(t, r.trace.front()));
    return text;
  };
  std::map<std::pair<std::string, std::string>, std::string> base_reports;  // (law, rig) -> report
  std::size_t compared = 0;
  for (const RunOption& o : run_options()) {
    if (is_selection(o) || o.group != RunOption::Group::setup || o.name == "no-tension") continue;
    for (const LawInfo& law : registered_laws())
      for (const char* rig : {"rigid", "elastic"}) {
        RunOptions base;
        base.damping = std::string(law.name);
        base.rod_model = rig;
        RunOptions with = base;
        set_sample(with, o);
        if (!read_in(o, with)) continue;  // refused: the matrix above
        INFO(o.name << " = " << given_text(with, o) << " with damping " << law.name << ", rod-model " << rig);
        std::string changed;
        try {
          changed = report(with);
        } catch (const InvalidParameter& e) {
          // Refused by a rule beyond the readers (a law that ignores e, ...): named, not ignored.
          CHECK(e.key == o.name);
          continue;
        }
        auto [it, fresh] = base_reports.try_emplace({std::string(law.name), rig});
        if (fresh) it->second = report(base);
        CHECK(changed != it->second);
        ++compared;
      }
  }
  CHECK(compared > 300);
}

TEST_CASE("the declarations' choices and defaults are those of their sources", "[parameters]") {
  // A declaration states its valid values and its default as a user reads them; where the value
  // lives elsewhere (an enum, the paper's tables and assumptions, SolverSettings) they must agree,
  // or the help and docs/parameters.md would say one thing and the run do another.
  auto decl = [](std::string_view key) -> const ParameterDecl& { return find_run_option(key)->decl; };
  auto joined = [](const auto& names) {
    std::string s;
    for (const auto& n : names) s += (s.empty() ? "" : ", ") + std::string(n);
    return s;
  };
  std::vector<std::string> rods, variants;
  for (const RodData& r : paper().rods) rods.push_back(r.name);
  for (OmegaNVariant v : all_omega_n_variants) variants.emplace_back(to_string(v));
  CHECK(decl("rod").choices == joined(rods));
  CHECK(decl("omega-n").choices == joined(variants));
  CHECK(decl("zeta").choices == joined(std::vector<std::string>{to_string(ZetaForm::paper), to_string(ZetaForm::exact)}));
  CHECK(decl("cvode-method").choices ==
        joined(std::vector<std::string>{to_string(CvodeMethod::adams), to_string(CvodeMethod::bdf)}));
  CHECK(decl("accelerometer").choices ==
        joined(std::vector<std::string>{to_string(Accelerometer::top), to_string(Accelerometer::bottom)}));
  // Numeric defaults, read back as numbers.
  auto number = [&](std::string_view key) {
    const std::optional<double> v = parse_option_number(std::string(decl(key).default_value));
    INFO(key << " default " << decl(key).default_value);
    REQUIRE(v);
    return *v;
  };
  const SolverSettings solver;
  CHECK(number("dt") == solver.dt_s);
  CHECK(number("rtol") == solver.rtol);
  CHECK(number("atol") == solver.atol);
  CHECK(number("max-step") == solver.max_step_s);
  CHECK(number("height") == default_height_m);
  CHECK(number("rod-elements") == ElasticRodSetup::default_elements);
  CHECK(number("ball-E") == paper().ball.E_Pa);
  CHECK(number("ball-nu") == paper().ball.nu);
  CHECK(number("ball-radius") == paper().ball.radius_m);
  CHECK(number("ball-yield-stress") == paper().ball.yield_stress_Pa);
  CHECK(number("gravity") == paper().gravity_mps2);
  CHECK(std::string(decl("integrator").default_value) == to_string(solver.integrator));
  CHECK(std::string(decl("damping").default_value) == default_damping_law);
  CHECK(std::string(decl("cvode-method").default_value) == to_string(solver.cvode_method));
}
