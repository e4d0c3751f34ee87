#include "hertzdash/simulation/run/integrator_table.hpp"

#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

namespace hertzdash {

const char* to_string(IntegratorKind k) { return integrator_traits(k).name.data(); }

std::string integrator_names(bool (*which)(const IntegratorTraits&)) {
  std::string names;
  for (const IntegratorTraits& row : all_integrator_traits)
    if (!which || which(row)) names += (names.empty() ? "" : ", ") + std::string(row.name);
  return names;
}

IntegratorKind parse_integrator(std::string_view name, const std::string& option) {
  for (IntegratorKind k : all_integrator_kinds)
    if (name == to_string(k)) return k;
  throw InvalidParameter(option, std::string(name), "one of: " + integrator_names());
}

IntegratorKind integrator_used(IntegratorKind asked, const ImpactNeeds& needs, std::string* why) {
  IntegratorKind k = asked;
  std::string reason;
  if ((needs.tension_clamp || needs.elastic_rod) && integrator_traits(k).physical_counterpart != k) {
    k = integrator_traits(k).physical_counterpart;
    reason = needs.elastic_rod
                 ? fmt::format("{} integrates a rigid rod's contact in regularising variables; the elastic rod "
                               "(`rod-model` elastic) runs in the physical variables, so {} runs instead",
                               to_string(asked), to_string(k))
                 : fmt::format("{} integrates the contact in regularising variables, which have no event for the "
                               "tension clamp (`no-tension` ends contact where the force reaches zero); {} runs in "
                               "the physical variables instead",
                               to_string(asked), to_string(k));
  }
  if (!needs.root_polynomial_law && integrator_traits(k).needs_root_polynomial) {
    const IntegratorKind from = k;
    k = integrator_traits(k).fallback_for_other_laws;
    reason = fmt::format("{} needs a law whose force is a polynomial in x^(1/2) (one that declares force_of_root); "
                         "this law does not, so {} runs instead, with its singular-point checks",
                         to_string(from), to_string(k));
  }
  if (why) *why = reason;
  return k;
}

void validate(const SolverSettings& s) {
  // Every setting is checked, whether or not the chosen integrator reads it: a bad value is a
  // mistake even where it happens not to matter.
  const IntegratorTraits& row = integrator_traits(s.integrator);
  require_positive("dt", s.dt_s, "s");
  require_in_open("rtol", s.rtol, 0, 1);
  require_in_open("atol", s.atol, 0, 1);
  require_non_negative("max-step", s.max_step_s, "s");
  // A regularised path steps in tau (dt = 2 x^{1/2} dtau), not in time: no largest step.
  if (row.variables == Variables::regularized && s.max_step_s != 0)
    throw InvalidParameter("max-step", fmt::format("{}", s.max_step_s),
                           fmt::format("0 (no limit) with {}, whose steps are in tau, not in time", row.name));
}

}  // namespace hertzdash
