// The commands' own options (simulation/options/command_options.hpp).
#include "hertzdash/simulation/options/command_options.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace hertzdash {

namespace {

using R = NumberRange;
using T = ParameterType;

constexpr ParameterDecl json{.key = "json", .type = T::flag, .default_value = "off", .help = "Print the result as one JSON object"};
constexpr ParameterDecl mkdir{.key = "mkdir", .type = T::flag, .default_value = "off",
                              .help = "Create the missing parent directories of the output files, right before "
                                      "writing them (without it, a missing directory is an error)"};
/// An output file `key`.
constexpr ParameterDecl file(std::string_view key, std::string_view help, std::string_view default_value = "none") {
  return {.key = key, .type = T::text, .choices = "a file path", .default_value = default_value, .help = help};
}

constexpr ParameterDecl simulate[] = {
    file("trace", "Write the contact-phase time series to this CSV file"),
    {.key = "trace-format", .type = T::text, .choices = "model, measured", .default_value = "model",
     .help = "model: every integrator step, the measured-trace columns and the model's own; measured: a virtual "
             "experiment (sampled, filtered, noisy); both in the measured-trace format (data/measurements/README.md), "
             "labelled synthetic"},
    {.key = "sample-rate", .unit = "Hz", .range = R::positive(), .default_value = "1e6",
     .help = "Virtual measurement: sampling rate [Hz]"},
    {.key = "anti-alias", .unit = "Hz", .range = R::non_negative(), .default_value = "0",
     .help = "Virtual measurement: cut-off [Hz] of the 2nd-order Butterworth anti-alias filter; 0 = none"},
    {.key = "noise", .range = R::non_negative(), .default_value = "0",
     .help = "Virtual measurement: Gaussian noise sigma as a fraction of each channel's largest magnitude, in [0, 1]"},
    {.key = "seed", .range = R::integer(0, 18446744073709551615.0), .default_value = "1",
     .help = "Virtual measurement: seed of the noise"},
    {.key = "channels", .type = T::text, .choices = "comma-separated channels of the measured-trace format",
     .default_value = "force_N,accel_mps2,displacement_m", .help = "Virtual measurement: channels to record"},
    json, mkdir};
constexpr ParameterDecl restitution[] = {
    {.key = "target-restitution", .range = R::open_closed(0, 1), .default_value = "none",
     .help = "Calibrate: find the input e whose effective restitution is this, in (0,1]"},
    json};
constexpr ParameterDecl bounce[] = {
    {.key = "bounces", .range = R::integer(1, 1000), .default_value = "5",
     .help = "Impacts to follow, the first included (3 give one interval ratio)"},
    {.key = "min-rebound-velocity", .unit = "m/s", .range = R::non_negative(), .default_value = "0.001",
     .help = "End the sequence after a rebound slower than this [m/s]"},
    {.key = "target-interval-restitution", .range = R::open_closed(0, 1), .default_value = "none",
     .help = "Calibrate: find the input e whose first interval ratio is this, in (0,1]"},
    json,
    file("trace", "Write the sequence's time series to this CSV file: every contact at the integrator's steps, each "
                  "flight in closed form (rigid rod only)"),
    mkdir};
constexpr ParameterDecl rig[] = {json, file("csv", "Write the kept impacts to this CSV file, one row each"), mkdir};
constexpr ParameterDecl sweep[] = {
    {.key = "case", .type = T::text, .choices = "a TOML file (docs/sweep.md)", .default_value = "required",
     .help = "The case file (TOML), the first argument"},
    file("out", "The CSV of one row per run", "the case's [output] file, else the case file's name with .csv"),
    file("summary", "Also write the summary of every output here",
         "with [output] summary = true: the CSV's name with .summary.csv"),
    {.key = "threads", .range = R::integer(0, 4294967295.0), .default_value = "0",
     .default_source = "the machine's cores shared among the job's processes on it", .help = "Threads per process"},
    {.key = "quiet", .type = T::flag, .default_value = "off", .help = "No progress line"},
    file("figure",
         "Draw the sweep of one varied key to this PNG, PDF or SVG file (by its extension): a rig's bifurcation "
         "diagram (each kept impact's phase and speed against the key), or each output against it (docs/sweep.md)"),
    mkdir};
constexpr double infinity = std::numeric_limits<double>::infinity();
// `hertzdash orbit RIG` (simulation/rigs/rig_orbit.hpp, docs/orbits.md).
constexpr ParameterDecl orbit_period{.key = "period", .range = R::integer(1, 1000), .default_value = "the rig's own run's",
    .default_number = 1, .default_source = "the period the rig's run settles on (1 with a guess)",
    .help = "Drive cycles N of the orbit sought, the fixed point of the map over N cycles"};
constexpr ParameterDecl section_phase{.key = "section-phase", .range = R::closed_open(0, 1), .default_value = "mid-gap",
    .default_source = "the middle of the widest impact-free arc of the rig's run's impact phases",
    .help = "Drive phase of the section in [0, 1), where the orbit's state is taken"};
constexpr ParameterDecl guess_position{.key = "guess-position", .unit = "m", .range = R::open(-infinity, infinity),
    .default_value = "none",
    .help = "Newton's start instead of the rig's own run: the body's position [m] at the section phase (with "
            "guess-velocity and section-phase)"};
constexpr ParameterDecl guess_velocity{.key = "guess-velocity", .unit = "m/s", .range = R::open(-infinity, infinity),
    .default_value = "none", .help = "Newton's start: the body's velocity [m/s] at the section phase"};
constexpr ParameterDecl guess_box_position{.key = "guess-box-position", .unit = "m", .range = R::open(-infinity, infinity),
    .default_value = "none", .help = "Newton's start, a box of its own (walls --rig damper): the primary's position [m]"};
constexpr ParameterDecl guess_box_velocity{.key = "guess-box-velocity", .unit = "m/s", .range = R::open(-infinity, infinity),
    .default_value = "none", .help = "Newton's start, a box of its own: the primary's velocity [m/s]"};
constexpr ParameterDecl orbit[] = {orbit_period,       section_phase,      guess_position, guess_velocity,
                                   guess_box_position, guess_box_velocity, json};
// `hertzdash continue RIG` (simulation/rigs/rig_continuation.hpp, docs/orbits.md): the orbit's
// options for the first branch's start, and the parameter's range.
constexpr ParameterDecl continuation[] = {
    {.key = "parameter", .type = T::text, .choices = "a numeric input of the rig or of its run", .default_value = "required",
     .help = "The parameter continued in, a number the rig's command takes (gamma, frequency, force-amplitude, "
             "restitution, ...)"},
    {.key = "from", .range = R::open(-infinity, infinity), .default_value = "required",
     .help = "The parameter's value at the start, where the first orbit is found"},
    {.key = "to", .range = R::open(-infinity, infinity), .default_value = "required",
     .help = "The parameter's value towards which the branches are followed"},
    orbit_period, section_phase, guess_position, guess_velocity, guess_box_position, guess_box_velocity,
    {.key = "max-points", .range = R::integer(10, 100000), .default_value = "2000", .default_number = 2000,
     .default_source = "chosen", .help = "Branch points at most, over all branches"},
    json, file("csv", "Write the branches to this CSV file, one row per point, the events as comments"), mkdir};
// `hertzdash lyapunov RIG` (simulation/rigs/rig_lyapunov.hpp, docs/orbits.md).
constexpr ParameterDecl lyapunov[] = {
    {.key = "periods", .range = R::integer(10, 10000000), .default_value = "10000", .default_number = 10000,
     .default_source = "chosen: a chaotic run's exponents to ~2 % (docs/orbits.md)",
     .help = "Drive periods of the run after the rig's own (its transient and kept impacts)"},
    section_phase, json};
// `hertzdash basins RIG` (simulation/rigs/rig_basins.hpp, docs/orbits.md).
constexpr ParameterDecl basins[] = {
    section_phase,
    {.key = "position-min", .unit = "m", .range = R::open(-infinity, infinity), .default_value = "around the attractor",
     .default_source = "the rig's attractor's position at the section less one position scale (v_s / f)",
     .help = "Lowest start position [m] of the grid (with position-max)"},
    {.key = "position-max", .unit = "m", .range = R::open(-infinity, infinity), .default_value = "around the attractor",
     .default_source = "the attractor's position plus one position scale", .help = "Highest start position [m] of the grid"},
    {.key = "velocity-min", .unit = "m/s", .range = R::open(-infinity, infinity), .default_value = "around the attractor",
     .default_source = "the attractor's velocity at the section less one speed scale (v_s)",
     .help = "Lowest start velocity [m/s] of the grid (with velocity-max)"},
    {.key = "velocity-max", .unit = "m/s", .range = R::open(-infinity, infinity), .default_value = "around the attractor",
     .default_source = "the attractor's velocity plus one speed scale", .help = "Highest start velocity [m/s] of the grid"},
    {.key = "resolution", .range = R::integer(2, 2000), .default_value = "64", .default_number = 64,
     .default_source = "chosen", .help = "Cells per axis of the grid of starts"},
    {.key = "cell-transient", .range = R::integer(0, 1000000), .default_value = "400", .default_number = 400,
     .default_source = "chosen", .help = "Impacts each start runs before its attractor is read"},
    {.key = "cell-impacts", .range = R::integer(2, 100000), .default_value = "32", .default_number = 32,
     .default_source = "chosen", .help = "Impacts each start keeps to read its attractor (period, phases)"},
    {.key = "threads", .range = R::integer(0, 4096), .default_value = "0", .default_number = 0,
     .default_source = "the machine's cores", .help = "Threads (the result does not depend on them)"},
    json, file("csv", "Write the grid to this CSV file, one row per start, the attractors as comments"), mkdir};
// `hertzdash export` and `hertzdash conformance` (simulation/export/, docs/engines.md).
constexpr ParameterDecl engine{.key = "engine", .type = T::text, .choices = "lammps, liggghts, yade", .default_value = "none",
                               .help = "The discrete-element engine (required)"};
constexpr ParameterDecl steps_per_contact{
    .key = "steps-per-contact", .range = R::integer(10, 10000000), .default_value = "1000", .default_number = 1000,
    .default_source = "chosen: the engines' e within 0.15 N^-(1+p) of the law's, 5e-6 (kuwabara-kono) and 3e-5 "
                      "(tsuji-dem) (docs/engines.md)",
    .help = "Time steps per predicted contact time: the decks' time step"};
constexpr ParameterDecl export_decks[] = {
    engine,
    {.key = "engine-model", .type = T::text, .choices = "granular-viscoelastic, granular-mass-velocity, granular-velocity, gran-hertz-history, granular-tsuji (lammps); "
                                                 "hertz (liggghts); mindlin (yade)",
     .default_value = "the engine's model equal to --damping", .default_source = "computed",
     .help = "The engine's contact model; it must equal the law --damping names"},
    {.key = "out", .type = T::text, .choices = "a directory", .default_value = "none",
     .help = "Directory of the decks (required): sphere_sphere.in, sphere_wall.in and contact_lines.in (.py for yade)"},
    steps_per_contact,
    json, mkdir};
constexpr ParameterDecl conformance[] = {engine, steps_per_contact, json};
constexpr ParameterDecl models[] = {{.key = "json", .type = T::flag, .default_value = "off", .help = "Print the list as a JSON array"}};

constexpr CommandOptions table[] = {
    {"simulate", simulate}, {"models", models},       {"restitution", restitution},
    {"bounce", bounce},     {"RIG", rig},             {"fit", {}},
    {"orbit", orbit},       {"continue", continuation}, {"lyapunov", lyapunov},
    {"basins", basins},     {"sweep", sweep},         {"export", export_decks},
    {"conformance", conformance}};

}  // namespace

std::span<const CommandOptions> command_options() { return table; }

ParameterDecls options_of_command(std::string_view command) {
  for (const CommandOptions& c : table)
    if (c.command == command) return c.options;
  return {};
}

const ParameterDecl& command_option(std::string_view command, std::string_view key) {
  for (const ParameterDecl& d : options_of_command(command))
    if (d.key == key) return d;
  throw std::logic_error("no option `" + std::string(key) + "` of command " + std::string(command));
}

}  // namespace hertzdash
