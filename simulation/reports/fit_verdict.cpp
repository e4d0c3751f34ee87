// What a fit means, first and in one line (simulation/reports/fit_verdict.hpp).
#include "hertzdash/simulation/reports/fit_verdict.hpp"

#include "hertzdash/model/air_drag.hpp"

#include <fmt/format.h>
#include <gsl/gsl_cdf.h>

#include <algorithm>
#include <cmath>

namespace hertzdash {

namespace {

// "e 0.93 at 1.2 m/s to 0.90 at 3.1 m/s", from the slower impact to the faster.
std::string e_over_speeds(const EffectiveRestitution& e) {
  const bool rising = e.speed_at_min_mps < e.speed_at_max_mps;
  return fmt::format("e {:.4f} at {:.3g} m/s to {:.4f} at {:.3g} m/s", rising ? e.min : e.max,
                     rising ? e.speed_at_min_mps : e.speed_at_max_mps, rising ? e.max : e.min,
                     rising ? e.speed_at_max_mps : e.speed_at_min_mps);
}

// ", prediction error 0.00014 s against 0.0038 s (cross-validation)" where both were cross-validated.
std::string cross_validation_words(const FitResult& a, const FitResult& b, const char* unit) {
  if (!a.cross_validation || !b.cross_validation || !a.cross_validation->failure.empty() ||
      !b.cross_validation->failure.empty())
    return {};
  return fmt::format(", prediction error {:.3g}{} against {:.3g}{} (cross-validation)", a.cross_validation->rms_prediction_error,
                     unit, b.cross_validation->rms_prediction_error, unit);
}

std::string speed_dependence(const FitRun& run) {
  const FitResult& best = run.fits.front();
  const char* unit = run.kind == FitDataKind::bounce_times ? " s" : "";
  if (run.fits.size() == 1)
    return constant_e(best.e_effective)
               ? fmt::format("e is constant over the data's speeds under '{}'; `compare-laws` tests whether the data "
                             "show a dependence on speed",
                             best.law)
               : fmt::format("'{}' makes {}; `compare-laws` tests whether the data need it", best.law,
                             e_over_speeds(best.e_effective));
  const FitResult *constant = nullptr, *varying = nullptr;
  for (const FitResult& f : run.fits) {
    if (f.failed || !std::isfinite(f.e_effective.value)) continue;
    const FitResult*& slot = constant_e(f.e_effective) ? constant : varying;
    if (!slot) slot = &f;
  }
  if (!constant || !varying) return "speed dependence not tested: the laws fitted are all of one kind (constant e or not)";
  const double d = constant->aic - varying->aic;
  if (d >= aic_preference)
    return fmt::format("e depends on speed: '{}' ({}) is preferred over the best constant-e law '{}' by dAIC {:.3g}{}",
                       varying->law, e_over_speeds(varying->e_effective), constant->law, d,
                       cross_validation_words(*varying, *constant, unit));
  if (d <= -aic_preference)
    return fmt::format("no dependence on speed shown: the constant-e law '{}' is preferred over the best "
                       "speed-dependent '{}' by dAIC {:.3g}{}",
                       constant->law, varying->law, -d, cross_validation_words(*constant, *varying, unit));
  return fmt::format("the data do not decide whether e depends on speed: '{}' (constant e) and '{}' (e varies) differ "
                     "by dAIC {:.2g}, below {:g}{}",
                     constant->law, varying->law, std::abs(d), aic_preference,
                     cross_validation_words(*constant, *varying, unit));
}

// Air drag on a recording's fastest flight: the loss of speed between a rebound and the next
// impact, as a change of the apparent e, against e's error.
std::string drag(const FitRun& run, const PaperParameters& paper) {
  const FitResult& best = run.fits.front();
  const RunOptions& o = best.fitted_options;
  const DropTestSetup s = resolve_setup(o, paper);
  const double given = o.air_density_kg_per_m3.value_or(0.0);
  AirDrag air = s.air_drag;
  air.air_density_kg_per_m3 = given > 0 ? given : standard_air_density_kg_per_m3;
  const double v_t = terminal_speed_mps(air, s.mass_kg, s.ball_radius_m, s.gravity_mps2);
  double fastest = 0;
  for (const FitPoint& p : best.points) fastest = std::max(fastest, std::isfinite(p.x) ? p.x : 0.0);
  const double rebound = fastest * best.e_effective.value;
  if (!(rebound > 0) || !(s.gravity_mps2 > 0)) return {};
  const Rise rise = rise_to_apex(rebound, s.gravity_mps2, v_t);
  const double change = best.e_effective.value * (1.0 - fall_from_rest(rise.height_m, s.gravity_mps2, v_t).speed_mps / rebound);
  const double error = best.e_effective.standard_error;
  if (!std::isfinite(error))
    return fmt::format("air drag {}: it lowers the apparent e by up to {:.2g} (e's error unknown)",
                       given > 0 ? "modelled" : "not modelled (`air-density`)", change);
  if (given > 0)
    return fmt::format("air drag modelled (`air-density` {:g}): it lowers the apparent e by up to {:.2g} ({:.3g} times "
                       "e's error)",
                       given, change, change / error);
  if (change > error)
    return fmt::format("air drag matters: air ({:g} kg/m^3) lowers the apparent e by up to {:.2g}, {:.3g} times e's "
                       "error; give `air-density`",
                       standard_air_density_kg_per_m3, change, change / error);
  return fmt::format("air drag negligible: air would lower the apparent e by up to {:.2g}, below e's error {:.2g}",
                     change, error);
}

std::string quality(const FitRun& run, const FitResult& f) {
  const bool bounce = run.kind == FitDataKind::bounce_times;
  if (f.sigma_estimated)
    return bounce ? fmt::format("precision not stated: the times scatter by {:.3g} s about the fit (`timing-sd` tests it)", f.sigma)
                  : fmt::format("precision not stated: e scatters by {:.3g} about the fit (an e_sd column tests it)", f.sigma);
  const std::string stated = bounce                                         ? fmt::format("`timing-sd` {:g} s", run.checked.timing_sd_s)
                             : run.kind == FitDataKind::restitution_table ? std::string("the table's e_sd")
                                                                          : std::string("the channels' noise");
  if (poor_fit(f))
    return fmt::format("poor fit: the residuals are {:.3g} times {} (reduced chi-square {:.3g})",
                       std::sqrt(f.reduced_chi_square), stated, f.reduced_chi_square);
  return fmt::format("the fit explains the data to {} (reduced chi-square {:.3g})", stated, f.reduced_chi_square);
}

}  // namespace

bool constant_e(const EffectiveRestitution& e) {
  return e.max - e.min < constant_e_span;
}

bool own_body(const FitResult& f) {
  const RunOptions& o = f.fitted_options;
  const std::pair<const char*, bool> pair_options[] = {
      {"mass", o.mass_kg.has_value()},     {"ball-E", o.ball_E_Pa.has_value()}, {"ball-nu", o.ball_nu.has_value()},
      {"ball-radius", o.ball_radius_m.has_value()}, {"rod-E", o.rod_E_Pa.has_value()}, {"rod-nu", o.rod_nu.has_value()}};
  for (const auto& option : pair_options) {  // no structured binding: clang 14 (make fuzz) cannot capture one
    const bool fitted = std::any_of(f.parameters.begin(), f.parameters.end(),
                                    [&](const FittedParameter& p) { return p.name == option.first; });
    if (option.second && !fitted) return true;
  }
  return false;
}

std::vector<std::size_t> aic_ranks(const std::vector<FitResult>& fits) {
  std::vector<std::size_t> rank(fits.size());
  for (std::size_t i = 0, first = 0; i < fits.size(); ++i) {
    const bool tie = i > 0 && !fits[i].failed && !fits[first].failed && fits[i].aic - fits[first].aic < aic_rank_tie;
    if (!tie) first = i;
    rank[i] = first + 1;
  }
  return rank;
}

std::vector<std::size_t> cv_ranks(const std::vector<FitResult>& fits) {
  std::vector<std::size_t> rank(fits.size(), 0), order;
  for (std::size_t i = 0; i < fits.size(); ++i)
    if (fits[i].cross_validation && fits[i].cross_validation->failure.empty()) order.push_back(i);
  const auto rms = [&fits](std::size_t i) { return fits[i].cross_validation->rms_prediction_error; };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return rms(a) < rms(b); });
  for (std::size_t k = 0, first = 0; k < order.size(); ++k) {
    if (k == 0 || !(rms(order[k]) - rms(order[first]) <= cv_rank_tie * rms(order[first]))) first = k;
    rank[order[k]] = first + 1;
  }
  return rank;
}

bool poor_fit(const FitResult& f) {
  if (f.sigma_estimated || f.n <= f.p || !(f.reduced_chi_square > poor_fit_reduced_chi_square)) return false;
  return gsl_cdf_chisq_Q(f.chi_square, static_cast<double>(f.n - f.p)) < poor_fit_probability;
}

std::string default_body_notice(const FitRun& run, const PaperParameters& paper) {
  if (run.kind == FitDataKind::trace || run.fits.empty() || own_body(run.fits.front())) return {};
  const RunOptions& o = run.fits.front().fitted_options;
  return fmt::format("the paper's {} rod ({:g} kg) on its nylon hemisphere: no `mass`, `ball-radius`, `ball-E`, "
                     "`ball-nu`, `rod-E` or `rod-nu` given (docs/balls.md)",
                     o.rod, resolve_setup(o, paper).mass_kg);
}

std::string fit_verdict(const FitRun& run, const PaperParameters& paper) {
  if (run.fits.empty()) return "no law could be fitted";
  const FitResult& best = run.fits.front();
  if (best.failed) return "the fit failed: " + best.failure;
  std::vector<std::string> clauses;
  if (!best.identifiable) clauses.push_back("the data do not determine the parameters (not_identifiable)");
  if (run.kind != FitDataKind::trace) clauses.push_back(speed_dependence(run));
  if (run.kind == FitDataKind::bounce_times)
    if (std::string d = drag(run, paper); !d.empty()) clauses.push_back(std::move(d));
  clauses.push_back(quality(run, best));
  std::string line;
  for (const std::string& c : clauses) line += (line.empty() ? "" : "; ") + c;
  return line;
}

std::vector<RunDiagnostic> unit_diagnostics(const FitRun& run, const PaperParameters& paper) {
  std::vector<RunDiagnostic> w;
  if (run.kind != FitDataKind::bounce_times || run.fits.empty() || run.fits.front().failed) return w;
  const FitResult& f = run.fits.front();
  const DropTestSetup s = resolve_setup(f.fitted_options, paper);
  const double v_t = terminal_speed_mps(s.air_drag, s.mass_kg, s.ball_radius_m, s.gravity_mps2);
  for (std::size_t d = 0; d < f.groups.size() && d < run.checked.drops.size(); ++d) {
    const double h = run.checked.drops[d].drop_height_m, v0 = f.groups[d].nuisances[0].estimate;
    if (!(h > 0) || !(v0 > 0)) continue;
    // The height the fitted speed falls from, with the run's drag: v0 = v_t sqrt(1 - exp(-2 g h /
    // v_t^2)) (model/air_drag.hpp) solved for h; in vacuum v0^2 / 2g.
    const double g = s.gravity_mps2, stated_speed = fall_from_rest(h, g, v_t).speed_mps;
    const double fall = std::isfinite(v_t) ? (v0 < v_t ? -v_t * v_t / (2 * g) * std::log1p(-(v0 / v_t) * (v0 / v_t)) : INFINITY)
                                           : v0 * v0 / (2 * g);
    const double ratio = h / fall;
    if (ratio > 0.5 && ratio < 2) continue;
    const double decades = std::log10(ratio), nearest = std::round(decades);
    std::string hint = "check the drop's height and its times";
    if (std::abs(decades - nearest) < 0.2 && nearest >= 1 && nearest <= 3)
      hint = fmt::format("a height in {} written in drop_height_m (the column is in metres)?",
                         nearest == 1 ? "dm" : nearest == 2 ? "cm" : "mm");
    else if (std::abs(decades - nearest) < 0.3 && nearest == -6)
      hint = "times in ms in the column impact_time_s (a fall a million times too long)? name it impact_time_ms";
    else if (nearest <= -1)
      hint = "the times in the wrong unit (ms in impact_time_s: name it impact_time_ms), or the height of another drop?";
    w.push_back({"warning", "drop_height_units",
                 fmt::format("drop '{}': its drop_height_m {:g} gives a first impact speed of {:.4g} m/s, the times "
                             "{:.4g} m/s (a fall of {:.3g} m): {}",
                             run.checked.drops[d].label, h, stated_speed, v0, fall, hint),
                 {}});
  }
  return w;
}

}  // namespace hertzdash
