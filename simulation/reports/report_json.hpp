#pragma once
// Internal to the reports (simulation/reports/run_reports.hpp; not installed, cmake/install.cmake): the
// JSON pieces several commands' reports share: a parameter's text as a JSON value, the
// closing "inputs" and "git_revision" keys of a run's report, and the parameters and
// correlation of a fit (trace or restitution table).
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/simulation/fit/trace_fit.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace hertzdash::report_detail {

/// Parameters are text; numbers and booleans go into JSON as such.
nlohmann::ordered_json json_value(const std::string& text);

/// The closing keys of a run's report: "inputs" (numbers as numbers) and "git_revision".
void add_inputs_and_revision(nlohmann::ordered_json& j, const Parameters& inputs);

/// A finite number, or null (an infinite bound or standard error, a NaN).
nlohmann::ordered_json number_or_null(double v);

/// A fit's "parameters": name, initial, estimate, standard_error, lower, upper, at_bound each;
/// where computed, "profile_interval" [lower, upper] (null: not found), "profile_interval_open"
/// [bool, bool] (the data do not bound that side: the end is the parameter's bound) and
/// "profile_failure" after standard_error.
nlohmann::ordered_json to_json(const std::vector<FittedParameter>& parameters);

/// A fit's "correlation" matrix, null where not finite.
nlohmann::ordered_json correlation_json(const std::vector<std::vector<double>>& correlation);

}  // namespace hertzdash::report_detail
