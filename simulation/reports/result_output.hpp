#pragma once
// The result fields (simulation/run/result_fields.hpp) as `simulate` shows them: its JSON keys and
// its text block, both in the table's order.
#include "hertzdash/simulation/run/result_fields.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace hertzdash {

/// Adds the JSON fields of one impact to `j`, in table order: numbers, booleans and counts as
/// such, a number_or_null that is not finite as null, a group as an object of its fields; a
/// field the run does not have (a NaN number, an absent group) is left out. `warnings` is the
/// run's notes and warnings (run_diagnostics), which need more than the impact to word.
void add_result_fields(nlohmann::ordered_json& j, const ImpactSummary& s, const DropTestSetup& setup,
                       nlohmann::ordered_json warnings);

/// A law's constants (ImpactSummary::law_coefficients) as a JSON object, name: value: simulate's,
/// restitution's and a trace fit's `law_coefficients`.
nlohmann::ordered_json law_coefficients_json(const std::vector<NamedValue>& coefficients);

/// The same as restitution's and fit's text line, "  law          NAME VALUE, NAME VALUE\n";
/// empty for a law without constants.
std::string law_coefficients_line(const std::vector<NamedValue>& coefficients);

/// simulate's text block below its heading: one line per field with a text line, in their order
/// (law_coefficients: one line per coefficient), each indented by two spaces and ended by a newline;
/// a field the run does not have is left out.
std::string result_text_block(const ImpactSummary& s, const DropTestSetup& setup);

}  // namespace hertzdash
