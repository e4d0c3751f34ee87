// Reading and writing bounce recordings (io/bounce_recording.hpp; the format:
// data/measurements/README.md, "Bounce recordings") on the CSV reader (io/csv_table.hpp).
#include "hertzdash/io/bounce_recording.hpp"

#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/csv_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

namespace hertzdash {

namespace {

const std::string drop_column = "drop", time_column = "impact_time_s", time_ms_column = "impact_time_ms",
                  height_column = "drop_height_m";
/// The label of a recording's one drop when it has no `drop` column.
const std::string only_drop = "1";

bool finite(double v) { return std::isfinite(v); }
bool finite_positive(double v) { return std::isfinite(v) && v > 0; }

constexpr ValueRange time_range{finite, "a finite number"};
constexpr ValueRange height_range{finite_positive, "a finite number > 0"};

std::string allowed_columns() {
  std::string s;
  for (const std::string& c : bounce_recording_columns()) s += (s.empty() ? "" : ", ") + c;
  return s;
}

std::string trimmed(const std::string& s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string::npos) return {};
  return s.substr(first, s.find_last_not_of(" \t") - first + 1);
}

}  // namespace

bool plain_label(const std::string& label) {
  return !label.empty() && std::none_of(label.begin(), label.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return c == ',' || c == '"' || c == '#' || u < 0x20 || u == 0x7f;
  });
}

std::size_t BounceRecording::impacts() const {
  std::size_t n = 0;
  for (const RecordedDrop& d : drops) n += d.impact_time_s.size();
  return n;
}

const std::vector<std::string>& bounce_recording_columns() {
  static const std::vector<std::string> columns{drop_column, time_column, time_ms_column, height_column};
  return columns;
}

BounceRecording read_bounce_recording(const std::filesystem::path& path) {
  const CsvTable t = CsvTable::read(path);
  const std::string file = path.string();
  BounceRecording out;
  out.path = path;
  const std::optional<std::string> source = t.comment_field("source");
  if (!source || source->empty())
    throw DataError(file + ": missing header line '# source: ...' (provenance: who recorded it, how, where published; "
                           "see data/measurements/README.md)");
  out.source = *source;
  if (const std::optional<std::string> s = t.comment_field("synthetic")) {
    if (*s != "true" && *s != "false") throw DataError(file + ": header 'synthetic: " + *s + "' must be true or false");
    out.synthetic = *s == "true";
  }
  const std::vector<std::string>& known = bounce_recording_columns();
  for (const std::string& c : t.columns())
    if (std::find(known.begin(), known.end(), c) == known.end())
      throw DataError(file + ": unknown column '" + c + "' (allowed: " + allowed_columns() +
                      "; units are in the names: the times in s or ms, the height in m)");
  const auto& columns = t.columns();
  auto has = [&](const std::string& c) { return std::find(columns.begin(), columns.end(), c) != columns.end(); };
  if (has(time_column) && has(time_ms_column))
    throw DataError(file + ": both " + time_column + " and " + time_ms_column + " (one time column, in s or in ms)");
  const bool ms = has(time_ms_column);
  const std::string& times = ms ? time_ms_column : time_column;
  t.require_columns({times});
  if (t.rows() < 1) throw DataError(file + ": no impacts (one row per detected impact)");
  const bool has_height = has(height_column), has_drop = has(drop_column);
  std::map<std::string, std::size_t> index;  // label -> position in out.drops
  std::vector<std::string> height_where;     // where each drop's height was first given
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const std::string label = has_drop ? trimmed(t.text(r, drop_column)) : only_drop;
    if (label.empty()) throw DataError(t.field_location(r, drop_column) + ": empty drop label");
    if (!plain_label(label))
      throw DataError(t.field_location(r, drop_column) +
                      ": a drop label is text without commas, double quotes, '#' or control characters (so that "
                      "every CSV reader, pandas and numpy among them, reads it as written)");
    auto it = index.find(label);
    if (it == index.end()) {
      it = index.emplace(label, out.drops.size()).first;
      out.drops.push_back({label, {}, {}, 0.0});
      height_where.emplace_back();
    }
    RecordedDrop& d = out.drops[it->second];
    d.impact_time_s.push_back(ms ? t.number(r, times, time_range) / 1000.0 : t.number(r, times, time_range));
    d.where.push_back(t.row_location(r));
    if (!has_height) continue;
    const double h = t.number_or(r, height_column, 0.0, height_range);
    if (h == 0.0) continue;
    if (d.drop_height_m == 0.0) {
      d.drop_height_m = h;
      height_where[it->second] = t.row_location(r);
    } else if (h != d.drop_height_m) {
      throw DataError(fmt::format("{}: drop '{}' has drop_height_m {} here and {} at {} (one height per drop)",
                                  t.field_location(r, height_column), label, h, d.drop_height_m, height_where[it->second]));
    }
  }
  return out;
}

std::string bounce_recording_text(const BounceRecording& r, const std::string& what, const Parameters& parameters) {
  const bool heights = std::any_of(r.drops.begin(), r.drops.end(), [](const RecordedDrop& d) { return d.drop_height_m > 0; });
  std::ostringstream out;
  out << drop_column << "," << time_column << (heights ? "," + height_column : "") << "\n";
  out << "# source: " << r.source << "\n# synthetic: " << (r.synthetic ? "true" : "false") << "\n";
  Parameters others;
  for (const auto& p : parameters)
    if (p.first != "source" && p.first != "synthetic") others.push_back(p);
  out << provenance_header(what, others);
  for (const RecordedDrop& d : r.drops)
    for (double t : d.impact_time_s) {
      out << d.label << fmt::format(",{:.17g}", t);
      if (heights) out << "," << (d.drop_height_m > 0 ? fmt::format("{:.17g}", d.drop_height_m) : std::string());
      out << "\n";
    }
  return out.str();
}

void write_bounce_recording(const std::filesystem::path& path, const BounceRecording& r, const std::string& what,
                            const Parameters& parameters) {
  write_file_atomically(path, bounce_recording_text(r, what, parameters));
}

}  // namespace hertzdash
