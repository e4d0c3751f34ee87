// A table's and a recording's curves (simulation/reports/fit_curves.hpp).
#include "hertzdash/simulation/reports/fit_curves.hpp"

#include "hertzdash/model/air_drag.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace hertzdash {

namespace {

Parameters curves_header(const FitRun& run, const FitResult& f) {
  const bool bounce = run.kind == FitDataKind::bounce_times;
  Parameters h{{bounce ? "recording" : "table", bounce ? run.recording.path.string() : run.table.path.string()},
               {"synthetic", (bounce ? run.recording.synthetic : run.table.synthetic) ? "true" : "false"},
               {"damping", f.law}};
  for (const FittedParameter& p : f.parameters) h.emplace_back(p.name + "_estimate", fmt::format("{}", p.estimate));
  h.emplace_back("e_effective", fmt::format("{}", f.e_effective.value));
  h.emplace_back("e_effective_standard_error", fmt::format("{}", f.e_effective.standard_error));
  return h;
}

// The fitted model's e and its error at each row of the data (NaN where its impact does not separate).
std::map<std::size_t, ImpactRestitution> model_e_by_row(const FitResult& f) {
  std::map<std::size_t, ImpactRestitution> by_row;
  for (const ImpactRestitution& i : f.e_effective.impacts) by_row[i.row] = i;
  return by_row;
}

// The rebound speed whose return flight lasts `flight_s` (bisection: the flight's time grows
// with the speed), or NaN where none does.
double rebound_for_flight(double flight_s, double g, double v_t) {
  if (!(flight_s > 0)) return NAN;
  double lo = 0, hi = g * flight_s;  // in vacuum the speed is g T / 2; drag only lengthens it
  const auto time = [&](double v) { return return_flight(v, 0.0, g, v_t).value_or(ReturnFlight{}).time_s; };
  while (time(hi) < flight_s) {
    if (hi > 1e6) return NAN;
    hi *= 2;
  }
  for (int k = 0; k < 100 && hi - lo > 1e-14 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    (time(mid) < flight_s ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

CsvWriter recording_curves(const FitRun& run, const FitResult& f, const PaperParameters& paper) {
  CsvWriter csv("hertzdash fit: e per bounce (drag-corrected, from the intervals) and the fitted model's, per impact",
                curves_header(run, f),
                {"drop", "impact_number", "impact_time_s", "model_time_s", "residual_s", "speed_measured_mps",
                 "e_measured", "impact_speed_mps", "e_model", "e_model_se", "residual_e"});
  const DropTestSetup s = resolve_setup(f.fitted_options, paper);
  const double g = s.gravity_mps2, v_t = terminal_speed_mps(s.air_drag, s.mass_kg, s.ball_radius_m, g);
  const std::map<std::size_t, ImpactRestitution> model = model_e_by_row(f);
  double approach = NAN;  // the measured approach speed of the current row
  for (std::size_t i = 0; i < f.points.size(); ++i) {
    const FitPoint& p = f.points[i];
    const bool after_previous = i > 0 && f.points[i - 1].group == p.group && f.points[i - 1].number + 1 == p.number;
    if (!after_previous) approach = p.x;  // the first of a drop, or after a missed impact: the model's
    const auto m = model.find(i);
    const double e_model = m == model.end() ? NAN : m->second.e, e_se = m == model.end() ? NAN : m->second.standard_error;
    double e_measured = NAN, next_approach = NAN;
    const bool next = i + 1 < f.points.size() && f.points[i + 1].group == p.group && f.points[i + 1].number == p.number + 1;
    if (next && std::isfinite(e_model)) {
      const FitPoint& q = f.points[i + 1];
      const double model_rebound = e_model * p.x;
      const auto model_flight = return_flight(model_rebound, 0.0, g, v_t);
      const double contact_s = model_flight ? (q.model - p.model) - model_flight->time_s : 0.0;
      const double rebound = rebound_for_flight((q.measured - p.measured) - contact_s, g, v_t);
      if (std::isfinite(rebound)) {
        e_measured = rebound / approach;
        next_approach = return_flight(rebound, 0.0, g, v_t).value_or(ReturnFlight{0, NAN}).landing_speed_mps;
      }
    }
    csv.add_row({f.groups[*p.group].label, static_cast<long>(p.number), p.measured, p.model, p.residual, approach,
                 e_measured, p.x, e_model, e_se, e_measured - e_model});
    approach = next_approach;
  }
  return csv;
}

CsvWriter table_curves(const FitRun& run, const FitResult& f) {
  CsvWriter csv("hertzdash fit: the table's e and the fitted model's, per row", curves_header(run, f),
                {"speed_measured_mps", "e_measured", "e_sd", "impact_speed_mps", "e_model", "e_model_se", "residual_e"});
  const std::map<std::size_t, ImpactRestitution> model = model_e_by_row(f);
  for (std::size_t i = 0; i < f.points.size(); ++i) {
    const FitPoint& p = f.points[i];
    const auto m = model.find(i);
    csv.add_row({p.x, p.measured, run.table.has_sd() ? run.table.e_sd[i] : NAN, p.x, p.model,
                 m == model.end() ? NAN : m->second.standard_error, p.residual});
  }
  return csv;
}

}  // namespace

CsvWriter restitution_curves_csv(const FitRun& run, const FitResult& fit, const PaperParameters& paper) {
  switch (run.kind) {
    case FitDataKind::bounce_times: return recording_curves(run, fit, paper);
    case FitDataKind::restitution_table: return table_curves(run, fit);
    case FitDataKind::trace: break;
  }
  throw std::logic_error("restitution_curves_csv: a trace's curves are write_fit_curves'");
}

CsvWriter law_curve_csv(const FitRun& run, const FitResult& fit) {
  CsvWriter csv("hertzdash fit: the fitted law's e at the data's impacts, by speed, and its 1-sigma band",
                curves_header(run, fit), {"impact_speed_mps", "e_model", "e_low", "e_high"});
  std::vector<ImpactRestitution> at = fit.e_effective.impacts;
  std::sort(at.begin(), at.end(), [](const ImpactRestitution& a, const ImpactRestitution& b) { return a.speed_mps < b.speed_mps; });
  for (const ImpactRestitution& i : at) {  // no band where the error is unknown or infinite (a failed fit)
    const double se = std::isfinite(i.standard_error) ? i.standard_error : NAN;
    csv.add_row({i.speed_mps, i.e, i.e - se, i.e + se});
  }
  return csv;
}

}  // namespace hertzdash
