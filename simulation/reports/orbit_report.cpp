// A rig's periodic orbit as JSON and text (simulation/reports/orbit_report.hpp).
#include "hertzdash/simulation/reports/orbit_report.hpp"

#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>

#include <cmath>

namespace hertzdash {

namespace {

constexpr const char* method = "stroboscopic map, monodromy from saltation matrices (instantaneous impacts)";

std::string complex_text(std::complex<double> z) {
  if (z.imag() == 0) return fmt::format("{:.9g}", z.real());
  return fmt::format("{:.9g} {} {:.9g}i", z.real(), z.imag() < 0 ? '-' : '+', std::abs(z.imag()));
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
  j["method"] = method;
  j["converged"] = o.converged;
  if (!o.converged) j["failure"] = o.failure;
  j["period"] = r.period;
  j["section_phase"] = r.section_phase;
  j["guess"] = r.guess;
  if (o.state.size() == 2) {
    j["impacts_per_period"] = o.impacts.size();
    j["section_state"] = {{"position_m", o.state(0)}, {"velocity_mps", o.state(1)}};
    nlohmann::ordered_json multipliers = nlohmann::ordered_json::array(), moduli = nlohmann::ordered_json::array();
    for (const std::complex<double> l : o.multipliers) {
      multipliers.push_back({l.real(), l.imag()});
      moduli.push_back(std::abs(l));
    }
    j["multipliers"] = multipliers;
    j["multiplier_moduli"] = moduli;
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
  if (o.state.size() != 2) {
    line("failure", o.failure);
    return out;
  }
  if (!o.converged) line("failure", o.failure);
  line("period", fmt::format("{} drive cycle{}, {} impact{}", r.period, r.period == 1 ? "" : "s", o.impacts.size(),
                             o.impacts.size() == 1 ? "" : "s"));
  line("section_phase", fmt::format("{:.9g}", r.section_phase));
  line("section_state", fmt::format("position {:.8g} m, velocity {:.8g} m/s", to_resolution(o.state(0), r.scale(0)),
                                    to_resolution(o.state(1), r.scale(1))));
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

}  // namespace hertzdash
