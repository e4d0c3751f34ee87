#include "hertzdash/io/csv_writer.hpp"

#include "hertzdash/io/atomic_file.hpp"

#include <fmt/format.h>

#include <iterator>
#include <stdexcept>
#include <utility>

namespace hertzdash {

namespace {
// A text cell as every reader splits it the same way: numpy.genfromtxt does not read quoted
// fields and pandas and numpy cut a line at '#', so a cell holds no comma, double quote, '#' or line
// break (';', '\'', '*' and ' ' stand for them).
std::string plain_text_cell(const std::string& v) {
  std::string out = v;
  for (char& c : out) {
    if (c == ',') c = ';';
    else if (c == '"') c = '\'';
    else if (c == '#') c = '*';
    else if (c == '\n' || c == '\r') c = ' ';
  }
  return out;
}
}  // namespace

CsvWriter::CsvWriter(std::string what, Parameters parameters, std::vector<std::string> columns)
    : what_(std::move(what)), parameters_(std::move(parameters)), columns_(std::move(columns)) {}

void CsvWriter::add_comment(const std::string& line) {
  if (line.find_first_of("\r\n") != std::string::npos) throw std::logic_error("CsvWriter: a comment line with a line break");
  comments_ += "# " + line + "\n";
}

void CsvWriter::add_row(const std::vector<Cell>& cells) {
  if (cells.size() != columns_.size()) {
    throw std::logic_error(fmt::format("CsvWriter: row has {} cells for {} columns", cells.size(), columns_.size()));
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i) body_ += ',';
    std::visit(
        [&](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, double>) fmt::format_to(std::back_inserter(body_), "{}", v);
          else if constexpr (std::is_same_v<T, long>) body_ += std::to_string(v);
          else body_ += plain_text_cell(v);
        },
        cells[i]);
  }
  body_ += '\n';
}

std::string CsvWriter::head() const {
  std::string header;
  for (std::size_t i = 0; i < columns_.size(); ++i) header += (i ? "," : "") + columns_[i];
  return header + "\n" + provenance_header(what_, parameters_) + comments_;
}

std::string CsvWriter::str() const { return head() + body_; }

std::string CsvWriter::take_rows() { return std::exchange(body_, std::string()); }

void CsvWriter::save(const std::filesystem::path& path) const { write_file_atomically(path, str()); }

}  // namespace hertzdash
