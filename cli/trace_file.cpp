#include "cli/trace_file.hpp"

#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/simulation/run/distinct_time_samples.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace hertzdash::cli {

void write_model_trace(const std::string& path, const std::vector<TraceSample>& samples, const std::string& source,
                       const std::string& contents, const Parameters& inputs, double height_m) {
  Parameters header{{"source", source + ", SYNTHETIC (the model's output, not a measurement)"}, {"synthetic", "true"}};
  // The trace format's height_m: the inputs hold it for a drop from rest; a run given its impact
  // velocity gets the equivalent height, as a virtual measurement does.
  if (std::none_of(inputs.begin(), inputs.end(), [](const auto& p) { return p.first == "height_m"; }))
    header.emplace_back("height_m", fmt::format("{}", height_m));
  header.insert(header.end(), inputs.begin(), inputs.end());
  CsvWriter csv(contents, header, trace_columns());
  std::vector<CsvWriter::Cell> row;
  const std::vector<TraceSample> rows = distinct_time_samples(samples);
  for (const TraceSample& s : rows) {  // rows.front() exists inside the loop
    row.clear();
    for (const TraceColumn& c : trace_column_table) row.emplace_back(c.value(s, rows.front()));
    csv.add_row(row);
  }
  csv.save(path);
}

}  // namespace hertzdash::cli
