#pragma once
// The checks every impact's result passes through before any front end sees it
// (ImpactSimulator::run): a result that contradicts the model is an error, one outside the
// model's assumptions or made with too coarse a step or tolerance carries a code
// (simulation/run/diagnostic_codes.hpp) that every front end reports.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/run/diagnostic_codes.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

namespace hertzdash {

/// Largest tolerance (--rtol, and --atol, which is relative to the impact's scales and so acts
/// like it) whose e_effective error stays below step_resolution_target_error (0.1 %, the fixed
/// steps' target), measured for every adaptive integrator on the steel rod from 20 mm with the
/// paper's law and duralumin-b from 50 mm with hunt-crossley against rtol 1e-12:
/// tests/test_tolerance_limit.cpp prints the table and asserts that every integrator meets the
/// target at this limit and that not every one does at ten times it. A larger --rtol or --atol
/// is flagged loose_tolerance.
inline constexpr double loose_rtol_limit = 1e-4;

/// The tolerance loose_rtol_limit is compared with: the larger of --rtol and --atol.
double run_tolerance(const SolverSettings& solver);

/// The largest e_effective a run may report: 1 plus step_resolution_target_error (0.1 %), the
/// accuracy of a resolved fixed step and of an adaptive integrator at a tolerance up to
/// loose_rtol_limit. No law creates energy (a dissipative one gives e_effective < 1, the
/// conservative one 1), so beyond it the run did not resolve the contact; a looser tolerance
/// does not raise the limit (cvode-regularized at --rtol 0.9 gives an e_effective above it for
/// hongo: tests/test_result_checks.cpp).
double restitution_limit();

/// Throws std::runtime_error (exit 1 on the command line, a per-row error in a sweep) when a
/// separated impact's e_effective exceeds restitution_limit(): the message names the law, says
/// the run is under-resolved and what to change (`dt`, `rtol`: key references that each front end
/// spells its own way, model/invalid_parameter.hpp).
void require_physical_restitution(const ImpactSummary& s, const SolverSettings& solver, const LawInfo& law,
                                  bool dissipative);

/// The codes of a finished impact of `setup` run with `solver` (allocation-free).
DiagnosticSet impact_diagnostics(const ImpactSummary& s, const DropTestSetup& setup, const SolverSettings& solver);

}  // namespace hertzdash
