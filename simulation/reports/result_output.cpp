#include "hertzdash/simulation/reports/result_output.hpp"

#include <fmt/format.h>

#include "hertzdash/simulation/run/integrator_table.hpp"

#include <cmath>
#include <vector>

namespace hertzdash {

namespace {

// The value of a field of type number, number_or_null, integer, boolean or group as JSON; null
// where the run does not have it.
nlohmann::ordered_json json_value(const ResultField& f, const ImpactSummary& s, const DropTestSetup& setup) {
  const double v = f.value(s, setup);
  if (!std::isfinite(v)) return nullptr;
  switch (f.type) {
    case ResultType::integer: return static_cast<long>(v);
    case ResultType::boolean: return v != 0;
    default: return v;
  }
}

// The fields of `group` ("" for the top level) into `j`.
void add_fields(nlohmann::ordered_json& j, std::string_view group, const ImpactSummary& s, const DropTestSetup& setup,
                nlohmann::ordered_json& warnings) {
  for (const ResultField& f : result_fields) {
    if (!f.in.json || f.group != group) continue;
    const std::string name(f.name);
    switch (f.type) {
      case ResultType::integrator: j[name] = to_string(s.integrator_used); break;
      case ResultType::coefficients: j[name] = law_coefficients_json(s.law_coefficients); break;
      case ResultType::warnings: j[name] = std::move(warnings); break;
      case ResultType::group:
        if (std::isnan(f.value(s, setup))) break;
        j[name] = nlohmann::ordered_json::object();
        add_fields(j[name], f.name, s, setup, warnings);
        break;
      case ResultType::number:
        if (std::isnan(f.value(s, setup))) break;
        j[name] = json_value(f, s, setup);
        break;
      default: j[name] = json_value(f, s, setup);
    }
  }
}

}  // namespace

nlohmann::ordered_json law_coefficients_json(const std::vector<NamedValue>& coefficients) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const NamedValue& c : coefficients) j[c.name] = c.value;
  return j;
}

std::string law_coefficients_line(const std::vector<NamedValue>& coefficients) {
  std::string constants;
  for (const NamedValue& c : coefficients) constants += fmt::format("{}{} {:.6g}", constants.empty() ? "" : ", ", c.name, c.value);
  return constants.empty() ? constants : "  law          " + constants + "\n";
}

void add_result_fields(nlohmann::ordered_json& j, const ImpactSummary& s, const DropTestSetup& setup,
                       nlohmann::ordered_json warnings) {
  add_fields(j, "", s, setup, warnings);
}

std::string result_text_block(const ImpactSummary& s, const DropTestSetup& setup) {
  std::vector<const ResultField*> lines;
  for (const ResultField& f : result_fields)
    if (f.text_line > 0) lines.push_back(&f);
  std::ranges::sort(lines, {}, &ResultField::text_line);
  std::string block;
  for (const ResultField* f : lines) {
    if (f->type == ResultType::coefficients) {
      for (const NamedValue& c : s.law_coefficients) block += "  " + result_text_line(c.name, c.value) + "\n";
      continue;
    }
    const double v = f->value(s, setup);
    if (std::isnan(v)) continue;
    block += "  " + (f->text ? f->text(s) : result_text_line(f->name, v)) + "\n";
  }
  return block;
}

}  // namespace hertzdash
