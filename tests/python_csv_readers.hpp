#pragma once
// Reads CSV files the suite wrote with pandas.read_csv(f, comment='#') and
// numpy.genfromtxt(f, delimiter=',', names=True, comments='#') (tests/csv_readers/check_csv_readers.py),
// and compares the column names and row counts with hertzdash's own reader (io/csv_table.hpp).
#include "cli_runner.hpp"
#include "hertzdash/io/csv_table.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace hertzdash::test {

/// The checker's report, and whether every file passed.
struct PythonReadersResult {
  bool passed;
  std::string report;
};

/// Check `files`; the list the checker reads is written into `scratch`.
inline PythonReadersResult read_with_python_readers(const std::vector<std::filesystem::path>& files,
                                                    const std::filesystem::path& scratch) {
  const std::filesystem::path list = scratch / "csv_files.txt";
  {
    std::ofstream out(list);
    for (const auto& f : files) {
      const CsvTable t = CsvTable::read(f);
      std::string columns;
      for (const std::string& c : t.columns()) columns += (columns.empty() ? "" : ",") + c;
      out << f.string() << '\t' << columns << '\t' << t.rows() << '\n';
    }
  }
  const CliResult r = run_cli_program(HERTZDASH_PYTHON, std::string("'") + HERTZDASH_SOURCE_DIR +
                                                            "/tests/csv_readers/check_csv_readers.py' '" +
                                                            list.string() + "'");
  return {r.exit_code == 0, r.out + r.err};
}

}  // namespace hertzdash::test
