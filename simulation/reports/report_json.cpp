// The JSON pieces the commands' reports share (simulation/reports/report_json.hpp).
#include "hertzdash/simulation/reports/report_json.hpp"

#include "hertzdash/io/decimal_number.hpp"

#include <cmath>
#include <optional>

namespace hertzdash::report_detail {

nlohmann::ordered_json json_value(const std::string& text) {
  if (text == "true" || text == "false") return text == "true";
  if (const std::optional<double> v = parse_decimal(text)) return *v;
  return text;
}

void add_inputs_and_revision(nlohmann::ordered_json& j, const Parameters& inputs) {
  nlohmann::ordered_json in;
  for (const auto& [name, value] : inputs) in[name] = json_value(value);
  j["inputs"] = in;
  j["git_revision"] = git_revision();
}

nlohmann::ordered_json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json to_json(const std::vector<FittedParameter>& parameters) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const FittedParameter& p : parameters) {
    nlohmann::ordered_json j{{"name", p.name},
                             {"initial", p.initial},
                             {"estimate", p.estimate},
                             {"standard_error", number_or_null(p.standard_error)}};
    if (p.profile) {
      j["profile_interval"] = {number_or_null(p.profile->lower), number_or_null(p.profile->upper)};
      j["profile_interval_open"] = {p.profile->lower_open, p.profile->upper_open};
      j["profile_failure"] = p.profile->failure;
    }
    j["lower"] = number_or_null(p.lower);
    j["upper"] = number_or_null(p.upper);
    j["at_bound"] = p.at_bound;
    out.push_back(j);
  }
  return out;
}

nlohmann::ordered_json correlation_json(const std::vector<std::vector<double>>& correlation) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const auto& row : correlation) {
    nlohmann::ordered_json r = nlohmann::ordered_json::array();
    for (double c : row) r.push_back(number_or_null(c));
    out.push_back(r);
  }
  return out;
}

}  // namespace hertzdash::report_detail
