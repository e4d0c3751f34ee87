#pragma once
// Internal to the reports (simulation/reports/run_reports.hpp; not installed, cmake/install.cmake): the
// JSON pieces several commands' reports share: a parameter's text as a JSON value, and the
// closing "inputs" and "git_revision" keys of a run's report.
#include "hertzdash/io/provenance.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace hertzdash::report_detail {

/// Parameters are text; numbers and booleans go into JSON as such.
nlohmann::ordered_json json_value(const std::string& text);

/// The closing keys of a run's report: "inputs" (numbers as numbers) and "git_revision".
void add_inputs_and_revision(nlohmann::ordered_json& j, const Parameters& inputs);

}  // namespace hertzdash::report_detail
