#pragma once
// The options of one run, by the names users type. `hertzdash simulate --ball-E 3e9` and
// `hertzdash.simulate(ball_E=3e9)` are read through the same table (run_options()), so the
// command line and Python take the same options with the same defaults, and reject bad
// values with the same message. Reading only; resolve_setup() and resolve_solver() validate.
#include "hertzdash/model/damping/registry.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/paper_parameters.hpp"
#include "hertzdash/simulation/solver_settings.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace hertzdash {

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
  std::optional<double> restitution;             ///< input e in (0, 1]
  std::optional<double> ball_E_Pa, ball_nu;      ///< hemisphere modulus [Pa], Poisson ratio
  std::optional<double> ball_radius_m;           ///< hemisphere radius [m]
  std::optional<double> ball_yield_stress_Pa;    ///< hemisphere yield stress [Pa] (inf: no elasticity check)
  std::optional<double> rod_E_Pa, rod_nu;        ///< rod modulus [Pa] (inf: rigid), Poisson ratio
  std::optional<double> gravity_mps2;            ///< g [m/s^2]
  bool no_tension = false;                       ///< clamp the contact force at >= 0
  std::string zeta = "paper";                    ///< paper (eq. 6) or exact
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
  // The solver (simulation/solver_settings.hpp).
  // Unset: SolverSettings' default. A setting given for an integrator that does not read it
  // is an error (resolve_solver), not silently ignored.
  std::string integrator = "cvode";
  std::optional<double> dt_s;                ///< fixed step [s] (euler, rk4)
  bool no_event_location = false;            ///< euler, rk4
  std::optional<double> rtol, atol;          ///< adaptive integrators
  std::optional<std::string> cvode_method;   ///< cvode, cvode-regularized
  std::optional<double> max_step_s;          ///< adaptive integrators in physical variables [s]
};

/// One option: its name (the command line's --name; Python's keyword, '-' read as '_'),
/// the field it sets, its help text (units in brackets), and the SI unit a column of its values
/// carries in its name (empty for a dimensionless or text option).
struct RunOption {
  using Field = std::variant<double RunOptions::*, std::optional<double> RunOptions::*, std::string RunOptions::*,
                             std::optional<std::string> RunOptions::*, bool RunOptions::*>;
  enum class Group { setup, solver };
  std::string name;
  Field field;
  std::string help;
  Group group;
  std::string unit = {};
};

/// The name of a column of the option's values: its Python keyword and unit ("height_m",
/// "ball_E_Pa", "restitution").
std::string column_name(const RunOption& option);

/// Every option, the set-up's first.
const std::vector<RunOption>& run_options();

/// The option called `name` (command-line or Python spelling), or nullptr.
const RunOption* find_run_option(std::string_view name);

/// The items of a comma-separated option value: "a,b" -> {"a", "b"}; an empty item stays
/// (",a" -> {"", "a"}, "" -> {""}) for the caller to refuse.
std::vector<std::string> split_option_list(const std::string& list);

/// "ball-E" -> "ball_E": the Python keyword of an option.
std::string python_keyword(std::string_view option_name);

/// The paper's set-up for the chosen rod with the given overrides; validated (throws
/// InvalidParameter naming the option and its valid range, an unknown law included).
DropTestSetup resolve_setup(const RunOptions& o, const PaperParameters& paper);

/// The solver settings asked for; validated likewise.
SolverSettings resolve_solver(const RunOptions& o);

}  // namespace hertzdash
