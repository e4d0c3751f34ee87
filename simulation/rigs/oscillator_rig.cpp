// The impact oscillator with a stop and its rig `oscillator` (simulation/rigs/oscillator_rig.hpp).
#include "hertzdash/simulation/rigs/oscillator_rig.hpp"

#include "hertzdash/model/shaker_parameters.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/rigs/rig_work_bound.hpp"
#include "hertzdash/simulation/rigs/shaker_rig.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/shaker/harmonic_soft_contacts.hpp"

#include <fmt/format.h>

#include <limits>
#include <numbers>
#include <vector>

namespace hertzdash {

namespace {

using R = NumberRange;
constexpr R finite = R::open(-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity());
constexpr ParameterDecl stiffness{.key = "stiffness", .unit = "N/m", .column_unit = "N_per_m", .range = R::positive(),
    .default_value = "10000", .default_number = 1e4, .default_source = "chosen: 18 Hz with the paper's steel rod",
    .help = "Stiffness k of the body's spring [N/m]"};
constexpr ParameterDecl damping_ratio{.key = "damping-ratio", .range = R::closed_open(0, 1), .default_value = "0.05",
    .default_number = 0.05, .default_source = "chosen", .help = "Damping ratio zeta, c = 2 zeta sqrt(k m), in [0, 1)"};
constexpr ParameterDecl force_amplitude{.key = "force-amplitude", .unit = "N", .column_unit = "N",
    .range = R::non_negative(), .default_value = "10", .default_number = 10, .default_source = "chosen",
    .help = "Amplitude F of the force F cos(2 pi f t) on the body [N]"};
constexpr ParameterDecl frequency{.key = "frequency", .unit = "Hz", .column_unit = "Hz", .range = R::positive(),
    .default_value = "20", .default_number = 20, .default_source = "chosen", .help = "Frequency f of the force [Hz]"};
constexpr ParameterDecl stop_distance{.key = "stop-distance", .unit = "m", .column_unit = "m", .range = R::positive(),
    .default_value = "0.002", .default_number = 0.002, .default_source = "chosen",
    .help = "Distance d of the stop from the spring's rest position [m]"};
constexpr ParameterDecl start_position{.key = "start-position", .unit = "m", .column_unit = "m", .range = finite,
    .default_value = "0", .default_number = 0, .default_source = "chosen", .help = "x0 at t = 0, below d [m]"};
constexpr ParameterDecl start_velocity{.key = "start-velocity", .unit = "m/s", .column_unit = "mps", .range = finite,
    .default_value = "0", .default_number = 0, .default_source = "chosen", .help = "x0' at t = 0 [m/s]"};
namespace s = shaker_parameters;
constexpr ParameterDecl inputs[] = {stiffness,      damping_ratio,  force_amplitude, frequency,  stop_distance,
                                    start_position, start_velocity, s::impacts,      s::transient, s::impact_model};

constexpr std::string_view not_read[] = {"height", "impact-velocity", "gravity"};
// What Newton's law at an instantaneous impact reads of a run's options.
constexpr std::string_view instantaneous_reads[] = {"rod", "restitution", "mass"};

struct Run {
  DropTestSetup setup;
  std::string law;
  SolverSettings solver;
  OscillatorOptions options;
  Parameters inputs;  ///< describe_run() and the oscillator's options
  OscillatorRun run;
};

/// Options of a trace, and with instantaneous impacts the options they do not read (Rig::refuse).
void refuse(const RunOptions& options, const RigInputs& in) {
  refuse_trace_only_options(options, "hertzdash oscillator");
  const std::string model = in.text("impact-model").value_or(std::string(s::impact_model.default_value));
  if (parse_shaker_impact_model(model) == ShakerImpactModel::instantaneous) {  // Newton's law reads e, the flights m
    RunOptions defaults;
    defaults.integrator = shaker_default_integrator;
    refuse_options_not_read(options, defaults, instantaneous_reads, "`impact-model` soft (instantaneous impacts read `restitution` and `mass`)");
  }
}

// Resolve and validate, without running (`run` left empty but for its impact model).
Run resolve(const RunOptions& options, const PaperParameters& paper, const RigInputs& in) {
  Run r{.setup = resolve_setup(options, paper), .law = options.damping, .solver = resolve_solver(options),
        .options = {}, .inputs = {}, .run = {}};
  const SolverSettings& solver = r.solver;
  OscillatorOptions& o = r.options;
  double* numbers[] = {&o.stiffness_N_per_m, &o.damping_ratio,   &o.force_amplitude_N, &o.frequency_Hz,
                       &o.stop_distance_m,   &o.start_position_m, &o.start_velocity_mps};
  r.inputs = describe_rig_run(r.setup, r.law, solver, not_read);
  for (std::size_t i = 0; i < std::size(numbers); ++i) {
    *numbers[i] = in.number_or_default(inputs[i]);
    r.inputs.emplace_back(input_column(inputs[i]), fmt::format("{}", *numbers[i]));
  }
  o.impacts = static_cast<int>(in.number_or_default(s::impacts));
  o.transient = static_cast<int>(in.number_or_default(s::transient));
  o.impact_model = parse_shaker_impact_model(in.text("impact-model").value_or(std::string(s::impact_model.default_value)));
  r.inputs.emplace_back(input_column(s::impacts), std::to_string(o.impacts));
  r.inputs.emplace_back(input_column(s::transient), std::to_string(o.transient));
  r.inputs.emplace_back(input_column(s::impact_model), to_string(o.impact_model));
  // The work bound (rig_work_bound.hpp): the drive period, the body's natural period, the soft
  // contact at the spec's speed scale (F + k d)/(m f).
  const double m = r.setup.mass_kg;
  std::vector<RigTimeScale> scales{
      drive_period_scale(o.frequency_Hz, in.number("frequency").has_value()),
      natural_period_scale("the body's", m, o.stiffness_N_per_m, "stiffness", o.stiffness_N_per_m,
                           in.number("stiffness").has_value())};
  if (o.impact_model == ShakerImpactModel::soft)
    scales.push_back(hertz_contact_time_scale(
        r.setup, (o.force_amplitude_N + o.stiffness_N_per_m * o.stop_distance_m) / (m * o.frequency_Hz),
        options.mass_kg.has_value()));
  require_bounded_rig_work(scales, o.impacts, o.transient, in.number("impacts").has_value());
  r.run.impact_model = o.impact_model;
  return r;
}

Run run(const RunOptions& options, const PaperParameters& paper, const RigInputs& in) {
  Run r = resolve(options, paper, in);
  r.run = run_oscillator(r.setup, r.law, r.solver, r.options);
  return r;
}

RigSequence sequence(const RunOptions& options, const PaperParameters& paper, const RigInputs& in) {
  const Run r = resolve(options, paper, in);
  return {make_oscillator_sequence(r.setup, r.law, r.solver, r.options), sequence_outcome(r).heading, r.inputs};
}

RigResult outcome(const Run& r) { return sequence_outcome(r); }

using F = SequenceFields<Run>;
constexpr RigFieldOf<Run> results[] = {
    F::impact_model, F::damping, F::integrator_used,
    {{"period", "", "the detected period in drive cycles (0: none)"}, [](const Run& r) -> RigValue { return long{r.run.pattern.period}; }},
    F::impacts_per_period,
    {{"e_effective", "1", "mean rebound over impact speed of the kept impacts (null: none)"}, [](const Run& r) -> RigValue { return r.run.e_effective; }},
    {{"amplitude_m", "m", "the body's (max x - min x)/2 over the kept window"}, [](const Run& r) -> RigValue { return r.run.amplitude_m; }},
    {{"peak_phase", "1", "the drive phase of the body's largest x over the kept window"}, [](const Run& r) -> RigValue { return r.run.peak_phase; }},
    {{"steady_amplitude_m", "m", "the steady amplitude without the stop (closed form)"}, [](const Run& r) -> RigValue { return r.run.steady_amplitude_m; }},
    {{"energy_J.drive_work", "J", "the force's work (instantaneous impacts)", false}, [](const Run& r) -> RigValue { return r.run.energy.drive_work_J; }},
    {{"energy_J.damping_dissipation", "J", "the dashpot's loss", false}, [](const Run& r) -> RigValue { return r.run.energy.damping_dissipation_J; }},
    {{"energy_J.impact_loss", "J", "the impacts' loss", false}, [](const Run& r) -> RigValue { return r.run.energy.impact_loss_J; }},
    {{"energy_J.change", "J", "E(end) - E(0), E = m v^2/2 + k x^2/2", false}, [](const Run& r) -> RigValue { return r.run.energy.final_J - r.run.energy.initial_J; }},
    {{"sticking_episodes", "", "times the body rested on the stop", true, true}, [](const Run& r) -> RigValue { return r.run.sticking_episodes; }},
    F::impacts_run,
};

constexpr RigOptionNote notes[] = {shaker_integrator_note};

}  // namespace

SequenceSetUp make_oscillator_sequence(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                                       const OscillatorOptions& o) {
  for (const auto& [decl, value] : {std::pair{stiffness, o.stiffness_N_per_m}, {damping_ratio, o.damping_ratio},
                                    {force_amplitude, o.force_amplitude_N}, {frequency, o.frequency_Hz},
                                    {stop_distance, o.stop_distance_m}, {start_velocity, o.start_velocity_mps}})
    require_in_range(decl, value);
  if (!(o.start_position_m < o.stop_distance_m))
    throw InvalidParameter("start-position", format_value(o.start_position_m), "below `stop-distance`");
  validate_impact_counts(o.impacts, o.transient);
  validate(setup);
  validate(solver);
  const double m = setup.mass_kg, k = o.stiffness_N_per_m, d = o.stop_distance_m, w = 2 * std::numbers::pi * o.frequency_Hz;
  const ForcedOscillator body{.mass_kg = m, .stiffness_N_per_m = k, .damping_ratio = o.damping_ratio,
                              .force_amplitude_N = o.force_amplitude_N, .omega_rad_per_s = w,
                              .force_phase_rad = std::numbers::pi / 2};
  SequenceSetUp out{
      .spec = {.body = body, .prescribed = OscillatorMotion::prescribed(0, w),
               .walls = {{.name = "stop", .sigma = -1, .offset_m = d}}, .frequency_Hz = o.frequency_Hz,
               .speed_scale_mps = (o.force_amplitude_N + k * d) / (m * o.frequency_Hz), .y0_m = o.start_position_m,
               .u0_mps = o.start_velocity_mps, .impacts = o.impacts, .transient = o.transient,
               .restitution = setup.restitution, .pattern = o.pattern, .energy = true,
               .sampled = ImpactSequenceSpec::Sampled::body},
      .integrator_used = std::nullopt};
  if (o.impact_model == ShakerImpactModel::soft)  // the stop's contact (model/contact_environments.hpp)
    set_harmonic_soft_contacts(out, law, setup, solver, "hertzdash oscillator",
                               [stop = HarmonicForcing{k, body.damping_N_s_per_m(), o.force_amplitude_N, w, d}](
                                   Wall, double t) {
                                 HarmonicForcing at = stop;
                                 at.t_onset_s = t;
                                 return at;
                               });
  return out;
}

OscillatorRun run_oscillator(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver,
                             const OscillatorOptions& o) {
  const SequenceSetUp sequence = make_oscillator_sequence(setup, law, solver, o);
  OscillatorRun out{run_impact_sequence(sequence.spec)};
  out.impact_model = o.impact_model;
  if (sequence.integrator_used) out.integrator_used = *sequence.integrator_used;
  out.steady_amplitude_m = sequence.spec.body.steady_amplitude_m();
  return out;
}

const Rig& oscillator_rig() {
  static const Rig rig = make_rig<Run, SequenceImpact>(
      {.name = "oscillator",
       .summary = "The impact oscillator: a body on a spring driven by F cos(2 pi f t) against a stop at distance d; "
                  "soft contacts or instantaneous impacts, exact flights",
       .inputs = inputs, .run_options_not_read = not_read, .not_read_because = "the body starts at `start-position`",
       .run_option_notes = notes, .default_integrator = shaker_default_integrator,
       .instantaneous_reads = instantaneous_reads, .refuse = refuse, .results = results,
       .table_description = "one row per kept impact (time from the start; phase of the drive F cos(2 pi f t) in "
                            "[0,1); speeds relative to the stop)",
       .table = one_wall_impact_table, .run = run, .outcome = outcome, .sequence = sequence});
  return rig;
}

}  // namespace hertzdash
