#pragma once
// The checks every impact's result passes through before any front end sees it
// (ImpactSimulator::run): a result that contradicts the model is an error, one outside the
// model's assumptions or made with too coarse a step or tolerance carries a code
// (simulation/diagnostic_codes.hpp) that every front end reports.
#include "hertzdash/model/damping/damping_law.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/diagnostic_codes.hpp"
#include "hertzdash/simulation/impact_summary.hpp"
#include "hertzdash/simulation/solver_settings.hpp"

namespace hertzdash {

/// Largest --rtol whose e_effective error stays below step_resolution_target_error (0.1 %, the
/// fixed steps' target). Measured (the steel rod from 20 mm with the paper's law, and duralumin-b
/// from 50 mm with hunt-crossley; reference: each integrator at rtol 1e-12), the worst relative
/// error of e_effective over cvode, dopri5, cvode-regularized, dopri5-regularized,
/// gbs8-regularized and taylor-regularized is 5.8 % at rtol 1e-2 (dopri5), 0.27 % at 1e-3
/// (cvode) and 0.025 % at 1e-4 (cvode): 1e-4 meets the target with a margin of 4, 1e-3 does not.
/// A larger --rtol is flagged loose_tolerance.
inline constexpr double loose_rtol_limit = 1e-4;

/// The same measurement bounds the error of e_effective by 6 rtol (5.8 % at 1e-2, 2.7 rtol at
/// 1e-3, 2.5 at 1e-4); restitution_limit() allows 10 rtol.
inline constexpr double restitution_error_per_rtol = 10;

/// The largest e_effective a run of `solver` may report: 1 plus its accuracy, which is
/// step_resolution_target_error for a resolved fixed step and, for an adaptive integrator,
/// max(step_resolution_target_error, restitution_error_per_rtol rtol). No law creates energy
/// (a dissipative one gives e_effective < 1, the conservative one 1), so beyond it the run did
/// not resolve the contact.
double restitution_limit(const SolverSettings& solver);

/// Throws std::runtime_error (exit 1 on the command line, a per-row error in a sweep) when a
/// separated impact's e_effective exceeds restitution_limit(): the message names the law, says
/// the run is under-resolved and what to change (--dt, --rtol).
void require_physical_restitution(const ImpactSummary& s, const SolverSettings& solver, const LawInfo& law,
                                  bool dissipative);

/// The codes of a finished impact of `setup` run with `solver` (allocation-free).
DiagnosticSet impact_diagnostics(const ImpactSummary& s, const DropTestSetup& setup, const SolverSettings& solver);

}  // namespace hertzdash
