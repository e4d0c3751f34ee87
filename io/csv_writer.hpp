#pragma once
// A CSV file with its provenance, built in memory and saved atomically. The first line names the
// columns, the provenance and comments follow as '#' lines, then the rows: so that
// pandas.read_csv(f, comment='#'), numpy.genfromtxt(f, delimiter=',', names=True, comments='#'),
// gnuplot's column('name') and io/csv_table.hpp all read the same column names.
#include "hertzdash/io/provenance.hpp"

#include <filesystem>
#include <string>
#include <variant>
#include <vector>

namespace hertzdash {

class CsvWriter {
 public:
  using Cell = std::variant<double, long, std::string>;

  /// `what` says what the file holds; `parameters` go into the header.
  CsvWriter(std::string what, Parameters parameters, std::vector<std::string> columns);

  /// A comment line ("# " + line) after the parameters, before the rows; `line` may not
  /// contain a line break.
  void add_comment(const std::string& line);

  /// One row; must have one cell per column. Doubles are written as the shortest text that reads
  /// back to the same double (fmt's "{}", Dragonbox: exact and several times faster than "{:.17g}").
  /// Text is written unquoted, a comma in it as ';', a double quote as '\'', a '#' as '*' and a line
  /// break as a blank: numpy.genfromtxt, one of the two readers every CSV must suit, does not read
  /// quotes, and it and pandas take '#' for the start of a comment.
  void add_row(const std::vector<Cell>& cells);

  std::string str() const;
  /// The column names, the provenance and the comments: str() without the rows.
  std::string head() const;
  /// The rows added since the last call, taken out of the writer: a long table written in
  /// pieces (head(), then take_rows() every few thousand rows) is never held whole.
  std::string take_rows();
  void save(const std::filesystem::path& path) const;

 private:
  std::string what_;
  Parameters parameters_;
  std::vector<std::string> columns_;
  std::string comments_;
  std::string body_;
};

}  // namespace hertzdash
