// A rig's Lyapunov exponents as JSON and text (simulation/reports/orbit_report.hpp).
#include "hertzdash/simulation/reports/orbit_report.hpp"

#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace hertzdash {

namespace {

constexpr const char* method =
    "QR method on the stroboscopic map's monodromy matrices, saltation matrices at the impacts (instantaneous impacts)";

std::string numbers(const std::vector<double>& v) { return fmt::format("{:.6g}", fmt::join(v, ", ")); }

}  // namespace

nlohmann::ordered_json to_json(const Rig& rig, const LyapunovResult& r) {
  const LyapunovSpectrum& s = r.spectrum;
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["rig"] = rig.name;
  j["method"] = method;
  if (!s.failure.empty()) j["failure"] = s.failure;
  j["periods"] = s.periods;
  j["impacts"] = s.impacts;
  j["section_phase"] = r.section_phase;
  j["exponents_per_period"] = s.per_period;
  j["exponents_per_impact"] = s.per_impact;
  j["sum_per_impact"] = report_detail::number_or_null(s.sum_per_impact);
  j["expected_sum_per_impact"] = report_detail::number_or_null(s.expected_sum_per_impact);
  j["half_difference"] = s.half_difference;
  j["converged"] = s.converged;
  j["running"] = {{"periods", s.running_periods}, {"exponents_per_impact", s.running_per_impact}};
  report_detail::add_inputs_and_revision(j, r.inputs);
  return j;
}

std::string lyapunov_text(const Rig& rig, const LyapunovResult& r) {
  const LyapunovSpectrum& s = r.spectrum;
  std::string out = fmt::format("hertzdash lyapunov {}: {}\n", rig.name, r.heading);
  auto line = [&](std::string_view name, const std::string& value) { out += fmt::format("  {:<24} {}\n", name, value); };
  if (!s.failure.empty()) line("failure", s.failure);
  line("periods, impacts", fmt::format("{}, {}", s.periods, s.impacts));
  line("exponents per period", numbers(s.per_period));
  line("exponents per impact", numbers(s.per_impact));
  line("sum per impact", fmt::format("{:.9g} (expected {:.9g})", s.sum_per_impact, s.expected_sum_per_impact));
  line("converged", fmt::format("{} (halves differ by {:.2g} per impact)", s.converged ? "yes" : "no", s.half_difference));
  return out;
}

}  // namespace hertzdash
