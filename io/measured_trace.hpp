#pragma once
// Measured drop-test traces to overlay on the model (Figs. 5 and 6). The format is
// defined in data/measurements/README.md: a header row with t_s and at least one of force_N,
// accel_mps2, velocity_mps, displacement_m (or the same quantities in the other units of
// trace_column_units(), read into SI), header lines "# key: value" (source, rod, height_m;
// optional synthetic) above or below it, then one row per sample. The trace the model writes
// (`hertzdash simulate --trace`) is in this format too, with model_trace_columns() besides.
// No measured trace ships: the paper printed its traces only as plots, and no
// machine-readable copy exists.
#include "hertzdash/io/provenance.hpp"

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
  std::vector<std::string> model_columns;  ///< the file's model_trace_columns(): read past, never fitted
};

/// The quantities a measured trace may carry besides the time, by their SI column names.
const std::vector<std::string>& measured_quantity_columns();

/// The columns a model trace (`hertzdash simulate --trace`) carries besides t_s and the measured
/// quantities: x_m (deformation), xdot_mps (its rate), contact_force_N (the force at the contact,
/// which the load cell reads only through an elastic rod's dynamics) and rod_accel_mps2 (the rod's
/// centre-of-mass acceleration). No instrument of the drop test measures them: the reader accepts
/// them and names them in MeasuredTrace::model_columns; nothing fits them.
const std::vector<std::string>& model_trace_columns();

/// Standard gravity [m/s^2], the unit of an acceleration column in g (accel_g).
inline constexpr double standard_gravity_mps2 = 9.80665;

/// A column name the reader accepts: the quantity (t_s or one of measured_quantity_columns())
/// in a unit, and the factor that converts it to SI (t_us: 1e-6; force_kN: 1e3; accel_g: 9.80665).
struct TraceColumnUnit {
  const char* column;
  const char* quantity;
  double si_factor;
};
const std::vector<TraceColumnUnit>& trace_column_units();

/// The samples of the quantity `name` (one of measured_quantity_columns()), or nullptr for another name.
std::vector<double>* quantity(MeasuredTrace& m, const std::string& name);
const std::vector<double>* quantity(const MeasuredTrace& m, const std::string& name);

/// Read and check one file; throws DataError naming the file (and line) of any defect.
MeasuredTrace read_measured_trace(const std::filesystem::path& path);

/// The four header lines of `m`: source, rod, height_m, synthetic ("# key: value").
std::string measured_trace_header(const MeasuredTrace& m);

/// The file of `m` in the measurement format (SI columns; NaN written as an empty field):
/// the column names, the four header lines, provenance_header(what, parameters) without the
/// parameters those lines give, the samples.
std::string measured_trace_text(const MeasuredTrace& m, const std::string& what, const Parameters& parameters);

/// measured_trace_text written atomically to `path`.
void write_measured_trace(const std::filesystem::path& path, const MeasuredTrace& m, const std::string& what,
                          const Parameters& parameters);

/// Every *.csv file in `dir` (sorted by name) whose header names `rod` and a height
/// within 0.5 mm of `height_m`. A missing directory has none; a malformed file throws.
std::vector<MeasuredTrace> find_measured_traces(const std::filesystem::path& dir, const std::string& rod,
                                                double height_m);

}  // namespace hertzdash
