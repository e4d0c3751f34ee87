#pragma once
// The messages of the codes an impact carries (simulation/run/diagnostic_codes.hpp), built only
// when a front end reports them: the command line on stderr ("hertzdash: <kind>: <message>"),
// Python as UserWarnings, JSON in "warnings" ({"kind", "code", "message"}).
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/run/diagnostic_codes.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

/// One note or warning about a run, as every front end reports it.
struct RunDiagnostic {
  std::string kind;     ///< "note" or "warning" (DiagnosticInfo::kind)
  std::string code;     ///< a DiagnosticInfo::name, or another front end's own (e.g. fit's, measured_trace)
  std::string message;  ///< options written as key_reference()s: each front end spells them (--dt, dt)
  std::optional<int> impact;  ///< bounce: the impact (from 0) it concerns; JSON "impact"
};

/// "`integrator` X fell back to Y: why" when the integrator that ran is not the one asked
/// for, else empty.
std::string fallback_note(IntegratorKind asked, IntegratorKind used, const std::string& why);

/// The message of `code` for the impact `s` of `setup` run with `solver`; `fallback_reason` is
/// why the integrator fell back (integrator_used(), simulation/run/impact_simulator.hpp).
std::string diagnostic_message(Diagnostic code, const ImpactSummary& s, const DropTestSetup& setup,
                               const SolverSettings& solver, const std::string& fallback_reason);

/// Every code of s.diagnostics with its message, in table order.
std::vector<RunDiagnostic> impact_diagnostic_list(const ImpactSummary& s, const DropTestSetup& setup,
                                                  const SolverSettings& solver, const std::string& fallback_reason);

/// The JSON "warnings" array: one {"kind", "code", "message"} object each (and "impact" if set).
nlohmann::ordered_json to_json(const std::vector<RunDiagnostic>& diagnostics);

}  // namespace hertzdash
