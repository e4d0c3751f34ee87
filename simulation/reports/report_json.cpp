// The JSON pieces the commands' reports share (simulation/reports/report_json.hpp).
#include "hertzdash/simulation/reports/report_json.hpp"

#include "hertzdash/io/decimal_number.hpp"

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

}  // namespace hertzdash::report_detail
