#pragma once
// The options of one run: one table (run_options()) built from the declarations of the model
// (model/parameter.hpp: the drop test's, the elastic rod's, each damping law's own) and of the
// integrator table, each bound to where a run keeps it and to who reads it. The command line
// (--ball-E), Python (ball_E=), case files (ball-E = ), the fit's parameters and bounds, the
// "given only with ..." refusals and docs/parameters.md are all generated from it, so that
// `hertzdash simulate --ball-E 3e9` and `hertzdash.simulate(ball_E=3e9)` take the same options
// with the same defaults and refuse bad values with the same {key, value, range}.
// resolve_setup() and resolve_solver() validate; no option is ignored: one given where nothing
// reads it (a law, the rig or the integrator chosen) is refused naming what reads it.
#include "hertzdash/model/damping/registry.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <functional>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace hertzdash {

struct IntegratorTraits;

/// The drop height of a run that gives none [m]: the paper's 20 mm.
inline constexpr double default_height_m = 0.02;

/// What a user asked for: the paper's drop test of one rod, with overrides, and a solver.
/// An unset override keeps the paper's value (Tables 1-3, data/assumptions.csv).
struct RunOptions {
  // The set-up.
  std::string rod = "steel";                     ///< a rod of Tables 1-3
  std::optional<double> height_m;                ///< drop height h [m] (unset: default_height_m)
  std::optional<double> impact_velocity_mps;     ///< approach speed at onset [m/s]; overrides height_m
  std::optional<double> mass_kg;                 ///< rod mass [kg]
  std::optional<double> density_kg_per_m3;       ///< a dropped ball's density [kg/m^3], instead of mass_kg
  std::optional<double> restitution;             ///< input e in (0, 1]
  std::optional<double> ball_E_Pa, ball_nu;      ///< hemisphere modulus [Pa], Poisson ratio
  std::optional<double> ball_radius_m;           ///< hemisphere radius [m]
  std::optional<double> ball_yield_stress_Pa;    ///< hemisphere yield stress [Pa] (inf: no elasticity check)
  std::optional<double> rod_E_Pa, rod_nu;        ///< rod modulus [Pa] (inf: rigid), Poisson ratio
  std::optional<double> gravity_mps2;            ///< g [m/s^2]
  bool no_tension = false;                       ///< clamp the contact force at >= 0
  std::optional<double> air_density_kg_per_m3;   ///< air density [kg/m^3] of the flights' drag (unset: none)
  std::optional<double> drag_coefficient;        ///< the drag coefficient C_d (unset: a smooth sphere's)
  std::optional<std::string> zeta;               ///< the paper's law's zeta form: paper (eq. 6, unset) or exact
  std::optional<std::string> omega_n;            ///< the paper's law's omega_n variant (unset: paper)
  std::string damping{default_damping_law};      ///< a registered law
  std::optional<double> viscous_time_constant_s; ///< A [s] of a viscoelastic law (kuwabara-kono)
  std::optional<double> reference_velocity_mps;  ///< speed [m/s] at which a viscoelastic law's e is the input e
  // The bodies: rigid (the paper's model) or the elastic rod on the load cell.
  std::string rod_model = "rigid";               ///< rigid or elastic
  std::optional<double> rod_elements;            ///< finite elements of the elastic rod (an integer)
  std::optional<double> rod_damping_ratio;       ///< zeta of the rod's first longitudinal mode
  std::optional<double> cell_stiffness_N_per_m;  ///< load cell stiffness [N/m] (inf: rigid base)
  std::optional<double> cell_damping_ratio;      ///< the hemisphere's damping ratio on the cell
  std::optional<double> hemisphere_mass_kg;      ///< [kg]
  std::optional<std::string> accelerometer;      ///< top or bottom end face
  // The solver (simulation/run/solver_settings.hpp).
  // Unset: SolverSettings' default. A setting given for an integrator that does not read it
  // is an error (resolve_solver), not silently ignored.
  std::string integrator = "cvode";
  std::optional<double> dt_s;                ///< fixed step [s] (euler, rk4)
  bool no_event_location = false;            ///< euler, rk4
  std::optional<double> rtol, atol;          ///< adaptive integrators
  std::optional<std::string> cvode_method;   ///< cvode, cvode-regularized
  std::optional<double> max_step_s;          ///< adaptive integrators in physical variables [s]
  /// The numbers given for inputs a law declares and reads through DampingSettings::number()
  /// (a law's own inputs, model/damping/damping_law.hpp), by key.
  std::map<std::string, double, std::less<>> law_numbers;
  /// Not an option: whether the front end follows the body's flights (`hertzdash bounce`, `fit
  /// --bounce-times`), where the options read only in flight (air drag) are read; others refuse them.
  bool follows_flights = false;
  /// Not an option: where impact_velocity_mps comes from when a front end sets it, not the user
  /// (`fit --bounce-times`: "the first impact speed of drop 'a' of FILE"); a refusal of the
  /// set-up names it, or an option the user gave, never `impact-velocity`.
  std::string impact_velocity_origin;
};

/// Who reads an option, besides every command that takes it: all runs, or only some laws, only
/// the elastic rod, only some integrators. An option given where nothing reads it is refused.
struct OptionReaders {
  std::vector<std::string> laws{};                        ///< non-empty: only these laws
  bool elastic_rod = false;                               ///< only --rod-model elastic
  bool (*integrators)(const IntegratorTraits&) = nullptr; ///< non-null: only the integrators it accepts
  bool trace_only = false;  ///< read only where a trace is recorded (refuse_trace_only_options)
  /// Read only in the flights of the rigid rod's bounce sequence (RunOptions::follows_flights).
  bool flights_only = false;
  /// What reads it, as a refusal says it: "`damping` hongo", "`rod-model` elastic",
  /// "`integrator` euler, rk4"; empty for an option every run reads.
  std::string describe() const;
  /// Whether a run of the law `law` (empty: any law), on the elastic rod or not, with
  /// `integrator`, following flights or not, reads it.
  bool read_by(std::string_view law, bool elastic_rod, const IntegratorTraits& integrator, bool follows_flights) const;
};

/// A law's own number, kept in RunOptions::law_numbers under its key.
struct LawNumber {};

/// One option: its declaration (key, unit, range, default and its source, help), where a run
/// keeps it, and who reads it. `name` is the key: the command line's --name, Python's keyword
/// ('-' read as '_'), a case file's key.
struct RunOption {
  using Field = std::variant<std::optional<double> RunOptions::*, std::string RunOptions::*,
                             std::optional<std::string> RunOptions::*, bool RunOptions::*, LawNumber>;
  enum class Group { setup, solver };
  ParameterDecl decl;
  std::string name;  ///< decl.key
  Field field;
  std::string help;  ///< decl.help with its valid values and default (generated)
  Group group;
  std::string unit;  ///< the unit in a column name (decl.column_unit)
  OptionReaders readers = {};
  /// A fittable option's value in a resolved set-up (its default where the user gave none),
  /// the fit's starting value; empty when the set-up has none (an elastic-rod input of a rigid run).
  std::function<std::optional<double>(const DropTestSetup&)> value_in_setup = {};
  /// The option's value in a run as the run holds it (its default where the user gave none),
  /// as text, for the run's description (options/run_description.hpp); empty where the run has
  /// none (a law's computed default, the height of a run given its impact velocity). Unset for
  /// `rod`, a preset whose values the other options describe, and `damping`, the law's name.
  std::function<std::optional<std::string>(const DropTestSetup&, const SolverSettings&)> value_in_run = {};
};

/// The help a user reads of declaration `d`: its sentence, valid values, default and the
/// default's source, other inputs written in `spelling`.
std::string help_text(const ParameterDecl& d, KeySpelling spelling);

/// Setting and reading an option, whatever its type (the one setter every front end uses).
/// A number for a text option (or the reverse) is a logic error: callers switch on decl.type.
void set_number(RunOptions& options, const RunOption& o, double value);
void set_text(RunOptions& options, const RunOption& o, const std::string& value);
void set_flag(RunOptions& options, const RunOption& o, bool value);
/// Unset: the option's default (Python's None).
void clear_option(RunOptions& options, const RunOption& o);
/// Whether the user gave it (a flag: whether it is on; a text with a default: whether it differs).
bool is_given(const RunOptions& options, const RunOption& o);
/// The value given, as text, for messages.
std::string given_text(const RunOptions& options, const RunOption& o);

/// The name of a column of the option's values: its Python keyword and unit ("height_m",
/// "ball_E_Pa", "restitution").
std::string column_name(const RunOption& option);

/// Every option, the set-up's first.
const std::vector<RunOption>& run_options();

/// The options `fit --fit` may estimate, in table order.
std::vector<const RunOption*> fittable_options();

/// The option called `name` (command-line or Python spelling), or nullptr.
const RunOption* find_run_option(std::string_view name);

/// The items of a comma-separated option value: "a,b" -> {"a", "b"}; an empty item stays
/// (",a" -> {"", "a"}, "" -> {""}) for the caller to refuse.
std::vector<std::string> split_option_list(const std::string& list);

/// "ball-E" -> "ball_E": the Python keyword of an option.
std::string python_keyword(std::string_view option_name);

/// Checks every option given: first each value against its declaration (its range, or its
/// choices), then that something in this run reads it (its law, rig or integrator), refusing one
/// that nothing reads with InvalidParameter{key, value, "given only with <readers>; <what the run
/// has>"}. resolve_setup() and resolve_solver() begin with it.
void check_given_options(const RunOptions& o);

/// What a command that records no trace (`what`: "hertzdash bounce") says of an option read only
/// into a trace (the accelerometer's face): InvalidParameter{key, value, "given only where a
/// trace is recorded ..."}. The commands and functions without a trace call it.
void refuse_trace_only_options(const RunOptions& o, std::string_view what);
/// The range of that refusal.
std::string trace_only_range(std::string_view what);

/// Refuses (InvalidParameter{key, value, "given only with " + only_with}) every option of `o` that
/// differs from the command's own `defaults` and is not among `read`: what a run that reads only
/// those (the instantaneous impact map of `shaker` and `walls`) says of the rest.
void refuse_options_not_read(const RunOptions& o, const RunOptions& defaults, std::span<const std::string_view> read,
                             const std::string& only_with);

/// Refuses option `option` (shown with `value`) where nothing in run `o` reads it (its law, rig or
/// integrator), as check_given_options does; `fit --fit` asks it of each parameter it fits.
void require_read(const RunOptions& o, const RunOption& option, const std::string& value);

/// The paper's set-up for the chosen rod with the given overrides; validated (throws
/// InvalidParameter naming the option and its valid range, an unknown law included).
/// The key of the law's material constant the run gives (`viscous-time-constant`, or a law's own
/// such as lee-herrmann's `damping-rate`), if it gives one (the law then reads no e).
std::optional<std::string_view> material_constant_given(const RunOptions& o);

DropTestSetup resolve_setup(const RunOptions& o, const PaperParameters& paper);

/// The solver settings asked for; validated likewise.
SolverSettings resolve_solver(const RunOptions& o);

}  // namespace hertzdash
