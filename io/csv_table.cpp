#include "hertzdash/io/csv_table.hpp"

#include "hertzdash/io/decimal_number.hpp"

#include <algorithm>
#include <fstream>
#include <optional>

namespace hertzdash {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

// Split one line on commas; a field in double quotes may contain commas ("" is a quote).
std::vector<std::string> split(const std::string& line, bool& ok) {
  std::vector<std::string> out;
  std::string field;
  bool quoted = false;
  ok = true;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') field += '"', ++i;
      else if (c == '"') quoted = false;
      else field += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(trim(field)), field.clear();
    } else {
      field += c;
    }
  }
  ok = !quoted;
  out.push_back(trim(field));
  return out;
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw DataError("cannot read " + path.string());
  CsvTable t;
  t.path_ = path.string();
  std::string line;
  std::size_t n = 0;
  while (std::getline(in, line)) {
    ++n;
    const std::string s = trim(line);
    if (s.empty()) continue;
    if (s[0] == '#') {
      if (t.columns_.empty()) t.comments_.push_back(trim(s.substr(1)));
      continue;
    }
    bool ok = true;
    auto fields = split(s, ok);
    if (!ok) throw DataError(t.path_ + ":" + std::to_string(n) + ": unterminated quoted field");
    if (t.columns_.empty()) {
      t.columns_ = std::move(fields);
      continue;
    }
    if (fields.size() != t.columns_.size()) {
      throw DataError(t.path_ + ":" + std::to_string(n) + ": expected " + std::to_string(t.columns_.size()) +
                      " fields (" + std::to_string(t.columns_.size()) + " columns), got " +
                      std::to_string(fields.size()));
    }
    t.rows_.push_back(std::move(fields));
    t.line_numbers_.push_back(n);
  }
  if (t.columns_.empty()) throw DataError(t.path_ + ": no header row");
  return t;
}

std::map<std::string, std::string> CsvTable::comment_fields() const {
  std::map<std::string, std::string> fields;
  for (const std::string& line : comments_) {
    const auto colon = line.find(':');
    if (colon != std::string::npos) fields[trim(line.substr(0, colon))] = trim(line.substr(colon + 1));
  }
  return fields;
}

void CsvTable::require_columns(const std::vector<std::string>& names) const {
  for (const auto& name : names) column_index(name);
}

std::size_t CsvTable::column_index(const std::string& name) const {
  const auto it = std::find(columns_.begin(), columns_.end(), name);
  if (it == columns_.end()) throw DataError(path_ + ": missing column '" + name + "'");
  return static_cast<std::size_t>(it - columns_.begin());
}

std::string CsvTable::row_location(std::size_t row) const { return path_ + ":" + std::to_string(line_numbers_.at(row)); }

std::string CsvTable::where(std::size_t row, const std::string& column) const {
  return row_location(row) + ": column '" + column + "'";
}

const std::string& CsvTable::text(std::size_t row, const std::string& column) const {
  return rows_.at(row).at(column_index(column));
}

double CsvTable::number(std::size_t row, const std::string& column) const {
  const std::string& s = text(row, column);
  const std::optional<double> v = parse_decimal(s);
  if (!v) throw DataError(where(row, column) + ": '" + s + "' is not " + decimal_number_format);
  return *v;
}

double CsvTable::number_or(std::size_t row, const std::string& column, double fallback) const {
  return text(row, column).empty() ? fallback : number(row, column);
}

std::size_t CsvTable::find_row(const std::string& column, const std::string& value) const {
  const std::size_t c = column_index(column);
  for (std::size_t r = 0; r < rows_.size(); ++r)
    if (rows_[r][c] == value) return r;
  throw DataError(path_ + ": no row with " + column + " = '" + value + "'");
}

}  // namespace hertzdash
