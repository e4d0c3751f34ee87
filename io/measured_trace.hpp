#pragma once
// Measured drop-test traces to overlay on the model (Figs. 5 and 6). The format is
// defined in data/measurements/README.md: provenance comment lines "# key: value"
// (source, rod, height_m; optional synthetic), a header row with t_s and at least
// one of force_N, accel_mps2, velocity_mps, displacement_m, then one row per sample.
// No measured trace ships: the paper printed its traces only as plots, and no
// machine-readable copy exists.
#include <filesystem>
#include <string>
#include <vector>

namespace hertzdash {

/// One measured trace. Quantities follow the model's conventions (SI, time from
/// contact onset, force compressive positive, rod motion downward positive); a
/// quantity not measured at a sample is NaN, one not measured at all is empty.
struct MeasuredTrace {
  std::filesystem::path path;
  std::string source;      ///< provenance: who measured it, where it was published
  std::string rod;         ///< Table 1 rod name
  double height_m = 0;     ///< drop height [m]
  bool synthetic = false;  ///< true for a made-up trace (tests, demonstrations)
  std::vector<double> t_s, force_N, accel_mps2, velocity_mps, displacement_m;
};

/// The columns a measured trace may carry besides t_s.
const std::vector<std::string>& measured_quantity_columns();

/// Read and check one file; throws DataError naming the file (and line) of any defect.
MeasuredTrace read_measured_trace(const std::filesystem::path& path);

/// Every *.csv file in `dir` (sorted by name) whose header names `rod` and a height
/// within 0.5 mm of `height_m`. A missing directory has none; a malformed file throws.
std::vector<MeasuredTrace> find_measured_traces(const std::filesystem::path& dir, const std::string& rod,
                                                double height_m);

}  // namespace hertzdash
