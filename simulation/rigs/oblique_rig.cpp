// The rig `oblique` (simulation/rigs/oblique_rig.hpp).
#include "hertzdash/simulation/rigs/oblique_rig.hpp"

#include "hertzdash/model/oblique_contact_mdr.hpp"  // max_cells
#include "hertzdash/model/tangential/registry.hpp"
#include "hertzdash/simulation/rigs/second_sphere_inputs.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/run/oblique_impact.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <vector>

namespace hertzdash {

namespace {

using R = NumberRange;
constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr ParameterDecl incidence_angle{.key = "incidence-angle", .unit = "deg", .column_unit = "deg",
    .range = R::closed_open(0, 90), .default_value = "0", .default_number = 0, .default_source = "head-on",
    .help = "Angle of the sphere's velocity from the flat's normal at onset [degrees], in [0, 90)"};
constexpr ParameterDecl friction{.key = "friction", .range = R::non_negative(), .default_value = "0.3",
    .default_number = 0.3, .default_source = "chosen: a dry contact",
    .help = "Coulomb's friction coefficient mu >= 0 of the contact"};
constexpr ParameterDecl tangential_model{.key = "tangential-model", .type = ParameterType::text,
    .choices = tangential_model_choices, .default_value = "mindlin-no-slip",
    .help = "Tangential contact model (docs/oblique.md)"};
constexpr ParameterDecl spin{.key = "spin", .unit = "rad/s", .column_unit = "rad_per_s",
    .range = R::open(-infinity, infinity), .default_value = "0", .default_number = 0, .default_source = "no spin",
    .help = "The sphere's angular velocity at onset [rad/s], counted so that the contact point slides at "
            "w + R omega (w the tangential velocity)"};
constexpr ParameterDecl inertia_factor{.key = "inertia-factor", .range = R::open_closed(0, 1), .default_value = "0.4",
    .default_number = 0.4, .default_source = "a solid sphere, 2/5",
    .help = "The sphere's moment of inertia over m R^2: 0.4 solid, 2/3 a thin shell"};
constexpr ParameterDecl tangential_stiffness{.key = "tangential-stiffness", .unit = "N/m", .column_unit = "N_per_m",
    .range = R::positive(), .default_value = "matched",
    .default_source = "Mindlin's 8 G* a at the normal impact's undamped Hertz maximum overlap",
    .help = "Stiffness k_t [N/m] of the linear tangential spring (--tangential-model linear-spring)"};
constexpr ParameterDecl tangential_damping{.key = "tangential-damping", .range = R::closed_open(0, 1), .default_value = "0",
    .default_number = 0, .default_source = "none",
    .help = "Damping ratio zeta_t in [0, 1) of a tangential dashpot beside the spring, eta = 2 zeta_t sqrt(k_t m_t): a "
            "sticking contact's slip oscillates with that damping ratio"};
constexpr ParameterDecl second_spin{.key = "second-spin", .unit = "rad/s", .column_unit = "rad_per_s",
    .range = R::open(-infinity, infinity), .default_value = "0", .default_number = 0, .default_source = "no spin",
    .help = "The second sphere's angular velocity at onset [rad/s] (with `second-radius`), counted so that the contact "
            "point slides at w1 - w2 + R1 omega1 + R2 omega2"};
constexpr ParameterDecl second_inertia_factor{.key = "second-inertia-factor", .range = R::open_closed(0, 1),
    .default_value = "0.4", .default_number = 0.4, .default_source = "a solid sphere, 2/5",
    .help = "The second sphere's moment of inertia over m R^2 (with `second-radius`)"};
constexpr ParameterDecl contact_cells{.key = "contact-cells", .range = R::integer(1, MdrObliqueContactSystem::max_cells),
    .default_value = "200",
    .default_number = default_contact_cells, .default_source = "second order in the cells: the slip after within about "
                                                               "2e-5 of its limit at 200 (tests/test_oblique_mdr.cpp)",
    .help = "Cells over the contact radius of a tangential model resolved over the contact area (--tangential-model "
            "cattaneo-mindlin-mdr)"};
namespace sphere2 = second_sphere_inputs;
constexpr ParameterDecl inputs[] = {incidence_angle,      friction,           tangential_model, spin,        inertia_factor,
                                    tangential_stiffness, tangential_damping, contact_cells,    sphere2::radius, sphere2::E,
                                    sphere2::nu,          sphere2::mass,      sphere2::density, second_spin, second_inertia_factor};
/// Given only with a second sphere (`second-radius`).
constexpr const ParameterDecl* second_sphere_only[] = {&sphere2::E, &sphere2::nu, &sphere2::mass, &sphere2::density,
                                                       &second_spin, &second_inertia_factor};

constexpr std::string_view not_read[] = {"rod", "height", "gravity", "air-density", "drag-coefficient", "rod-model",
                                         "integrator", "dt", "no-event-location", "cvode-method", "max-step",
                                         "no-tension", "ball-yield-stress"};
constexpr std::string_view why_not_read =
    "the sphere meets the flat at `impact-velocity` and `incidence-angle` in free space (no drop, no rod, no "
    "gravity), its contact run by dopri5 in regularising variables (the stick/slip switch rules out the others)";

constexpr RigOptionNote notes[] = {
    {"impact-velocity", "The sphere's speed at onset [m/s] (required), relative to the second sphere if any; its normal "
                        "part v cos(theta) calibrates the law"},
    {"mass", "Mass of the sphere [kg] (required, or --density)"},
    {"density", "Density of the sphere [kg/m^3], instead of --mass"},
    {"rod-E", "Young's modulus of the flat [Pa] (inf: rigid; not with `second-radius`)"},
    {"rod-nu", "Poisson ratio of the flat (not with `second-radius`)"},
    {"restitution", "The normal coefficient of restitution e in (0,1] (required by a law that reads it)"},
};

struct ObliqueRow {
  double speed_mps, incidence_angle_deg;
};

struct Run {
  ObliqueImpactSpec spec;
  ObliqueImpactResult result;
  Parameters inputs;
  struct {
    std::vector<ObliqueRow> impacts;
  } run;
};

void refuse(const RunOptions& o, const RigInputs& in) {
  require_free_sphere(o, "the sphere's speed [m/s] (`hertzdash oblique` has no drop)", "the sphere's");
  const std::string model = in.text("tangential-model").value_or(std::string(tangential_model.default_value));
  if (in.number("tangential-stiffness") && model != "linear-spring")
    throw InvalidParameter("tangential-stiffness", format_value(*in.number("tangential-stiffness")),
                           "given only with `tangential-model` linear-spring");
  const TangentialModelInfo* info = find_tangential_model(model);  // null for a name the choices refuse
  if (in.number(contact_cells.key) && !(info && info->resolves_contact_area))
    throw InvalidParameter(std::string(contact_cells.key), format_value(*in.number(contact_cells.key)),
                           "given only with a tangential model resolved over the contact area (cattaneo-mindlin-mdr)");
  if (in.number(sphere2::radius.key)) {
    for (const auto& [key, given] : {std::pair{"rod-E", o.rod_E_Pa}, {"rod-nu", o.rod_nu}})
      if (given) throw InvalidParameter(key, format_value(*given), "omitted with `second-radius` (a second sphere, not a flat)");
    sphere2::refuse_both_masses(in);
  } else {
    for (const ParameterDecl* decl : second_sphere_only)
      if (in.number(decl->key))
        throw InvalidParameter(std::string(decl->key), format_value(*in.number(decl->key)),
                               "given only with `second-radius` (a second sphere instead of the flat)");
  }
}

Run run(const RunOptions& options, const PaperParameters& paper, const RigInputs& in) {
  Run r;
  DropTestSetup setup = resolve_setup(options, paper);
  setup.gravity_mps2 = 0;
  ObliqueImpactSpec& s = r.spec;
  s.setup = setup;
  s.law = options.damping;
  s.tangential_model = in.text("tangential-model").value_or(std::string(tangential_model.default_value));
  s.friction = in.number_or_default(friction);
  s.incidence_angle_deg = in.number_or_default(incidence_angle);
  s.speed_mps = *setup.impact_velocity_mps;
  s.spin_rad_per_s = in.number_or_default(spin);
  s.inertia_factor = in.number_or_default(inertia_factor);
  s.tangential_damping_ratio = in.number_or_default(tangential_damping);
  s.linear_stiffness_N_per_m = in.number("tangential-stiffness");
  s.contact_cells = static_cast<int>(in.number_or_default(contact_cells));
  if (in.number(sphere2::radius.key)) {
    const Sphere b = sphere2::resolve(options, in, {setup.ball_radius_m, setup.mass_kg, setup.ball});
    s.second = SecondSphere{.radius_m = b.radius_m, .mass_kg = b.mass_kg, .material = b.material,
                            .inertia_factor = in.number_or_default(second_inertia_factor),
                            .spin_rad_per_s = in.number_or_default(second_spin)};
  }
  s.solver = resolve_solver(options);
  r.result = run_oblique_impact(s);
  // A second sphere replaces the flat: its rod-E and rod-nu are not read then.
  std::vector<std::string_view> unread(std::begin(not_read), std::end(not_read));
  if (s.second) unread.insert(unread.end(), {"rod-E", "rod-nu"});
  r.inputs = describe_rig_run(setup, s.law, s.solver, unread);
  for (const auto& [decl, value] : {std::pair{incidence_angle, s.incidence_angle_deg}, {friction, s.friction},
                                    {spin, s.spin_rad_per_s}, {inertia_factor, s.inertia_factor},
                                    {tangential_damping, s.tangential_damping_ratio}})
    r.inputs.emplace_back(input_column(decl), fmt::format("{}", value));
  r.inputs.emplace_back(input_column(tangential_model), s.tangential_model);
  if (s.linear_stiffness_N_per_m) r.inputs.emplace_back(input_column(tangential_stiffness), fmt::format("{}", *s.linear_stiffness_N_per_m));
  if (find_tangential_model(s.tangential_model)->resolves_contact_area)
    r.inputs.emplace_back(input_column(contact_cells), fmt::format("{}", s.contact_cells));
  if (s.second)
    for (const auto& [decl, value] : {std::pair{sphere2::radius, s.second->radius_m}, {sphere2::E, s.second->material.E_Pa},
                                      {sphere2::nu, s.second->material.nu}, {sphere2::mass, s.second->mass_kg},
                                      {second_spin, s.second->spin_rad_per_s}, {second_inertia_factor, s.second->inertia_factor}})
      r.inputs.emplace_back(input_column(decl), fmt::format("{}", value));
  r.run.impacts.push_back({s.speed_mps, s.incidence_angle_deg});
  return r;
}

RigResult outcome(const Run& r) {
  std::vector<std::string> warnings;
  // The tangential force can only take energy from the sphere's sliding and spin: positive work
  // is the model creating it (an incremental spring whose stiffness falls while it unloads returns
  // more than it stored; docs/oblique.md).
  if (r.result.tangential_work_J > 0)
    warnings.push_back(fmt::format("the tangential force did positive work on the sphere, {:.3g} J: the tangential model {} "
                                   "created energy (docs/oblique.md)",
                                   r.result.tangential_work_J, r.spec.tangential_model));
  return {.heading = fmt::format("a sphere at {} deg, damping law '{}', tangential model {}, mu = {}", r.spec.incidence_angle_deg,
                                 r.spec.law, r.spec.tangential_model, r.spec.friction),
          .scalars = {}, .rows = {}, .warnings = warnings,
          .end_reason = r.result.separated ? "the sphere separated" : "the sphere did not separate",
          .work = r.result.work, .inputs = r.inputs};
}

using V = RigValue;
constexpr RigFieldOf<Run> results[] = {
    {{"damping", "", "the normal damping law", false, false, false}, [](const Run& r) -> V { return r.spec.law; }},
    {{"tangential_model", "", "the tangential contact model", false, false, false},
     [](const Run& r) -> V { return r.spec.tangential_model; }},
    {{"normal_restitution", "1", "normal rebound over approach speed"}, [](const Run& r) -> V { return r.result.normal_restitution; }},
    {{"tangential_restitution", "1", "the centre's tangential velocity after over before, relative to the second sphere if any (null head-on)"},
     [](const Run& r) -> V { return r.result.tangential_restitution; }},
    {{"rebound_angle_deg", "deg", "the contact point's velocity after, from the normal: atan(s / v_n)"},
     [](const Run& r) -> V { return r.result.rebound_angle_deg; }},
    {{"centre_rebound_angle_deg", "deg", "the centre's velocity after, from the normal (relative to the second sphere if any)"},
     [](const Run& r) -> V { return r.result.centre_rebound_angle_deg; }},
    {{"tangential_velocity_after_mps", "m/s", "the centre's tangential velocity after (the first sphere's, the second at rest before)"},
     [](const Run& r) -> V { return r.result.tangential_velocity_after_mps; }},
    {{"rebound_angular_velocity_rad_per_s", "rad/s", "the sphere's spin after (the contact point slides at w + R omega)"},
     [](const Run& r) -> V { return r.result.spin_after_rad_per_s; }},
    {{"second_tangential_velocity_after_mps", "m/s", "the second sphere's tangential velocity after (null on a flat)"},
     [](const Run& r) -> V { return r.spec.second ? V(r.result.second_tangential_velocity_after_mps) : V(); }},
    {{"second_rebound_angular_velocity_rad_per_s", "rad/s", "the second sphere's spin after (null on a flat)"},
     [](const Run& r) -> V { return r.spec.second ? V(r.result.second_spin_after_rad_per_s) : V(); }},
    {{"contact_time_s", "s", "onset to separation"}, [](const Run& r) -> V { return r.result.contact_time_s; }},
    {{"peak_normal_force_N", "N", "largest normal contact force"}, [](const Run& r) -> V { return r.result.peak_normal_force_N; }},
    {{"sliding_fraction", "1", "of the contact time on the Coulomb cone (sliding)"},
     [](const Run& r) -> V { return r.result.sliding_fraction; }},
    {{"tangential_work_J", "J", "the tangential force's work on the sphere, int T s dt"},
     [](const Run& r) -> V { return r.result.tangential_work_J; }},
    {{"tangential_stiffness_N_per_m", "N/m", "the linear spring's k_t, given or matched (linear-spring; null otherwise)"},
     [](const Run& r) -> V { return r.spec.tangential_model == "linear-spring" ? V(r.result.linear_stiffness_N_per_m) : V(); }},
};

constexpr RigColumnOf<ObliqueRow> table[] = {
    {{"impact_speed_mps", "m/s", "the sphere's speed at onset"}, [](const ObliqueRow& i) { return i.speed_mps; }},
    {{"impact_angle_deg", "deg", "its angle from the normal"}, [](const ObliqueRow& i) { return i.incidence_angle_deg; }},
};

}  // namespace

const Rig& oblique_rig() {
  static const Rig rig = make_rig<Run, ObliqueRow>(
      {.name = "oblique",
       .summary = "A sphere onto a flat (or a second sphere) at an incidence angle, with friction and spin: any damping "
                  "law normal to the contact, any tangential model along it",
       .inputs = inputs, .run_options_not_read = not_read, .not_read_because = why_not_read, .run_option_notes = notes,
       .default_integrator = {}, .refuse = refuse, .results = results,
       .table_description = "the impact (the sphere's speed and angle at onset)", .table = table, .run = run, .outcome = outcome,
       .regularized_contacts = false});
  return rig;
}

}  // namespace hertzdash
