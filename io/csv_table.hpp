#pragma once
// Reading CSV files: one header row (the column names), then rows with exactly as many fields;
// '#' comment lines anywhere. The comment lines before the first row (above or below the header
// row: the suite writes its provenance below the column names, io/csv_writer.hpp) are the
// file's header lines, "# key: value". A UTF-8 byte-order mark and LF, CRLF or lone CR line ends are accepted; a
// file larger than max_table_bytes is refused before it is read. Numbers are decimal
// (io/decimal_number.hpp). Every error names the file, and where it applies the line and
// column: "FILE:LINE:COL: column 'NAME': ...".
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace hertzdash {

class DataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The largest table read: 16 MiB, a thousand times the largest table the project ships.
inline constexpr std::uintmax_t max_table_bytes = std::uintmax_t{16} << 20;

/// The values a field may take, and how a message says so ("> 0", "in (0, 1]").
struct ValueRange {
  bool (*contains)(double);
  const char* text;
};

class CsvTable {
 public:
  /// Read and check the file; throws DataError if it is missing, too large or malformed.
  static CsvTable read(const std::filesystem::path& path);

  const std::vector<std::string>& columns() const { return columns_; }
  std::size_t rows() const { return rows_.size(); }
  /// A comment line before the first row (above or below the column names), without the leading
  /// '#' (trimmed), where it is.
  struct Comment {
    std::string text;
    std::size_t line, column;  ///< 1-based; the column where `text` starts
  };
  const std::vector<Comment>& comments() const { return comments_; }
  /// The value (trimmed) of the comment line "key: value" before the first row, if there is one;
  /// throws DataError naming FILE:LINE:COL if two lines give `key`.
  std::optional<std::string> comment_field(const std::string& key) const;

  /// Throws DataError if the table lacks any of these columns.
  void require_columns(const std::vector<std::string>& names) const;
  /// Throws DataError if the table has no rows below its header.
  void require_rows() const;
  /// Throws DataError naming both lines if two rows have the same value in `column` (a key).
  void require_unique(const std::string& column) const;
  /// Field as text.
  const std::string& text(std::size_t row, const std::string& column) const;
  /// Field as a number; throws DataError naming file, line and column if it is not one.
  double number(std::size_t row, const std::string& column) const;
  /// Field as a number in `range`; throws DataError naming file, line, column and the range if not.
  double number(std::size_t row, const std::string& column, const ValueRange& range) const;
  /// Field as a number, or `fallback` if the field is empty.
  double number_or(std::size_t row, const std::string& column, double fallback) const;
  /// Field as a number in `range`, or `fallback` if the field is empty.
  double number_or(std::size_t row, const std::string& column, double fallback, const ValueRange& range) const;
  /// The first row whose `column` equals `value`; throws DataError if there is none.
  std::size_t find_row(const std::string& column, const std::string& value) const;
  /// "FILE:LINE" of a row, for messages about its content.
  std::string row_location(std::size_t row) const;
  /// "FILE:LINE:COL: column 'NAME'" of a field, for messages about its value.
  std::string field_location(std::size_t row, const std::string& column) const;

 private:
  std::size_t column_index(const std::string& name) const;

  std::string path_;
  std::vector<Comment> comments_;
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> rows_;
  std::vector<std::vector<std::size_t>> field_columns_;  ///< the 1-based column where each field starts
  std::vector<std::size_t> line_numbers_;
};

}  // namespace hertzdash
