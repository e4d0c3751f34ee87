#include "hertzdash/io/measured_trace.hpp"

#include "hertzdash/io/csv_table.hpp"

#include <algorithm>
#include <cmath>

namespace hertzdash {

const std::vector<std::string>& measured_quantity_columns() {
  static const std::vector<std::string> columns{"force_N", "accel_mps2", "velocity_mps", "displacement_m"};
  return columns;
}

MeasuredTrace read_measured_trace(const std::filesystem::path& path) {
  const CsvTable t = CsvTable::read(path);
  const std::string file = path.string();
  const auto fields = t.comment_fields();
  auto required = [&](const std::string& key) {
    const auto it = fields.find(key);
    if (it == fields.end() || it->second.empty())
      throw DataError(file + ": missing header line '# " + key + ": ...' (see data/measurements/README.md)");
    return it->second;
  };

  MeasuredTrace m;
  m.path = path;
  m.source = required("source");
  m.rod = required("rod");
  const std::string h = required("height_m");
  char* end = nullptr;
  m.height_m = std::strtod(h.c_str(), &end);
  if (end != h.c_str() + h.size() || !(m.height_m > 0) || !std::isfinite(m.height_m))
    throw DataError(file + ": header 'height_m: " + h + "' must be a finite number > 0 (m)");
  if (const auto s = fields.find("synthetic"); s != fields.end()) {
    if (s->second != "true" && s->second != "false")
      throw DataError(file + ": header 'synthetic: " + s->second + "' must be true or false");
    m.synthetic = s->second == "true";
  }

  t.require_columns({"t_s"});
  for (const std::string& c : t.columns()) {
    const auto& known = measured_quantity_columns();
    if (c != "t_s" && std::find(known.begin(), known.end(), c) == known.end())
      throw DataError(file + ": unknown column '" + c + "' (allowed: t_s, force_N, accel_mps2, velocity_mps, "
                      "displacement_m)");
  }
  if (t.columns().size() < 2) throw DataError(file + ": needs t_s and at least one measured quantity column");
  if (t.rows() < 2) throw DataError(file + ": needs at least two samples");

  auto column = [&](const std::string& name, std::vector<double>& out) {
    if (std::find(t.columns().begin(), t.columns().end(), name) == t.columns().end()) return;
    out.reserve(t.rows());
    for (std::size_t r = 0; r < t.rows(); ++r) out.push_back(t.number_or(r, name, NAN));
  };
  for (std::size_t r = 0; r < t.rows(); ++r) {
    m.t_s.push_back(t.number(r, "t_s"));
    if (r > 0 && !(m.t_s[r] > m.t_s[r - 1]))
      throw DataError(file + ": t_s must increase strictly (sample " + std::to_string(r + 1) + ")");
  }
  column("force_N", m.force_N);
  column("accel_mps2", m.accel_mps2);
  column("velocity_mps", m.velocity_mps);
  column("displacement_m", m.displacement_m);
  return m;
}

std::vector<MeasuredTrace> find_measured_traces(const std::filesystem::path& dir, const std::string& rod,
                                                double height_m) {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  if (fs::is_directory(dir))
    for (const auto& entry : fs::directory_iterator(dir))
      if (entry.is_regular_file() && entry.path().extension() == ".csv") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::vector<MeasuredTrace> found;
  for (const auto& f : files) {
    MeasuredTrace m = read_measured_trace(f);
    if (m.rod == rod && std::abs(m.height_m - height_m) <= 0.5e-3) found.push_back(std::move(m));
  }
  return found;
}

}  // namespace hertzdash
