// A rig's branches as JSON, text and CSV (simulation/reports/orbit_report.hpp).
#include "hertzdash/simulation/reports/orbit_report.hpp"

#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>

namespace hertzdash {

namespace {

constexpr const char* method =
    "pseudo-arclength continuation of the stroboscopic map's fixed points, monodromy from saltation matrices "
    "(instantaneous impacts)";

std::string event_line(const ContinuationResult& r, const BranchEvent& e) {
  return fmt::format("{} at {} = {:.9g} (branch {}, period {})", to_string(e.type), r.parameter, e.parameter, e.branch,
                     e.period);
}

}  // namespace

nlohmann::ordered_json to_json(const Rig& rig, const ContinuationResult& r) {
  using report_detail::number_or_null;
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["rig"] = rig.name;
  j["method"] = method;
  j["parameter"] = r.parameter;
  const std::string column = r.column;
  j["start"] = {{"period", r.start.period}, {"section_phase", r.start.section_phase}, {"guess", r.start.guess}};
  if (!r.failure.empty()) j["failure"] = r.failure;
  nlohmann::ordered_json branch = nlohmann::ordered_json::array();
  for (const BranchPoint& p : r.continuation.points) {
    nlohmann::ordered_json m = nlohmann::ordered_json::array(), moduli = nlohmann::ordered_json::array();
    for (const std::complex<double> l : p.multipliers) {
      m.push_back({l.real(), l.imag()});
      moduli.push_back(std::abs(l));
    }
    branch.push_back({{"branch", p.branch}, {"period", p.period}, {column, p.parameter}, {"position_m", p.state(0)},
                      {"velocity_mps", p.state(1)}, {"multipliers", m}, {"multiplier_moduli", moduli},
                      {"stable", p.stable}, {"impacts_per_period", p.impacts}, {"impact_phase", p.impact_phases},
                      {"min_impact_speed_mps", number_or_null(p.min_impact_speed_mps)},
                      {"min_flight_gap_m", number_or_null(p.min_flight_gap_m)}});
  }
  j["branch"] = branch;
  nlohmann::ordered_json events = nlohmann::ordered_json::array();
  for (const BranchEvent& e : r.continuation.events)
    events.push_back({{"type", to_string(e.type)}, {"parameter", e.parameter}, {"branch", e.branch}, {"period", e.period}});
  j["events"] = events;
  j["ends"] = r.continuation.ends;
  report_detail::add_inputs_and_revision(j, r.inputs);
  return j;
}

std::string continuation_text(const Rig& rig, const ContinuationResult& r) {
  std::string out = fmt::format("hertzdash continue {}: {}\n", rig.name, r.heading);
  out += fmt::format("  start     period {}, section phase {:.9g}: {}\n", r.start.period, r.start.section_phase, r.start.guess);
  if (!r.failure.empty()) return out + fmt::format("  failure   {}\n", r.failure);
  out += fmt::format("  points    {}\n", r.continuation.points.size());
  for (const BranchEvent& e : r.continuation.events) out += "  event     " + event_line(r, e) + "\n";
  for (const std::string& end : r.continuation.ends) out += "  end       " + end + "\n";
  return out;
}

CsvWriter continuation_csv(const Rig& rig, const ContinuationResult& r) {
  std::vector<std::string> columns{"branch", "period", r.column, "position_m", "velocity_mps"};
  for (const char* part : {"multiplier_1_re", "multiplier_1_im", "multiplier_2_re", "multiplier_2_im"}) columns.emplace_back(part);
  for (const char* c : {"stable", "impacts_per_period", "min_impact_speed_mps", "min_flight_gap_m"}) columns.emplace_back(c);
  CsvWriter csv(fmt::format("hertzdash continue {}: one row per branch point (the orbit's state at the section, its "
                            "Floquet multipliers largest first; stable 1 or 0; an infinite closeness: no impact or "
                            "no flight minimum)",
                            rig.name),
                r.inputs, columns);
  if (!r.failure.empty()) csv.add_comment("failure: " + r.failure);
  for (const BranchEvent& e : r.continuation.events) csv.add_comment("event: " + event_line(r, e));
  for (const std::string& end : r.continuation.ends) csv.add_comment("end: " + end);
  for (const BranchPoint& p : r.continuation.points) {
    std::vector<CsvWriter::Cell> row{static_cast<long>(p.branch), static_cast<long>(p.period), p.parameter, p.state(0),
                                     p.state(1)};
    for (std::size_t k = 0; k < 2; ++k) {
      const std::complex<double> l = k < p.multipliers.size() ? p.multipliers[k] : std::complex<double>(NAN, NAN);
      row.emplace_back(l.real());
      row.emplace_back(l.imag());
    }
    row.emplace_back(static_cast<long>(p.stable));
    row.emplace_back(static_cast<long>(p.impacts));
    row.emplace_back(p.min_impact_speed_mps);
    row.emplace_back(p.min_flight_gap_m);
    csv.add_row(row);
  }
  return csv;
}

}  // namespace hertzdash
