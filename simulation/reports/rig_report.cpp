// A rig's run as JSON, text and CSV (simulation/reports/rig_report.hpp).
#include "hertzdash/simulation/reports/rig_report.hpp"

#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace hertzdash {

namespace {

nlohmann::ordered_json json_value(const RigValue& v) {
  if (const double* x = std::get_if<double>(&v)) return *x;  // NaN and inf dump as null
  if (const long* n = std::get_if<long>(&v)) return *n;
  return std::get<std::string>(v);
}

std::string text_value(const RigValue& v) {
  if (const double* x = std::get_if<double>(&v)) return fmt::format("{:.6g}", *x);
  if (const long* n = std::get_if<long>(&v)) return std::to_string(*n);
  return std::get<std::string>(v);
}

/// The label `index` of a column's labels "a, b".
std::string label(const RigColumn& c, double index) {
  const std::vector<std::string> labels = split_option_list(std::string(c.labels));
  std::string l = labels.at(static_cast<std::size_t>(index));
  l.erase(0, l.find_first_not_of(' '));
  return l;
}

std::string cell_text(const RigColumn& c, double v) {
  if (!c.labels.empty()) return label(c, v);
  return c.integer ? fmt::format("{}", static_cast<long>(v)) : fmt::format("{:.10g}", v);
}

}  // namespace

nlohmann::ordered_json to_json(const Rig& rig, const RigResult& r) {
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  auto scalars = [&](bool after_table) {
    for (std::size_t k = 0; k < rig.results.size(); ++k) {
      const std::string_view name = rig.results[k].name;
      if (rig.results[k].after_table != after_table || std::holds_alternative<std::monostate>(r.scalars[k])) continue;
      const std::size_t dot = name.find('.');
      if (dot == std::string_view::npos) j[std::string(name)] = json_value(r.scalars[k]);
      else j[std::string(name.substr(0, dot))][std::string(name.substr(dot + 1))] = json_value(r.scalars[k]);
    }
  };
  scalars(false);
  for (std::size_t c = 0; c < rig.table.size(); ++c) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (const std::vector<double>& row : r.rows) {
      if (rig.table[c].labels.empty()) a.push_back(row[c]);
      else a.push_back(label(rig.table[c], row[c]));
    }
    j[std::string(rig.table[c].name)] = a;
  }
  scalars(true);
  j["end_reason"] = r.end_reason;
  j["warnings"] = r.warnings;
  if (r.work) j["work"] = {{"steps", r.work->steps}, {"rhs_evaluations", r.work->rhs_evaluations}};
  report_detail::add_inputs_and_revision(j, r.inputs);
  return j;
}

std::string rig_text(const Rig& rig, const RigResult& r) {
  std::string out = fmt::format("hertzdash {}: {}\n", rig.name, r.heading);
  std::size_t width = 0;
  for (const RigField& f : rig.results) width = std::max(width, f.name.size());
  for (std::size_t k = 0; k < rig.results.size(); ++k)
    if (rig.results[k].text && !std::holds_alternative<std::monostate>(r.scalars[k]))
      out += fmt::format("  {:<{}} {}\n", rig.results[k].name, width + 1, text_value(r.scalars[k]));
  std::vector<std::size_t> widths{6};
  out += fmt::format("  {:>6}", "n");
  for (const RigColumn& c : rig.table) {
    widths.push_back(std::max<std::size_t>(c.name.size(), 15));
    out += fmt::format(" {:>{}}", c.name, widths.back());
  }
  out += "\n";
  for (std::size_t n = 0; n < r.rows.size(); ++n) {
    out += fmt::format("  {:>6}", n);
    for (std::size_t c = 0; c < rig.table.size(); ++c)
      out += fmt::format(" {:>{}}", cell_text(rig.table[c], r.rows[n][c]), widths[c + 1]);
    out += "\n";
  }
  out += fmt::format("  ended: {}", r.end_reason);
  if (r.work) out += fmt::format("; {} steps, {} rhs evaluations", r.work->steps, r.work->rhs_evaluations);
  return out + "\n";
}

CsvWriter rig_table_csv(const Rig& rig, const RigResult& r) {
  std::vector<std::string> columns{"n"};
  for (const RigColumn& c : rig.table) columns.emplace_back(c.name);
  CsvWriter csv(fmt::format("hertzdash {}: {}", rig.name, rig.table_description), r.inputs, columns);
  for (std::size_t k = 0; k < rig.results.size(); ++k) {
    const RigValue& v = r.scalars[k];
    if (std::holds_alternative<std::monostate>(v)) continue;
    const std::string value = std::holds_alternative<double>(v) ? fmt::format("{}", std::get<double>(v)) : text_value(v);
    csv.add_comment(fmt::format("{}: {}", flat_name(rig.results[k].name), value));
  }
  for (const std::string& w : r.warnings) csv.add_comment("warning: " + w);
  for (std::size_t n = 0; n < r.rows.size(); ++n) {
    std::vector<CsvWriter::Cell> row{static_cast<long>(n)};
    for (std::size_t c = 0; c < rig.table.size(); ++c) {
      if (rig.table[c].integer) row.emplace_back(static_cast<long>(r.rows[n][c]));
      else row.emplace_back(r.rows[n][c]);
    }
    csv.add_row(row);
  }
  return csv;
}

}  // namespace hertzdash
