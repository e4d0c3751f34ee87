#include "hertzdash/io/measured_trace.hpp"

#include "hertzdash/io/atomic_file.hpp"
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/decimal_number.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <sstream>

namespace hertzdash {

const std::vector<std::string>& measured_quantity_columns() {
  static const std::vector<std::string> columns{"force_N", "accel_mps2", "velocity_mps", "displacement_m"};
  return columns;
}

const std::vector<std::string>& model_trace_columns() {
  static const std::vector<std::string> columns{"x_m", "xdot_mps", "contact_force_N", "rod_accel_mps2"};
  return columns;
}

const std::vector<TraceColumnUnit>& trace_column_units() {
  static const std::vector<TraceColumnUnit> units{
      {"t_s", "t_s", 1.0},
      {"t_ms", "t_s", 1e-3},
      {"t_us", "t_s", 1e-6},
      {"force_N", "force_N", 1.0},
      {"force_kN", "force_N", 1e3},
      {"accel_mps2", "accel_mps2", 1.0},
      {"accel_g", "accel_mps2", standard_gravity_mps2},
      {"velocity_mps", "velocity_mps", 1.0},
      {"velocity_mmps", "velocity_mps", 1e-3},
      {"displacement_m", "displacement_m", 1.0},
      {"displacement_mm", "displacement_m", 1e-3},
      {"displacement_um", "displacement_m", 1e-6},
  };
  return units;
}

namespace {

const TraceColumnUnit* find_column_unit(const std::string& column) {
  for (const TraceColumnUnit& u : trace_column_units())
    if (u.column == column) return &u;
  return nullptr;
}

std::string allowed_columns() {
  std::string s;
  for (const TraceColumnUnit& u : trace_column_units()) s += (s.empty() ? "" : ", ") + std::string(u.column);
  for (const std::string& c : model_trace_columns()) s += ", " + c;
  return s + " (the last four: a model trace's own, never fitted)";
}

}  // namespace

MeasuredTrace read_measured_trace(const std::filesystem::path& path) {
  const CsvTable t = CsvTable::read(path);
  const std::string file = path.string();
  auto required = [&](const std::string& key) {
    const std::optional<std::string> value = t.comment_field(key);
    if (!value || value->empty())
      throw DataError(file + ": missing header line '# " + key + ": ...' (see data/measurements/README.md)");
    return *value;
  };

  MeasuredTrace m;
  m.path = path;
  m.source = required("source");
  m.rod = required("rod");
  const std::string h = required("height_m");
  m.height_m = parse_decimal(h).value_or(NAN);
  if (decimal_error(h) == DecimalError::out_of_range)
    throw DataError(file + ": header 'height_m: " + h + "': " + decimal_refusal(h));
  if (!(m.height_m > 0))
    throw DataError(file + ": header 'height_m: " + h + "' must be a decimal number > 0 (m)");
  if (const std::optional<std::string> s = t.comment_field("synthetic")) {
    if (*s != "true" && *s != "false") throw DataError(file + ": header 'synthetic: " + *s + "' must be true or false");
    m.synthetic = *s == "true";
  }

  // Each column is a quantity with its unit (t_us, force_kN, ...), read into SI; one column per quantity.
  std::map<std::string, std::string> column_of;  // SI quantity -> the file's column
  const std::vector<std::string>& model_only = model_trace_columns();
  for (const std::string& c : t.columns()) {
    if (std::find(model_only.begin(), model_only.end(), c) != model_only.end()) {
      m.model_columns.push_back(c);
      continue;
    }
    const TraceColumnUnit* u = find_column_unit(c);
    if (!u) throw DataError(file + ": unknown column '" + c + "' (allowed: " + allowed_columns() + ")");
    if (!column_of.emplace(u->quantity, c).second)
      throw DataError(file + ": columns '" + column_of[u->quantity] + "' and '" + c + "' are the same quantity");
  }
  if (!column_of.count("t_s")) throw DataError(file + ": missing the time column (t_s, t_ms or t_us)");
  if (column_of.size() < 2) throw DataError(file + ": needs a time column and at least one measured quantity column");
  if (t.rows() < 2) throw DataError(file + ": needs at least two samples");

  auto column = [&](const std::string& quantity, std::vector<double>& out) {
    const auto it = column_of.find(quantity);
    if (it == column_of.end()) return;
    const double factor = find_column_unit(it->second)->si_factor;
    out.reserve(t.rows());
    for (std::size_t r = 0; r < t.rows(); ++r) out.push_back(factor * t.number_or(r, it->second, NAN));
  };
  column("t_s", m.t_s);
  for (std::size_t r = 0; r < m.t_s.size(); ++r) {
    if (std::isnan(m.t_s[r])) throw DataError(fmt::format("{}: sample {} has no time", file, r + 1));
    if (r > 0 && !(m.t_s[r] > m.t_s[r - 1]))
      throw DataError(file + ": the time must increase strictly (sample " + std::to_string(r + 1) + ")");
  }
  column("force_N", m.force_N);
  column("accel_mps2", m.accel_mps2);
  column("velocity_mps", m.velocity_mps);
  column("displacement_m", m.displacement_m);
  return m;
}

namespace {

// The column of `name` in a trace, const or not.
template <class Trace>
auto* quantity_in(Trace& m, const std::string& name) {
  if (name == "force_N") return &m.force_N;
  if (name == "accel_mps2") return &m.accel_mps2;
  if (name == "velocity_mps") return &m.velocity_mps;
  if (name == "displacement_m") return &m.displacement_m;
  return static_cast<decltype(&m.force_N)>(nullptr);
}

}  // namespace

std::vector<double>* quantity(MeasuredTrace& m, const std::string& name) { return quantity_in(m, name); }

const std::vector<double>* quantity(const MeasuredTrace& m, const std::string& name) { return quantity_in(m, name); }

std::string measured_trace_header(const MeasuredTrace& m) {
  return fmt::format("# source: {}\n# rod: {}\n# height_m: {}\n# synthetic: {}\n", m.source, m.rod, m.height_m,
                     m.synthetic ? "true" : "false");
}

std::string measured_trace_text(const MeasuredTrace& m, const std::string& what, const Parameters& parameters) {
  std::ostringstream out;
  std::vector<std::string> names{"t_s"};
  std::vector<const std::vector<double>*> columns{&m.t_s};
  for (const std::string& c : measured_quantity_columns())
    if (const auto* q = quantity(m, c); !q->empty()) {
      names.push_back(c);
      columns.push_back(q);
    }
  for (std::size_t i = 0; i < names.size(); ++i) out << (i ? "," : "") << names[i];
  // The header lines give source, rod, height_m and synthetic: a parameter of the same key is theirs.
  Parameters others;
  for (const auto& p : parameters)
    if (p.first != "source" && p.first != "rod" && p.first != "height_m" && p.first != "synthetic") others.push_back(p);
  out << "\n" << measured_trace_header(m) << provenance_header(what, others);
  for (std::size_t r = 0; r < m.t_s.size(); ++r) {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      const double v = (*columns[i])[r];
      out << (i ? "," : "") << (std::isnan(v) ? std::string() : fmt::format("{:.17g}", v));
    }
    out << "\n";
  }
  return out.str();
}

void write_measured_trace(const std::filesystem::path& path, const MeasuredTrace& m, const std::string& what,
                          const Parameters& parameters) {
  write_file_atomically(path, measured_trace_text(m, what, parameters));
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
