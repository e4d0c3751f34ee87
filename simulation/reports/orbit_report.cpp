// What the orbit analyses print (simulation/reports/orbit_report.hpp): `orbit`, then
// `continue`, then `lyapunov`, then `basins`.
#include "hertzdash/simulation/reports/orbit_report.hpp"

#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>

namespace hertzdash {

namespace {

std::string complex_text(std::complex<double> z) {
  if (z.imag() == 0) return fmt::format("{:.9g}", z.real());
  return fmt::format("{:.9g} {} {:.9g}i", z.real(), z.imag() < 0 ? '-' : '+', std::abs(z.imag()));
}

/// "multipliers" ([re, im] each, largest modulus first) and "multiplier_moduli" into `j`.
void add_multipliers(nlohmann::ordered_json& j, const std::vector<std::complex<double>>& multipliers) {
  nlohmann::ordered_json pairs = nlohmann::ordered_json::array(), moduli = nlohmann::ordered_json::array();
  for (const std::complex<double> l : multipliers) {
    pairs.push_back({l.real(), l.imag()});
    moduli.push_back(std::abs(l));
  }
  j["multipliers"] = pairs;
  j["multiplier_moduli"] = moduli;
}

/// The section state z into `j`, one key per coordinate (position_m, velocity_mps, ...).
void add_state(nlohmann::ordered_json& j, std::span<const std::string_view> coordinates, const Eigen::VectorXd& z) {
  for (std::size_t k = 0; k < coordinates.size(); ++k) j[std::string(coordinates[k])] = z(static_cast<Eigen::Index>(k));
}

/// `x` to 1e-8 of its scale: Newton leaves the state uncertain beyond that (its residual is below
/// 1e-11 of the scales, the state's error that over the conditioning of M - I), and the text shows
/// no round-off noise (-1e-13 m/s is 0).
double to_resolution(double x, double scale) {
  const double unit = 1e-8 * scale;
  return std::round(x / unit) * unit + 0.0;
}

}  // namespace

nlohmann::ordered_json to_json(const Rig& rig, const OrbitResult& r) {
  using report_detail::number_or_null;
  const PeriodicOrbit& o = r.orbit;
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["rig"] = rig.name;
  j["method"] = r.method;
  j["converged"] = o.converged;
  if (!o.converged) j["failure"] = o.failure;
  j["period"] = r.period;
  j["section_phase"] = r.section_phase;
  j["guess"] = r.guess;
  if (o.state.size() == static_cast<Eigen::Index>(r.coordinates.size())) {
    j["impacts_per_period"] = o.impacts.size();
    add_state(j["section_state"], r.coordinates, o.state);
    add_multipliers(j, o.multipliers);
    j["stable"] = o.stable;
    j["newton_residual"] = o.residual;
    j["newton_iterations"] = o.iterations;
    j["min_impact_speed_mps"] = number_or_null(o.min_impact_speed_mps);
    nlohmann::ordered_json t = nlohmann::ordered_json::array(), phase = t, v = t, rebound = t;
    for (const SequenceImpact& i : o.impacts) {
      t.push_back(i.time_s);
      phase.push_back(i.phase);
      v.push_back(i.impact_speed_mps);
      rebound.push_back(i.rebound_speed_mps);
    }
    j["impact_time_s"] = t;
    j["impact_phase"] = phase;
    j["impact_speed_mps"] = v;
    j["rebound_speed_mps"] = rebound;
  }
  report_detail::add_inputs_and_revision(j, r.inputs);
  return j;
}

std::string orbit_text(const Rig& rig, const OrbitResult& r) {
  const double tolerance = ShootingOptions{}.tolerance;
  const PeriodicOrbit& o = r.orbit;
  std::string out = fmt::format("hertzdash orbit {}: {}\n", rig.name, r.heading);
  auto line = [&](std::string_view name, const std::string& value) { out += fmt::format("  {:<16} {}\n", name, value); };
  line("guess", r.guess);
  if (o.state.size() != static_cast<Eigen::Index>(r.coordinates.size())) {
    line("failure", o.failure);
    return out;
  }
  if (!o.converged) line("failure", o.failure);
  line("period", fmt::format("{} drive cycle{}, {} impact{}", r.period, r.period == 1 ? "" : "s", o.impacts.size(),
                             o.impacts.size() == 1 ? "" : "s"));
  line("section_phase", fmt::format("{:.9g}", r.section_phase));
  std::string state;
  for (std::size_t k = 0; k < r.coordinates.size(); ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    state += fmt::format("{}{} {:.8g}", k ? ", " : "", r.coordinates[k], to_resolution(o.state(i), r.scale(i)));
  }
  line("section_state", state);
  std::string multipliers, moduli;
  for (const std::complex<double> l : o.multipliers) {
    multipliers += (multipliers.empty() ? "" : ", ") + complex_text(l);
    moduli += fmt::format("{}{:.9g}", moduli.empty() ? "" : ", ", std::abs(l));
  }
  line("multipliers", multipliers);
  line("moduli", moduli);
  line("stable", o.stable ? "yes" : "no");
  line("newton", fmt::format("{} step{}, residual {}", o.iterations, o.iterations == 1 ? "" : "s",
                             o.converged ? fmt::format("below {:g}", tolerance) : fmt::format("{:.3g}", o.residual)));
  out += fmt::format("  {:>4} {:>16} {:>17} {:>17}\n", "n", "impact_phase", "impact_speed_mps", "rebound_speed_mps");
  for (std::size_t n = 0; n < o.impacts.size(); ++n) {
    const SequenceImpact& i = o.impacts[n];
    out += fmt::format("  {:>4} {:>16.10g} {:>17.10g} {:>17.10g}\n", n, i.phase, i.impact_speed_mps, i.rebound_speed_mps);
  }
  return out;
}

namespace {

constexpr const char* continuation_method =
    "pseudo-arclength continuation of the stroboscopic map's fixed points, monodromy from saltation matrices "
    "(instantaneous impacts)";

std::string event_line(const ContinuationResult& r, const BranchEvent& e) {
  return fmt::format("{} at {} = {:.9g} (branch {}, period {})", to_string(e.type), r.parameter, e.parameter, e.branch,
                     e.period);
}

}  // namespace

nlohmann::ordered_json to_json(const Rig& rig, const ContinuationResult& r) {
  using report_detail::number_or_null;
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["rig"] = rig.name;
  j["method"] = continuation_method;
  j["parameter"] = r.parameter;
  const std::string column = r.column;
  j["start"] = {{"period", r.start.period}, {"section_phase", r.start.section_phase}, {"guess", r.start.guess}};
  if (!r.failure.empty()) j["failure"] = r.failure;
  nlohmann::ordered_json branch = nlohmann::ordered_json::array();
  for (const BranchPoint& p : r.continuation.points) {
    nlohmann::ordered_json point{{"branch", p.branch}, {"period", p.period}, {column, p.parameter}};
    add_state(point, r.coordinates, p.state);
    add_multipliers(point, p.multipliers);
    point["stable"] = p.stable;
    point["impacts_per_period"] = p.impacts;
    point["impact_phase"] = p.impact_phases;
    point["min_impact_speed_mps"] = number_or_null(p.min_impact_speed_mps);
    point["min_flight_gap_m"] = number_or_null(p.min_flight_gap_m);
    branch.push_back(std::move(point));
  }
  j["branch"] = branch;
  nlohmann::ordered_json events = nlohmann::ordered_json::array();
  for (const BranchEvent& e : r.continuation.events)
    events.push_back({{"type", to_string(e.type)}, {"parameter", e.parameter}, {"branch", e.branch}, {"period", e.period}});
  j["events"] = events;
  j["ends"] = r.continuation.ends;
  report_detail::add_inputs_and_revision(j, r.inputs);
  return j;
}

std::string continuation_text(const Rig& rig, const ContinuationResult& r) {
  std::string out = fmt::format("hertzdash continue {}: {}\n", rig.name, r.heading);
  out += fmt::format("  start     period {}, section phase {:.9g}: {}\n", r.start.period, r.start.section_phase, r.start.guess);
  if (!r.failure.empty()) return out + fmt::format("  failure   {}\n", r.failure);
  for (const BranchEvent& e : r.continuation.events) out += "  event     " + event_line(r, e) + "\n";
  for (const std::string& end : r.continuation.ends) out += "  end       " + end + "\n";
  return out;
}

CsvWriter continuation_csv(const Rig& rig, const ContinuationResult& r) {
  std::vector<std::string> columns{"branch", "period", r.column};
  for (const std::string_view c : r.coordinates) columns.emplace_back(c);
  for (std::size_t k = 1; k <= r.coordinates.size(); ++k)
    for (const char* part : {"re", "im"}) columns.push_back(fmt::format("multiplier_{}_{}", k, part));
  for (const char* c : {"stable", "impacts_per_period", "min_impact_speed_mps", "min_flight_gap_m"}) columns.emplace_back(c);
  CsvWriter csv(fmt::format("hertzdash continue {}: one row per branch point (the orbit's state at the section, its "
                            "Floquet multipliers largest first; stable 1 or 0; an infinite closeness: no impact or "
                            "no flight minimum)",
                            rig.name),
                r.inputs, columns);
  if (!r.failure.empty()) csv.add_comment("failure: " + r.failure);
  for (const BranchEvent& e : r.continuation.events) csv.add_comment("event: " + event_line(r, e));
  for (const std::string& end : r.continuation.ends) csv.add_comment("end: " + end);
  for (const BranchPoint& p : r.continuation.points) {
    std::vector<CsvWriter::Cell> row{static_cast<long>(p.branch), static_cast<long>(p.period), p.parameter};
    for (Eigen::Index k = 0; k < p.state.size(); ++k) row.emplace_back(p.state(k));
    for (std::size_t k = 0; k < r.coordinates.size(); ++k) {
      const std::complex<double> l = k < p.multipliers.size() ? p.multipliers[k] : std::complex<double>(NAN, NAN);
      row.emplace_back(l.real());
      row.emplace_back(l.imag());
    }
    row.emplace_back(static_cast<long>(p.stable));
    row.emplace_back(static_cast<long>(p.impacts));
    row.emplace_back(p.min_impact_speed_mps);
    row.emplace_back(p.min_flight_gap_m);
    csv.add_row(row);
  }
  return csv;
}

namespace {

std::string numbers(const std::vector<double>& v) { return fmt::format("{:.6g}", fmt::join(v, ", ")); }

}  // namespace

nlohmann::ordered_json to_json(const Rig& rig, const LyapunovResult& r) {
  const LyapunovSpectrum& s = r.spectrum;
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["rig"] = rig.name;
  j["method"] = "QR method on the " + r.method;
  if (!s.failure.empty()) j["failure"] = s.failure;
  j["periods"] = s.periods;
  j["impacts"] = s.impacts;
  j["section_phase"] = r.section_phase;
  j["exponents_per_period"] = s.per_period;
  j["exponents_per_impact"] = s.per_impact;
  j["sum_per_impact"] = report_detail::number_or_null(s.sum_per_impact);
  j["expected_sum_per_impact"] = report_detail::number_or_null(s.expected_sum_per_impact);
  j["half_difference"] = s.half_difference;
  j["converged"] = s.converged;
  j["running"] = {{"periods", s.running_periods}, {"exponents_per_impact", s.running_per_impact}};
  report_detail::add_inputs_and_revision(j, r.inputs);
  return j;
}

std::string lyapunov_text(const Rig& rig, const LyapunovResult& r) {
  const LyapunovSpectrum& s = r.spectrum;
  std::string out = fmt::format("hertzdash lyapunov {}: {}\n", rig.name, r.heading);
  auto line = [&](std::string_view name, const std::string& value) { out += fmt::format("  {:<24} {}\n", name, value); };
  if (!s.failure.empty()) line("failure", s.failure);
  line("periods, impacts", fmt::format("{}, {}", s.periods, s.impacts));
  line("exponents per period", numbers(s.per_period));
  line("exponents per impact", numbers(s.per_impact));
  line("sum per impact", std::isnan(s.expected_sum_per_impact)
                             ? fmt::format("{:.9g}", s.sum_per_impact)
                             : fmt::format("{:.9g} (expected {:.9g})", s.sum_per_impact, s.expected_sum_per_impact));
  line("converged", fmt::format("{} (halves differ by {:.2g} per impact)", s.converged ? "yes" : "no", s.half_difference));
  return out;
}

namespace {

constexpr const char* basins_method = "a grid of starts at the section, each run by the impact-sequence driver and "
                                      "classified by its attractor (period and impact phases)";

const char* kind_name(BasinAttractor::Kind k) {
  switch (k) {
    case BasinAttractor::Kind::rest: return "rest";
    case BasinAttractor::Kind::no_period: return "no-period";
    case BasinAttractor::Kind::periodic: break;
  }
  return "periodic";
}

std::vector<double> axis(double lo, double hi, int n) {
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(cell_centre(lo, hi, i, n));
  return v;
}

}  // namespace

nlohmann::ordered_json to_json(const Rig& rig, const BasinsResult& r) {
  const BasinOptions& g = r.grid;
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["rig"] = rig.name;
  j["method"] = basins_method;
  if (!r.failure.empty()) j["failure"] = r.failure;
  j["section_phase"] = g.section_phase;
  j["position_m"] = axis(g.position_min_m, g.position_max_m, g.resolution);
  j["velocity_mps"] = axis(g.velocity_min_mps, g.velocity_max_mps, g.resolution);
  j["resolution"] = g.resolution;
  j["cell_transient"] = g.transient;
  j["cell_impacts"] = g.kept;
  const double total = static_cast<double>(r.basins.cell.size());
  nlohmann::ordered_json attractors = nlohmann::ordered_json::array();
  for (std::size_t i = 0; i < r.basins.attractors.size(); ++i) {
    const BasinAttractor& a = r.basins.attractors[i];
    attractors.push_back({{"index", i}, {"kind", kind_name(a.kind)}, {"period", a.period},
                          {"impacts_per_period", a.impacts_per_period}, {"impact_phase", a.phases}, {"cells", a.cells},
                          {"fraction", total > 0 ? static_cast<double>(a.cells) / total : 0.0}});
  }
  j["attractors"] = attractors;
  j["inside_wall"] = r.basins.inside_wall;
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  const auto n = static_cast<std::size_t>(g.resolution);
  for (std::size_t row = 0; row * n < r.basins.cell.size(); ++row)
    rows.push_back(std::vector<int>(r.basins.cell.begin() + static_cast<long>(row * n),
                                    r.basins.cell.begin() + static_cast<long>((row + 1) * n)));
  j["cell"] = rows;
  report_detail::add_inputs_and_revision(j, r.inputs);
  return j;
}

std::string basins_text(const Rig& rig, const BasinsResult& r) {
  const BasinOptions& g = r.grid;
  std::string out = fmt::format("hertzdash basins {}: {}\n", rig.name, r.heading);
  auto line = [&](std::string_view name, const std::string& value) { out += fmt::format("  {:<14} {}\n", name, value); };
  if (!r.failure.empty()) {
    line("failure", r.failure);
    return out;
  }
  line("section_phase", fmt::format("{:.9g}", g.section_phase));
  line("grid", fmt::format("{} x {}: position {:.6g} .. {:.6g} m, velocity {:.6g} .. {:.6g} m/s", g.resolution,
                           g.resolution, g.position_min_m, g.position_max_m, g.velocity_min_mps, g.velocity_max_mps));
  const double total = static_cast<double>(r.basins.cell.size());
  for (std::size_t i = 0; i < r.basins.attractors.size(); ++i) {
    const BasinAttractor& a = r.basins.attractors[i];
    line(fmt::format("attractor {}", i),
         fmt::format("{}{}: {:.1f} % of the starts", a.describe(),
                     a.phases.empty() ? "" : fmt::format(", phases {:.6f}", fmt::join(a.phases, " ")),
                     100.0 * static_cast<double>(a.cells) / total));
  }
  if (r.basins.inside_wall > 0)
    line("inside a wall", fmt::format("{:.1f} % of the starts", 100.0 * static_cast<double>(r.basins.inside_wall) / total));
  return out;
}

CsvWriter basins_csv(const Rig& rig, const BasinsResult& r) {
  const BasinOptions& g = r.grid;
  CsvWriter csv(fmt::format("hertzdash basins {}: one row per start at the section (attractor -1: inside a wall)", rig.name),
                r.inputs, {"position_m", "velocity_mps", "attractor", "period", "impacts_per_period"});
  if (!r.failure.empty()) csv.add_comment("failure: " + r.failure);
  for (std::size_t i = 0; i < r.basins.attractors.size(); ++i)
    csv.add_comment(fmt::format("attractor {}: {}", i, r.basins.attractors[i].describe()));
  const int n = g.resolution;
  for (std::size_t c = 0; c < r.basins.cell.size(); ++c) {
    const int row = static_cast<int>(c) / n, col = static_cast<int>(c) % n, a = r.basins.cell[c];
    const BasinAttractor* at = a >= 0 ? &r.basins.attractors[static_cast<std::size_t>(a)] : nullptr;
    csv.add_row({cell_centre(g.position_min_m, g.position_max_m, col, n), cell_centre(g.velocity_min_mps, g.velocity_max_mps, row, n),
                 static_cast<long>(a), static_cast<long>(at ? at->period : 0), static_cast<long>(at ? at->impacts_per_period : 0)});
  }
  return csv;
}

}  // namespace hertzdash
