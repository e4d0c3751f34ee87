// The rig `walls` (simulation/rigs/walls_rig.hpp).
#include "hertzdash/simulation/rigs/walls_rig.hpp"

#include "hertzdash/model/shaker_parameters.hpp"
#include "hertzdash/model/two_walls_parameters.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/rigs/rig_work_bound.hpp"
#include "hertzdash/simulation/rigs/shaker_rig.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/shaker/two_walls.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hertzdash {

namespace {

namespace s = shaker_parameters;
namespace p = two_walls_parameters;

constexpr std::string_view not_read[] = {"height", "impact-velocity"};
// What Newton's law at an instantaneous impact reads of a run's options: the driven box's, and
// the damper's (its primary's response to the momentum exchange reads the body's mass).
constexpr std::string_view box_reads[] = {"rod", "restitution", "gravity"};
constexpr std::string_view damper_reads[] = {"rod", "restitution", "gravity", "mass"};

struct Run {
  DropTestSetup setup;
  std::string law;
  SolverSettings solver;
  TwoWallsOptions options;
  Parameters inputs;  ///< describe_run() and the two walls' options
  TwoWallsRun run;
};

/// Refuse an input given where the rig does not read it.
void refuse_unless(bool read, const RigInputs& in, const ParameterDecl& d, std::string_view rig) {
  if (!read && in.number(d.key))
    throw InvalidParameter(std::string(d.key), format_value(*in.number(d.key)), fmt::format("not given with `rig` {}", rig));
}

/// The inputs of the other variant, `gamma` with `amplitude`, `gamma` with `gravity` 0, options
/// the instantaneous model does not read (Rig::refuse: checked before any run).
void refuse(const RunOptions& options, const RigInputs& in) {
  const TwoWallsRig variant = parse_two_walls_rig(in.text("rig").value_or(std::string(p::rig.default_value)));
  const bool box = variant == TwoWallsRig::box;
  const std::string_view rig = to_string(variant);
  for (const ParameterDecl* d : {&s::amplitude, &p::gamma}) refuse_unless(box, in, *d, rig);
  for (const ParameterDecl* d : {&p::primary_mass, &p::primary_stiffness, &p::primary_damping_ratio, &p::force_amplitude})
    refuse_unless(!box, in, *d, rig);
  if (in.number("amplitude") && in.number("gamma"))
    throw InvalidParameter("gamma", format_value(*in.number("gamma")), "omitted with `amplitude` (one sets the other)");
  if (box && !in.number("amplitude") && options.gravity_mps2 && *options.gravity_mps2 == 0)
    throw InvalidParameter("gamma", format_value(in.number_or_default(p::gamma)),
                           "omitted with `gravity` 0 (gamma is in units of g): give `amplitude`");
  refuse_trace_only_options(options, "hertzdash walls");
  const std::string model = in.text("impact-model").value_or(std::string(s::impact_model.default_value));
  if (parse_shaker_impact_model(model) == ShakerImpactModel::instantaneous) {  // Newton's law reads e, the flights g, momentum m
    RunOptions defaults;
    defaults.integrator = shaker_default_integrator;
    refuse_options_not_read(options, defaults, box ? std::span<const std::string_view>(box_reads) : damper_reads,
                            box ? "`impact-model` soft (the instantaneous box reads `restitution` and `gravity`)"
                                : "`impact-model` soft (the instantaneous damper reads `restitution`, `gravity` and "
                                  "`mass`)");
  }
}

// Resolve and validate, without running (`run` left empty but for its rig and impact model).
Run resolve(const RunOptions& options, const PaperParameters& paper, const RigInputs& in) {
  Run r;
  TwoWallsOptions& o = r.options;
  o.rig = parse_two_walls_rig(in.text("rig").value_or(std::string(p::rig.default_value)));
  const bool box = o.rig == TwoWallsRig::box;
  const std::string_view rig = to_string(o.rig);
  o.gap_m = in.number_or_default(p::gap);
  o.impact_model = parse_shaker_impact_model(in.text("impact-model").value_or(std::string(s::impact_model.default_value)));
  o.drive.frequency_Hz = in.number_or_default(s::frequency);
  const double w = o.drive.omega_rad_per_s();
  // The set-up's representative approach speed (its Hertz-scale check; a viscoelastic law's
  // calibration without `reference-velocity`) is the drop test's sqrt(2 g h); with g = 0 (a
  // horizontal box) it is the box's speed scale: A w, or the bare primary's steady amplitude times w.
  RunOptions set_up = options;
  const bool horizontal = options.gravity_mps2 && *options.gravity_mps2 == 0;
  double speed_scale_mps = 0;
  if (box) {
    if (in.number("amplitude")) o.drive.amplitude_m = *in.number("amplitude");
    speed_scale_mps = o.drive.amplitude_m * w;
  } else {
    o.primary.mass_kg = in.number_or_default(p::primary_mass);
    o.primary.stiffness_N_per_m = in.number_or_default(p::primary_stiffness);
    o.primary.damping_ratio = in.number_or_default(p::primary_damping_ratio);
    o.primary.force_amplitude_N = in.number_or_default(p::force_amplitude);
    ForcedOscillator bare = o.primary;
    bare.omega_rad_per_s = w;
    speed_scale_mps = bare.steady_amplitude_m() * w;
  }
  if (horizontal) {
    if (!(speed_scale_mps > 0))
      throw InvalidParameter(box ? "amplitude" : "force-amplitude",
                             format_value(box ? o.drive.amplitude_m : o.primary.force_amplitude_N),
                             "> 0 with `gravity` 0 (nothing would move the body)");
    // Soft impacts: the box's speed scale is the set-up's approach speed (its Hertz-scale check, a
    // viscoelastic law's calibration). Newton's law has no contact scale: a nominal 1 m/s carries
    // the set-up (the undamped damper at resonance is a classic, not a contact beyond Hertz).
    const bool soft = o.impact_model == ShakerImpactModel::soft;
    set_up.impact_velocity_mps = soft ? speed_scale_mps : 1.0;
    set_up.impact_velocity_origin =
        soft ? fmt::format("the box's speed scale {} with `gravity` 0", box ? "A (2 pi f)" : "(the bare primary's steady amplitude) (2 pi f)")
             : "a nominal 1 m/s (instantaneous impacts have no contact scale)";
  }
  r.setup = resolve_setup(set_up, paper);
  r.law = options.damping;
  r.solver = resolve_solver(options);
  const SolverSettings& solver = r.solver;
  if (box && !in.number("amplitude"))
    o.drive.amplitude_m = amplitude_from_gamma(in.number_or_default(p::gamma), o.drive.frequency_Hz, r.setup.gravity_mps2);
  o.impacts = static_cast<int>(in.number_or_default(s::impacts));
  o.transient = static_cast<int>(in.number_or_default(s::transient));
  // The work bound (rig_work_bound.hpp): the drive period, the fall across the gap (at the box's
  // speed scale with g = 0), the primary's natural period, the soft contact at the speed scale.
  const double g = r.setup.gravity_mps2;
  if (box) speed_scale_mps = o.drive.amplitude_m * w;
  std::vector<RigTimeScale> scales{
      drive_period_scale(o.drive.frequency_Hz, in.number("frequency").has_value()),
      {.what = g > 0 ? "the fall across the gap sqrt(2 gap / g)" : "the crossing of the gap at the box's speed",
       .seconds = g > 0 ? std::sqrt(2 * o.gap_m / g) : o.gap_m / speed_scale_mps, .key = "gap", .value = o.gap_m,
       .given = in.number("gap").has_value()}};
  if (!box) {
    const bool mass = in.number("primary-mass") && !in.number("primary-stiffness");
    scales.push_back(natural_period_scale("the primary's", o.primary.mass_kg, o.primary.stiffness_N_per_m,
                                          mass ? "primary-mass" : "primary-stiffness",
                                          mass ? o.primary.mass_kg : o.primary.stiffness_N_per_m,
                                          in.number("primary-mass") || in.number("primary-stiffness")));
  }
  if (o.impact_model == ShakerImpactModel::soft)
    scales.push_back(hertz_contact_time_scale(r.setup, std::max(speed_scale_mps, g / o.drive.frequency_Hz),
                                              options.mass_kg.has_value()));
  require_bounded_rig_work(scales, o.impacts, o.transient, in.number("impacts").has_value());
  r.inputs = describe_rig_run(r.setup, r.law, solver, not_read);
  r.inputs.emplace_back("rig", std::string(rig));
  r.inputs.emplace_back("gap_m", fmt::format("{}", o.gap_m));
  r.inputs.emplace_back("frequency_Hz", fmt::format("{}", o.drive.frequency_Hz));
  if (box) {
    r.inputs.emplace_back("amplitude_m", fmt::format("{}", o.drive.amplitude_m));
  } else {
    r.inputs.emplace_back("primary_mass_kg", fmt::format("{}", o.primary.mass_kg));
    r.inputs.emplace_back("primary_stiffness_N_per_m", fmt::format("{}", o.primary.stiffness_N_per_m));
    r.inputs.emplace_back("primary_damping_ratio", fmt::format("{}", o.primary.damping_ratio));
    r.inputs.emplace_back("force_amplitude_N", fmt::format("{}", o.primary.force_amplitude_N));
  }
  r.inputs.emplace_back("impacts", std::to_string(o.impacts));
  r.inputs.emplace_back("transient", std::to_string(o.transient));
  r.inputs.emplace_back("impact_model", to_string(o.impact_model));
  r.run.rig = o.rig;
  r.run.impact_model = o.impact_model;
  return r;
}

Run run(const RunOptions& options, const PaperParameters& paper, const RigInputs& in) {
  Run r = resolve(options, paper, in);
  r.run = run_two_walls(r.setup, r.law, r.solver, r.options);
  return r;
}

bool soft(const Run& r) { return r.run.impact_model == ShakerImpactModel::soft; }
bool box(const Run& r) { return r.run.rig == TwoWallsRig::box; }

RigResult outcome(const Run& r) { return sequence_outcome(r, box(r) ? "driven box, " : "impact damper, "); }

RigSequence sequence(const RunOptions& options, const PaperParameters& paper, const RigInputs& in) {
  const Run r = resolve(options, paper, in);
  return {make_two_walls_sequence(r.setup, r.law, r.solver, r.options), outcome(r).heading, r.inputs};
}

/// A number the run has only where `has` holds.
RigValue only(bool has, double v) { return has ? RigValue(v) : RigValue(); }
/// The damper's energy account, with instantaneous impacts.
RigValue energy(const Run& r, double EnergyAccount::*member) { return only(!box(r) && !soft(r), r.run.energy.*member); }

constexpr RigFieldOf<Run> results[] = {
    {{"rig", "", "box or damper", false, false, false}, [](const Run& r) -> RigValue { return std::string(to_string(r.run.rig)); }},
    {{"gap_m", "m", "the body's free travel between the walls"}, [](const Run& r) -> RigValue { return r.options.gap_m; }},
    {{"frequency_Hz", "Hz", "the drive's frequency f"}, [](const Run& r) -> RigValue { return r.options.drive.frequency_Hz; }},
    {{"amplitude_m", "m", "the box's amplitude A (box)"},
     [](const Run& r) { return only(box(r), r.options.drive.amplitude_m); }},
    {{"gamma", "1", "A (2 pi f)^2 / g (box; null with g = 0)", false},
     [](const Run& r) { return only(box(r), shaker_gamma(r.options.drive, r.setup.gravity_mps2)); }},
    SequenceFields<Run>::impact_model, SequenceFields<Run>::damping, SequenceFields<Run>::integrator_used,
    {{"period", "", "the detected period in drive cycles (0: none)"}, [](const Run& r) -> RigValue { return long{r.run.pattern.period}; }},
    SequenceFields<Run>::impacts_per_period,
    {{"impacts_per_cycle", "1", "impacts per drive cycle (0: no period)"},
     [](const Run& r) -> RigValue { return r.run.impacts_per_cycle; }},
    {{"floor_impacts", "", "kept impacts on the floor"}, [](const Run& r) -> RigValue { return r.run.floor_impacts; }},
    {{"ceiling_impacts", "", "kept impacts on the ceiling"}, [](const Run& r) -> RigValue { return r.run.ceiling_impacts; }},
    {{"e_effective", "1", "mean rebound over impact speed, relative to the box, of the kept impacts (null: none)"},
     [](const Run& r) -> RigValue { return r.run.e_effective; }},
    {{"primary_amplitude_m", "m", "the primary's amplitude with the body (damper)"},
     [](const Run& r) { return only(!box(r), r.run.primary_amplitude_m); }},
    {{"primary_amplitude_bare_m", "m", "the primary's steady amplitude alone (damper)"},
     [](const Run& r) { return only(!box(r), r.run.primary_amplitude_bare_m); }},
    {{"primary_amplitude_rigid_m", "m", "the steady amplitude of mass M + m, the body carried (damper)"},
     [](const Run& r) { return only(!box(r), r.run.primary_amplitude_rigid_m); }},
    {{"energy_J.initial", "J", "the energy at the start (damper, instantaneous impacts)", false},
     [](const Run& r) { return energy(r, &EnergyAccount::initial_J); }},
    {{"energy_J.final", "J", "the energy at the end", false}, [](const Run& r) { return energy(r, &EnergyAccount::final_J); }},
    {{"energy_J.drive_work", "J", "the drive's work", false},
     [](const Run& r) { return energy(r, &EnergyAccount::drive_work_J); }},
    {{"energy_J.damping_dissipation", "J", "the primary's damping loss", false},
     [](const Run& r) { return energy(r, &EnergyAccount::damping_dissipation_J); }},
    {{"energy_J.impact_loss", "J", "the impacts' loss", false},
     [](const Run& r) { return energy(r, &EnergyAccount::impact_loss_J); }},
    {{"sticking_episodes", "", "times a wall carried the body", true, true},
     [](const Run& r) -> RigValue { return r.run.sticking_episodes; }},
    SequenceFields<Run>::impacts_run,
};

constexpr RigColumnOf<TwoWallsImpact> table[] = {
    {{"impact_time_s", "s", "impact (contact onset) time from the start"}, [](const TwoWallsImpact& i) { return i.time_s; }},
    {{"impact_phase", "1", "phase of the drive sin(2 pi f t) in [0, 1)"}, [](const TwoWallsImpact& i) { return i.phase; }},
    {{"wall", "", "the wall hit: 0 floor, 1 ceiling", "floor, ceiling", true},
     [](const TwoWallsImpact& i) { return static_cast<double>(i.wall); }},
    {{"impact_speed_mps", "m/s", "impact speed relative to the box"},
     [](const TwoWallsImpact& i) { return i.impact_speed_mps; }},
    {{"rebound_speed_mps", "m/s", "rebound speed relative to the box"},
     [](const TwoWallsImpact& i) { return i.rebound_speed_mps; }},
    {{"contact_time_s", "s", "contact duration (0: instantaneous)"}, [](const TwoWallsImpact& i) { return i.contact_time_s; }},
    {{"peak_force_N", "N", "largest contact force (0: instantaneous)"}, [](const TwoWallsImpact& i) { return i.peak_force_N; }},
    {{"box_displacement_m", "m", "the box's displacement X at the impact"},
     [](const TwoWallsImpact& i) { return i.box_displacement_m; }},
};

constexpr ParameterDecl inputs[] = {p::rig,           p::gap,         s::frequency,       s::amplitude,
                                    p::gamma,         p::primary_mass, p::primary_stiffness, p::primary_damping_ratio,
                                    p::force_amplitude, s::impacts,   s::transient,       s::impact_model};
constexpr RigOptionNote notes[] = {shaker_integrator_note};

}  // namespace

const Rig& walls_rig() {
  static const Rig rig = make_rig<Run, TwoWallsImpact>(
      {.name = "walls",
       .summary = "A body between two walls: a harmonically driven box, or the impact damper (a box on a primary "
                  "oscillator under a harmonic force); exact flights",
       .inputs = inputs, .run_options_not_read = not_read, .not_read_because = "the body starts at rest at mid-gap",
       .run_option_notes = notes, .default_integrator = shaker_default_integrator,
       .instantaneous_reads = damper_reads,  // `orbit walls` takes either; `refuse` keeps `mass` from the box
       .refuse = refuse, .results = results,
       .table_description = "one row per kept impact (time from the start, the body at rest at mid-gap; phase of the "
                            "drive sin(2 pi f t) in [0,1); wall 0 floor, 1 ceiling; speeds relative to the box)",
       .table = table, .run = run, .outcome = outcome, .sequence = sequence});
  return rig;
}

}  // namespace hertzdash
