// libFuzzer harness: the CSV table reader (io/csv_table.hpp). Any input must be read or refused
// with a DataError; every field of a table that was read is then taken as a number (which may
// refuse it with a DataError too). Anything else (a crash, a sanitizer report, another
// exception) is a finding.
#include "fuzz/input_file.hpp"
#include "hertzdash/io/csv_table.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const hertzdash::CsvTable t = hertzdash::CsvTable::read(hertzdash::fuzz::input_file(data, size));
    (void)t.comment_field("source");
    for (std::size_t r = 0; r < t.rows(); ++r)
      for (const std::string& c : t.columns()) {
        (void)t.text(r, c);
        try {
          (void)t.number_or(r, c, 0.0);
        } catch (const hertzdash::DataError&) {
        }
      }
    if (t.rows() > 0 && !t.columns().empty()) (void)t.find_row(t.columns().front(), t.text(0, t.columns().front()));
  } catch (const hertzdash::DataError&) {
  }
  return 0;
}
