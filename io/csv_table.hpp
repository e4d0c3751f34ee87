#pragma once
// Reading the CSV files under data/: '#' comment lines, one header row, then rows
// with exactly as many fields. Every error names the file, the line and the column.
#include <filesystem>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace hertzdash {

class DataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class CsvTable {
 public:
  /// Read and check the file; throws DataError if it is missing or malformed.
  static CsvTable read(const std::filesystem::path& path);

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t rows() const { return rows_.size(); }
  /// The comment lines before the header, without the leading '#'.
  const std::vector<std::string>& comments() const { return comments_; }
  /// The comment lines of the form "key: value", as key -> value (both trimmed).
  std::map<std::string, std::string> comment_fields() const;

  /// Throws DataError if the table lacks any of these columns.
  void require_columns(const std::vector<std::string>& names) const;
  /// Field as text.
  const std::string& text(std::size_t row, const std::string& column) const;
  /// Field as a number; throws DataError naming file, line and column if it is not one.
  double number(std::size_t row, const std::string& column) const;
  /// Field as a number, or `fallback` if the field is empty.
  double number_or(std::size_t row, const std::string& column, double fallback) const;
  /// The first row whose `column` equals `value`; throws DataError if there is none.
  std::size_t find_row(const std::string& column, const std::string& value) const;
  /// "FILE:LINE" of a row, for messages about its content.
  std::string row_location(std::size_t row) const;

 private:
  std::size_t column_index(const std::string& name) const;
  std::string where(std::size_t row, const std::string& column) const;

  std::string path_;
  std::vector<std::string> comments_;
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<std::size_t> line_numbers_;
};

}  // namespace hertzdash
