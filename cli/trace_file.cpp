#include "cli/trace_file.hpp"

#include "hertzdash/io/csv_writer.hpp"

namespace hertzdash::cli {

void write_model_trace(const std::string& path, const std::vector<TraceSample>& samples, const std::string& source,
                       const std::string& contents, const Parameters& inputs) {
  Parameters header{{"source", source + ", SYNTHETIC (the model's output, not a measurement)"}, {"synthetic", "true"}};
  header.insert(header.end(), inputs.begin(), inputs.end());
  CsvWriter csv(contents, header, trace_columns());
  std::vector<CsvWriter::Cell> row;
  for (const TraceSample& s : samples) {
    row.clear();
    for (const TraceColumn& c : trace_column_table) row.emplace_back(c.value(s, samples.front()));
    csv.add_row(row);
  }
  csv.save(path);
}

}  // namespace hertzdash::cli
