// Two spheres head-on and the rig `spheres` (simulation/rigs/spheres_rig.hpp).
#include "hertzdash/simulation/rigs/spheres_rig.hpp"

#include "hertzdash/model/drop_test_parameters.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/rigs/second_sphere_inputs.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hertzdash {

namespace {

namespace p = drop_test_parameters;
using R = NumberRange;
namespace sphere2 = second_sphere_inputs;
constexpr ParameterDecl inputs[] = {sphere2::radius, sphere2::E, sphere2::nu, sphere2::mass, sphere2::density};

// The drop's height, the flat and the flights: two spheres in free space have none.
constexpr std::string_view not_read[] = {"rod", "height", "rod-E", "rod-nu", "gravity", "air-density", "drag-coefficient",
                                         "rod-model"};
constexpr std::string_view why_not_read = "two spheres meet head-on in free space at `impact-velocity`: no drop, no flat";

// What the drop test's options mean here.
constexpr RigOptionNote notes[] = {
    {"impact-velocity", "Relative approach speed v of the spheres [m/s] (required)"},
    {"mass", "Mass of the first sphere [kg] (required, or --density)"},
    {"density", "Density of the first sphere [kg/m^3], instead of --mass (and the second's, unless it has its own "
                "--second-mass or --second-density)"},
    {"ball-yield-stress", "Yield stress of the first sphere [Pa]: its onset of yield under the contact is flagged "
                          "(default: inf, no check)"},
    {"restitution", "The pair's coefficient of restitution e in (0,1] at --reference-velocity (required by a law that "
                    "reads it)"},
};

struct SpheresImpact {
  double impact_speed_mps, rebound_speed_mps;
};

struct Run {
  DropTestSetup setup;  ///< the contact: m*, R*, the two materials
  std::string law;
  Sphere first, second;
  Parameters inputs;
  ImpactSummary summary;
  VelocitiesAfter after;
  struct {
    std::vector<SpheresImpact> impacts;
  } run;
};

/// Inputs the spheres need that a drop test defaults: the speed, the first mass, e (where the law reads it).
void refuse(const RunOptions& o, const RigInputs& in) {
  require_free_sphere(o, "the spheres' approach speed [m/s] (`hertzdash spheres` has no drop)", "the first sphere's");
  const std::vector<std::string>& reading_e = find_run_option("restitution")->readers.laws;
  if (!o.restitution && !material_constant_given(o) && std::ranges::find(reading_e, o.damping) != reading_e.end())
    throw InvalidParameter("restitution", "none",
                           fmt::format("given for the law {}: the pair's e (the paper's Table 2 is a rod's on nylon)", o.damping));
  sphere2::refuse_both_masses(in);
}

Run run(const RunOptions& options, const PaperParameters& paper, const RigInputs& in) {
  Run r;
  DropTestSetup given = resolve_setup(options, paper);
  if (!options.ball_yield_stress_Pa) given.ball_yield_stress_Pa = INFINITY;  // no preset body is a sphere
  r.law = options.damping;
  r.first = {given.ball_radius_m, given.mass_kg, given.ball};
  r.second = sphere2::resolve(options, in, r.first);
  const double v = *given.impact_velocity_mps;
  r.setup = two_spheres_contact(given, r.first, r.second, v);
  const SolverSettings solver = resolve_solver(options);
  r.inputs = describe_rig_run(given, r.law, solver, not_read);
  for (const auto& [decl, value] : {std::pair{sphere2::radius, r.second.radius_m}, {sphere2::E, r.second.material.E_Pa},
                                    {sphere2::nu, r.second.material.nu}, {sphere2::mass, r.second.mass_kg}})
    r.inputs.emplace_back(input_column(decl), fmt::format("{}", value));
  ImpactSimulator simulator(solver);
  r.summary = simulator.run(r.setup, r.law);
  r.after = velocities_after(r.first, r.second, v, r.summary.e_effective);
  r.run.impacts.push_back({v, r.summary.rebound_velocity_mps});
  return r;
}

RigResult outcome(const Run& r) {
  RigResult out{.heading = fmt::format("two spheres head-on, damping law '{}', integrator {}", r.law,
                                       to_string(r.summary.integrator_used)),
                .scalars = {}, .rows = {}, .warnings = {},
                .end_reason = r.summary.separated ? "the spheres separated" : "the spheres did not separate", .work = r.summary.work, .inputs = r.inputs};
  for (const DiagnosticInfo& d : diagnostic_table)
    if (d.kind == "warning" && r.summary.diagnostics.has(d.code))
      out.warnings.push_back(fmt::format("{} (`hertzdash simulate` with the same contact explains it: docs/json-output.md)", d.name));
  return out;
}

using V = RigValue;
constexpr RigFieldOf<Run> results[] = {
    {{"damping", "", "the damping law", false, false, false}, [](const Run& r) -> V { return r.law; }},
    {{"integrator_used", "", "the integrator that ran", false, false, false},
     [](const Run& r) -> V { return std::string(to_string(r.summary.integrator_used)); }},
    {{"reduced_mass_kg", "kg", "m* = m1 m2 / (m1 + m2)"}, [](const Run& r) -> V { return r.setup.mass_kg; }},
    {{"reduced_radius_m", "m", "R* = R1 R2 / (R1 + R2)"}, [](const Run& r) -> V { return r.setup.ball_radius_m; }},
    {{"effective_modulus_Pa", "Pa", "E* of eq. (3) from both spheres' E and nu"},
     [](const Run& r) -> V { return 1 / (compliance(r.setup.ball) + compliance(r.setup.rod)); }},
    {{"e_effective", "1", "rebound over approach speed, relative"}, [](const Run& r) -> V { return r.summary.e_effective; }},
    {{"contact_time_s", "s", "onset to separation"}, [](const Run& r) -> V { return r.summary.contact_time_s; }},
    {{"peak_force_N", "N", "largest contact force"}, [](const Run& r) -> V { return r.summary.peak_force_N; }},
    {{"max_compression_m", "m", "largest approach of the centres"}, [](const Run& r) -> V { return r.summary.max_deformation_m; }},
    {{"first_velocity_after_mps", "m/s", "the first sphere's velocity after, the second at rest before (towards it: positive)"},
     [](const Run& r) -> V { return r.after.a_mps; }},
    {{"second_velocity_after_mps", "m/s", "the second sphere's velocity after, in the same frame"},
     [](const Run& r) -> V { return r.after.b_mps; }},
    {{"energy_lost_J", "J", "(1/2) m* v^2 (1 - e_effective^2)"},
     [](const Run& r) -> V {
       const double v = *r.setup.impact_velocity_mps;
       return 0.5 * r.setup.mass_kg * v * v * (1 - r.summary.e_effective * r.summary.e_effective);
     }},
};

constexpr RigColumnOf<SpheresImpact> table[] = {
    {{"impact_speed_mps", "m/s", "relative approach speed"}, [](const SpheresImpact& i) { return i.impact_speed_mps; }},
    {{"rebound_speed_mps", "m/s", "relative rebound speed"}, [](const SpheresImpact& i) { return i.rebound_speed_mps; }},
};

}  // namespace

const Rig& spheres_rig() {
  static const Rig rig = make_rig<Run, SpheresImpact>(
      {.name = "spheres",
       .summary = "Two spheres of their own radius, modulus, Poisson ratio and mass head-on: one impact of the "
                  "reduced mass and radius with any law and integrator, and each sphere's velocity after",
       .inputs = inputs, .run_options_not_read = not_read, .not_read_because = why_not_read, .run_option_notes = notes,
       .default_integrator = {}, .refuse = refuse, .results = results,
       .table_description = "the impact (relative speeds)", .table = table, .run = run, .outcome = outcome,
       .regularized_contacts = false});
  return rig;
}

}  // namespace hertzdash
