#pragma once
// The description of a run: its inputs as name = value pairs, for the provenance header of every
// output file and the "inputs" of the JSON reports. Made from the option table
// (options/run_options.hpp), so a declared input appears here without another edit.
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <string_view>

namespace hertzdash {

/// One entry per option of run_options() that the run reads (its law `law`, its rig and the
/// integrator solver.integrator) and holds a value of, in the table's order: named by the
/// option's column_name() (its Python keyword and unit: `ball_E_Pa`), valued as the set-up and
/// the solver hold it (defaults included). `law` may name no single law ("all registered
/// laws"): then every law's inputs that the set-up holds are described. The elastic rod's
/// geometry, which comes with the rod preset and is no option, is added as `rod_length_m` and
/// `rod_diameter_m`.
Parameters describe_run(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver);

}  // namespace hertzdash
