#include "hertzdash/io/csv_table.hpp"

#include "hertzdash/io/decimal_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <istream>
#include <map>
#include <optional>
#include <string_view>
#include <system_error>

namespace hertzdash {

namespace {

constexpr const char* blanks = " \t\r";
constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(blanks);
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(blanks) - b + 1);
}

// The offset of the first byte of `line` that is a NUL or not UTF-8 text (RFC 3629: no overlong
// forms, surrogates or code points above U+10FFFF), or npos: a Latin-1 "é" in a label would
// otherwise reach the JSON writer, which refuses it after the whole fit.
std::size_t first_non_text_byte(std::string_view line) {
  const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(line[i]); };
  for (std::size_t i = 0; i < line.size();) {
    const unsigned b = byte(i);  // a sequence's length from its first byte; its second byte's range
    const std::size_t n = b == 0 ? 0 : b < 0x80 ? 1 : b < 0xC2 ? 0 : b < 0xE0 ? 2 : b < 0xF0 ? 3 : b < 0xF5 ? 4 : 0;
    const unsigned lo = b == 0xE0 ? 0xA0 : b == 0xF0 ? 0x90 : 0x80, hi = b == 0xED ? 0x9F : b == 0xF4 ? 0x8F : 0xBF;
    if (n == 0 || i + n > line.size()) return i;
    for (std::size_t k = 1; k < n; ++k)
      if (byte(i + k) < (k == 1 ? lo : 0x80) || byte(i + k) > (k == 1 ? hi : 0xBF)) return i;
    i += n;
  }
  return std::string_view::npos;
}

struct Fields {
  std::vector<std::string> texts;
  std::vector<std::size_t> columns;  // 0-based offset of each field's first non-blank character
  bool terminated = true;            // false: a quoted field runs to the end of the line
};

// Split one line on commas; a field in double quotes may contain commas ("" is a quote).
Fields split(const std::string& line) {
  Fields out;
  std::string field;
  std::size_t start = 0;
  bool quoted = false;
  auto close_field = [&](std::size_t end) {
    const auto first = line.find_first_not_of(blanks, start);
    out.texts.push_back(trim(field));
    out.columns.push_back(first < end ? first : start);
    field.clear();
    start = end + 1;
  };
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') field += '"', ++i;
      else if (c == '"') quoted = false;
      else field += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      close_field(i);
    } else {
      field += c;
    }
  }
  close_field(line.size());
  out.terminated = !quoted;
  return out;
}

// Refuse a file beyond max_table_bytes before reading it (one that grows while it is read, or a
// pipe, is stopped at the limit by read_bounded).
void check_size(const std::filesystem::path& path) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > max_table_bytes)
    throw DataError(path.string() + ": " + std::to_string(size) + " bytes; a data table is at most 16 MiB (" +
                    std::to_string(max_table_bytes) + " bytes)");
}

// The whole of `in`, refused as soon as it exceeds max_table_bytes: at most that and one chunk
// are ever held, however long a line is.
std::string read_bounded(std::istream& in, const std::string& path) {
  std::string content;
  char chunk[1 << 16];
  errno = 0;  // the reason of a failed read below is the read's own, not an earlier call's
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    content.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (content.size() > max_table_bytes)
      throw DataError(path + ": more than " + std::to_string(max_table_bytes) +
                      " bytes; a data table is at most 16 MiB (read so far)");
  }
  if (in.bad()) {
    const int reason = errno;
    throw DataError(path + ": cannot read: " + (reason ? std::generic_category().message(reason) : "input error"));
  }
  return content;
}

// The 1-based column of a comment line's text, after the '#' and blanks.
std::size_t comment_column(std::string_view line) {
  const std::size_t hash = line.find('#');
  const std::size_t text = line.find_first_not_of(blanks, hash + 1);
  return (text == std::string_view::npos ? hash + 1 : text) + 1;
}

}  // namespace

CsvTable CsvTable::read(const std::filesystem::path& path) {
  check_size(path);
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw DataError(path.string() + ": cannot read: " + std::generic_category().message(errno));
  CsvTable t;
  t.path_ = path.string();
  const std::string content = read_bounded(in, t.path_);
  std::size_t n = 0;
  for (std::size_t begin = 0; begin < content.size();) {
    // A line ends at LF (Unix), CR LF (Windows) or a lone CR (classic Mac OS, some loggers).
    const std::size_t end = std::min(content.find_first_of("\r\n", begin), content.size());
    std::string line = content.substr(begin, end - begin);
    begin = end + (content.compare(end, 2, "\r\n") == 0 ? 2 : 1);
    ++n;
    if (n == 1 && line.rfind(byte_order_mark, 0) == 0) line.erase(0, byte_order_mark.size());
    if (const std::size_t bad = first_non_text_byte(line); bad != std::string_view::npos)
      throw DataError(fmt::format("{}:{}:{}: {}, not UTF-8 text; save the file as UTF-8 (a Latin-1 or Windows-1252 file "
                                  "is not)", t.path_, n, bad + 1, line[bad] == '\0' ? std::string("a NUL byte")
                                  : fmt::format("byte 0x{:02X}", static_cast<unsigned char>(line[bad]))));
    const std::string s = trim(line);
    if (s.empty()) continue;
    if (s[0] == '#') {
      if (t.rows_.empty()) t.comments_.push_back({trim(s.substr(1)), n, comment_column(line)});
      continue;
    }
    Fields fields = split(line);
    if (!fields.terminated) throw DataError(t.path_ + ":" + std::to_string(n) + ": unterminated quoted field");
    if (t.columns_.empty()) {
      std::map<std::string_view, std::size_t> first;  // name -> its column: n log n for a 16 MiB header
      for (std::size_t c = 0; c < fields.texts.size(); ++c)
        if (const auto [at, fresh] = first.emplace(fields.texts[c], c); !fresh)
          throw DataError(t.path_ + ":" + std::to_string(n) + ":" + std::to_string(fields.columns[c] + 1) + ": column '" +
                          fields.texts[c] + "' again (first at column " + std::to_string(fields.columns[at->second] + 1) +
                          "); each column name appears once");
      t.columns_ = std::move(fields.texts);
      continue;
    }
    if (fields.texts.size() != t.columns_.size()) {
      throw DataError(t.path_ + ":" + std::to_string(n) + ": expected " + std::to_string(t.columns_.size()) +
                      " fields (" + std::to_string(t.columns_.size()) + " columns), got " +
                      std::to_string(fields.texts.size()));
    }
    t.rows_.push_back(std::move(fields.texts));
    t.field_columns_.push_back(std::move(fields.columns));
    t.line_numbers_.push_back(n);
  }
  if (t.columns_.empty())
    throw DataError(t.path_ + ": the table is empty (no header row" + (n == 0 ? ", no lines" : "") + ")");
  return t;
}

std::optional<std::string> CsvTable::comment_field(const std::string& key) const {
  const Comment* found = nullptr;
  for (const Comment& c : comments_) {
    const auto colon = c.text.find(':');
    if (colon == std::string::npos || trim(c.text.substr(0, colon)) != key) continue;
    if (found)
      throw DataError(path_ + ":" + std::to_string(c.line) + ":" + std::to_string(c.column) + ": header key '" + key +
                      "' again (first on line " + std::to_string(found->line) + "); each header key appears once");
    found = &c;
  }
  if (!found) return std::nullopt;
  return trim(found->text.substr(found->text.find(':') + 1));
}

void CsvTable::require_columns(const std::vector<std::string>& names) const {
  for (const auto& name : names) column_index(name);
}

void CsvTable::require_rows() const {
  if (rows_.empty()) throw DataError(path_ + ": the table is empty (a header row and no rows below it)");
}

void CsvTable::require_unique(const std::string& column) const {
  const std::size_t c = column_index(column);
  std::map<std::string_view, std::size_t> first;  // value -> its first row
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const auto [it, inserted] = first.emplace(rows_[r][c], r);
    if (!inserted)
      throw DataError(field_location(r, column) + ": '" + rows_[r][c] + "' again (first on line " +
                      std::to_string(line_numbers_[it->second]) + "); each " + column + " appears once");
  }
}

std::size_t CsvTable::column_index(const std::string& name) const {
  const auto it = std::find(columns_.begin(), columns_.end(), name);
  if (it == columns_.end()) throw DataError(path_ + ": missing column '" + name + "'");
  return static_cast<std::size_t>(it - columns_.begin());
}

std::string CsvTable::row_location(std::size_t row) const { return path_ + ":" + std::to_string(line_numbers_.at(row)); }

std::string CsvTable::field_location(std::size_t row, const std::string& column) const {
  return row_location(row) + ":" + std::to_string(field_columns_.at(row).at(column_index(column)) + 1) + ": column '" +
         column + "'";
}

const std::string& CsvTable::text(std::size_t row, const std::string& column) const {
  return rows_.at(row).at(column_index(column));
}

double CsvTable::number(std::size_t row, const std::string& column) const {
  const std::string& s = text(row, column);
  const std::optional<double> v = parse_decimal(s);
  if (!v) throw DataError(field_location(row, column) + ": " + decimal_refusal(s));
  return *v;
}

double CsvTable::number(std::size_t row, const std::string& column, const ValueRange& range) const {
  const double v = number(row, column);
  if (!range.contains(v)) throw DataError(field_location(row, column) + ": " + text(row, column) + " is not " + range.text);
  return v;
}

double CsvTable::number_or(std::size_t row, const std::string& column, double fallback) const {
  return text(row, column).empty() ? fallback : number(row, column);
}

double CsvTable::number_or(std::size_t row, const std::string& column, double fallback, const ValueRange& range) const {
  return text(row, column).empty() ? fallback : number(row, column, range);
}

std::size_t CsvTable::find_row(const std::string& column, const std::string& value) const {
  const std::size_t c = column_index(column);
  for (std::size_t r = 0; r < rows_.size(); ++r)
    if (rows_[r][c] == value) return r;
  throw DataError(path_ + ": no row with " + column + " = '" + value + "'");
}

}  // namespace hertzdash
