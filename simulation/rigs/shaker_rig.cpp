// The rig `shaker` (simulation/rigs/shaker_rig.hpp).
#include "hertzdash/simulation/rigs/shaker_rig.hpp"

#include "hertzdash/model/shaker_parameters.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/rigs/rig_work_bound.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <vector>

namespace hertzdash {

namespace {

constexpr std::string_view not_read[] = {"impact-velocity"};
// What Newton's law at an instantaneous impact reads of a run's options.
constexpr std::string_view instantaneous_reads[] = {"rod", "restitution", "gravity", "height"};
constexpr std::string_view starts = "the body starts at rest, at `height` above the wall's mean position";

// A shaker run: its resolved set-up, law, solver and options, its inputs and its outcome.
struct ShakerCommandRun {
  DropTestSetup setup;
  std::string law;
  SolverSettings solver;
  ShakerOptions options;
  Parameters inputs;  // describe_run() and the shaker's options
  ShakerRun run;
};

// The shaker's refusals before any run (Rig::refuse): `amplitude` with `gamma`, an option of a
// trace, an option the instantaneous map does not read.
void refuse_shaker_inputs(const RunOptions& options, const RigInputs& in) {
  namespace p = shaker_parameters;
  if (in.number("amplitude") && in.number("gamma"))
    throw InvalidParameter("gamma", format_value(*in.number("gamma")), "omitted with `amplitude` (one sets the other)");
  refuse_trace_only_options(options, "hertzdash shaker");
  // Without gravity a body the wall throws off never comes back (the drop test's own refusal
  // would name `impact-velocity`, which the shaker does not read).
  if (options.gravity_mps2 && !(*options.gravity_mps2 > 0))
    throw InvalidParameter("gravity", format_value(*options.gravity_mps2),
                           "> 0 for the shaker: gravity returns the body to the wall, without it no impact follows");
  const std::string model = in.text("impact-model").value_or(std::string(p::impact_model.default_value));
  if (parse_shaker_impact_model(model) == ShakerImpactModel::instantaneous) {  // Newton's law reads e, the flights g
    RunOptions defaults;
    defaults.integrator = shaker_default_integrator;
    refuse_options_not_read(options, defaults, instantaneous_reads,
                            "`impact-model` soft (the instantaneous map reads `restitution`, `gravity` and `height`)");
  }
}

// Resolve and validate, without running (`run` left empty).
ShakerCommandRun resolve_shaker_command(const RunOptions& options, const PaperParameters& paper, const RigInputs& in) {
  namespace p = shaker_parameters;
  refuse_shaker_inputs(options, in);
  ShakerCommandRun r;
  // `height` (the start's, 0: at rest on the wall) is where a viscoelastic law is calibrated, unless 0.
  RunOptions body = options;
  if (body.height_m == 0.0) body.height_m.reset();
  r.setup = resolve_setup(body, paper);
  r.law = options.damping;
  r.solver = resolve_solver(options);
  ShakerOptions& o = r.options;
  o.wall.frequency_Hz = in.number_or_default(p::frequency);
  o.wall.amplitude_m = in.number("amplitude")
                           ? in.number_or_default(p::amplitude)
                           : amplitude_from_gamma(in.number("gamma").value_or(period_one_middle_gamma(r.setup.restitution)),
                                                  o.wall.frequency_Hz, r.setup.gravity_mps2);
  o.impacts = static_cast<int>(in.number_or_default(p::impacts));
  o.transient = static_cast<int>(in.number_or_default(p::transient));
  o.start_height_m = options.height_m;
  o.start_phase = in.number("start-phase");
  o.impact_model = parse_shaker_impact_model(in.text("impact-model").value_or(std::string(p::impact_model.default_value)));
  r.inputs = describe_rig_run(r.setup, r.law, r.solver, not_read);
  r.inputs.emplace_back("frequency_Hz", fmt::format("{}", o.wall.frequency_Hz));
  r.inputs.emplace_back("amplitude_m", fmt::format("{}", o.wall.amplitude_m));
  r.inputs.emplace_back("impacts", std::to_string(o.impacts));
  r.inputs.emplace_back("transient", std::to_string(o.transient));
  r.inputs.emplace_back("impact_model", to_string(o.impact_model));
  // The work bound (rig_work_bound.hpp): the drive period, a flight after a take-off at the
  // wall's peak speed, the soft contact at the speed one drive period of fall gives.
  const double T = o.wall.period_s(), g = r.setup.gravity_mps2, take_off_mps = o.wall.amplitude_m * o.wall.omega_rad_per_s();
  const bool amplitude = in.number("amplitude").has_value();
  std::vector<RigTimeScale> scales{
      drive_period_scale(o.wall.frequency_Hz, in.number("frequency").has_value()),
      {.what = "a flight after a take-off at the wall's peak speed, 2 A (2 pi f)/g", .seconds = 2 * take_off_mps / g,
       .key = amplitude ? "amplitude" : "gamma", .value = amplitude ? o.wall.amplitude_m : shaker_gamma(o.wall, g),
       .given = amplitude || in.number("gamma"), .resolved = false}};
  if (o.impact_model == ShakerImpactModel::soft)
    scales.push_back(hertz_contact_time_scale(r.setup, g * T, options.mass_kg.has_value()));
  require_bounded_rig_work(scales, o.impacts, o.transient, in.number("impacts").has_value());
  const ShakerStart start = shaker_start(o, r.setup.restitution, r.setup.gravity_mps2);
  r.inputs.emplace_back("start_height_m", fmt::format("{}", start.height_m));
  r.inputs.emplace_back("start_phase", fmt::format("{}", start.phase));
  return r;
}

using Run = ShakerCommandRun;

ShakerCommandRun run(const RunOptions& options, const PaperParameters& paper, const RigInputs& in) {
  ShakerCommandRun r = resolve_shaker_command(options, paper, in);
  r.run = run_shaker(r.setup, r.law, r.solver, r.options);
  return r;
}

RigResult outcome(const Run& r) { return sequence_outcome(r); }

RigSequence sequence(const RunOptions& options, const PaperParameters& paper, const RigInputs& in) {
  ShakerCommandRun r = resolve_shaker_command(options, paper, in);
  r.run.impact_model = r.options.impact_model;
  return {make_shaker_sequence(r.setup, r.law, r.solver, r.options), sequence_outcome(r).heading, r.inputs};
}

constexpr RigFieldOf<Run> results[] = {
    {{"gamma", "1", "the wall's peak acceleration over g, A (2 pi f)^2 / g"}, [](const Run& r) -> RigValue { return r.run.gamma; }},
    {{"frequency_Hz", "Hz", "the wall's frequency f"}, [](const Run& r) -> RigValue { return r.options.wall.frequency_Hz; }},
    {{"amplitude_m", "m", "the wall's amplitude A"}, [](const Run& r) -> RigValue { return r.options.wall.amplitude_m; }},
    SequenceFields<Run>::impact_model, SequenceFields<Run>::damping, SequenceFields<Run>::integrator_used,
    {{"period", "", "the detected period in table cycles (0: none)"}, [](const Run& r) -> RigValue { return long{r.run.pattern.period}; }},
    SequenceFields<Run>::impacts_per_period,
    {{"e_effective", "1", "mean rebound over impact speed, relative to the wall, of the kept impacts (null: none)"},
     [](const Run& r) -> RigValue { return r.run.e_effective; }},
    {{"sticking_episodes", "", "times the wall carried the body", true, true},
     [](const Run& r) -> RigValue { return r.run.sticking_episodes; }},
    SequenceFields<Run>::impacts_run,
};

constexpr RigOptionNote notes[] = {
    shaker_integrator_note,
    {"gravity", "Gravity g [m/s^2] > 0, which returns the body to the wall (default: 9.80665; standard gravity)"},
    {"height", "Height [m] above the wall's mean position from which the body is released at rest at --start-phase; "
               "0: at rest on the wall (default: the apex of the instantaneous map's period-1 orbit, docs/shaker.md)"}};

}  // namespace

double amplitude_from_gamma(double gamma, double frequency_Hz, double gravity_mps2) {
  const double A = shaker_amplitude_m(gamma, frequency_Hz, gravity_mps2);
  if (std::isfinite(A) && (A >= std::numeric_limits<double>::min() || gamma * gravity_mps2 == 0)) return A;
  throw InvalidParameter(
      "frequency", format_value(frequency_Hz),
      fmt::format("such that the amplitude A = gamma g / (2 pi f)^2 is a number double precision holds: with gamma = "
                  "{:.6g} it is {} m",
                  gamma, A == 0 ? "below 1e-308" : format_value(A)));
}

const Rig& shaker_rig() {
  static const Rig rig = make_rig<Run, ShakerImpact>(
      {.name = "shaker",
       .summary = "A body bouncing on a vibrating wall: soft contacts or instantaneous impacts, exact flights",
       .inputs = shaker_parameters::all, .run_options_not_read = not_read, .not_read_because = starts,
       .run_option_notes = notes, .default_integrator = shaker_default_integrator,
       .instantaneous_reads = instantaneous_reads, .refuse = refuse_shaker_inputs, .results = results,
       .table_description = "one row per kept impact (time from the start, the body at rest on the wall; phase of "
                            "s(t) = A sin(2 pi f t) in [0,1); speeds relative to the wall)",
       .table = one_wall_impact_table, .run = run, .outcome = outcome, .sequence = sequence});
  return rig;
}

}  // namespace hertzdash
