// Reading and writing restitution tables (io/restitution_table.hpp; the format:
// data/measurements/README.md, "Restitution tables") on the CSV reader (io/csv_table.hpp).
#include "hertzdash/io/restitution_table.hpp"

#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/csv_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

namespace hertzdash {

namespace {

const std::string speed_column = "impact_speed_m_per_s", e_column = "e", sd_column = "e_sd",
                  time_column = "contact_time_s";

bool finite_positive(double v) { return std::isfinite(v) && v > 0; }
bool restitution_range(double v) { return v > 0 && v <= 1; }

constexpr ValueRange positive_range{finite_positive, "a finite number > 0"};
constexpr ValueRange e_range{restitution_range, "in (0, 1]"};

std::string allowed_columns() {
  std::string s;
  for (const std::string& c : restitution_table_columns()) s += (s.empty() ? "" : ", ") + c;
  return s;
}

}  // namespace

const std::vector<std::string>& restitution_table_columns() {
  static const std::vector<std::string> columns{speed_column, e_column, sd_column, time_column};
  return columns;
}

RestitutionTable read_restitution_table(const std::filesystem::path& path) {
  const CsvTable t = CsvTable::read(path);
  const std::string file = path.string();
  RestitutionTable out;
  out.path = path;
  const std::optional<std::string> source = t.comment_field("source");
  if (!source || source->empty())
    throw DataError(file + ": missing header line '# source: ...' (provenance: who measured it, where it was published; "
                           "see data/measurements/README.md)");
  out.source = *source;
  if (const std::optional<std::string> s = t.comment_field("synthetic")) {
    if (*s != "true" && *s != "false") throw DataError(file + ": header 'synthetic: " + *s + "' must be true or false");
    out.synthetic = *s == "true";
  }
  const std::vector<std::string>& known = restitution_table_columns();
  for (const std::string& c : t.columns())
    if (std::find(known.begin(), known.end(), c) == known.end())
      throw DataError(file + ": unknown column '" + c + "' (allowed: " + allowed_columns() +
                      "; units are in the names: the speed in m/s, the contact time in s)");
  t.require_columns({speed_column, e_column});
  if (t.rows() < 2) throw DataError(file + ": needs at least two rows (impact speeds and their e)");
  const auto& columns = t.columns();
  const bool has_sd = std::find(columns.begin(), columns.end(), sd_column) != columns.end();
  const bool has_time = std::find(columns.begin(), columns.end(), time_column) != columns.end();
  for (std::size_t r = 0; r < t.rows(); ++r) {
    out.impact_speed_mps.push_back(t.number(r, speed_column, positive_range));
    out.e.push_back(t.number(r, e_column, e_range));
    if (has_sd) out.e_sd.push_back(t.number(r, sd_column, positive_range));
    if (has_time) out.contact_time_s.push_back(t.number_or(r, time_column, NAN, positive_range));
  }
  return out;
}

std::string restitution_table_text(const RestitutionTable& t, const std::string& what, const Parameters& parameters) {
  std::ostringstream out;
  out << speed_column << "," << e_column << (t.has_sd() ? "," + sd_column : "")
      << (t.contact_time_s.empty() ? "" : "," + time_column) << "\n";
  out << "# source: " << t.source << "\n# synthetic: " << (t.synthetic ? "true" : "false") << "\n";
  Parameters others;
  for (const auto& p : parameters)
    if (p.first != "source" && p.first != "synthetic") others.push_back(p);
  out << provenance_header(what, others);
  for (std::size_t r = 0; r < t.rows(); ++r) {
    out << fmt::format("{:.17g},{:.17g}", t.impact_speed_mps[r], t.e[r]);
    if (t.has_sd()) out << fmt::format(",{:.17g}", t.e_sd[r]);
    if (!t.contact_time_s.empty())
      out << "," << (std::isnan(t.contact_time_s[r]) ? std::string() : fmt::format("{:.17g}", t.contact_time_s[r]));
    out << "\n";
  }
  return out.str();
}

void write_restitution_table(const std::filesystem::path& path, const RestitutionTable& t, const std::string& what,
                             const Parameters& parameters) {
  write_file_atomically(path, restitution_table_text(t, what, parameters));
}

}  // namespace hertzdash
