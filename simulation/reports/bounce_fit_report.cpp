// `fit --bounce-times`'s run and report (simulation/reports/bounce_fit_report.hpp): read a
// bounce recording, check it, fit one law or every law (and cross-validate), the warnings, the JSON.
#include "hertzdash/simulation/reports/bounce_fit_report.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>

namespace hertzdash {

using report_detail::correlation_json;
using report_detail::number_or_null;

BounceFitRun run_bounce_fit(const std::string& recording_path, const RunOptions& base, const PaperParameters& paper,
                            const BounceFitSettings& settings, bool compare_all_laws) {
  BounceFitRun r;
  r.settings = settings;
  if (compare_all_laws && base.damping != RunOptions{}.damping)
    throw InvalidParameter("damping", base.damping, "omitted with `compare-laws` (every registered law is fitted)");
  check_bounce_fit_options(base);
  {  // bad options are reported before the file is read
    RunOptions probe = base;
    probe.follows_flights = true;  // the model's flights read the air drag
    if (compare_all_laws) probe.damping = RunOptions{}.damping;
    probe.impact_velocity_mps = 1.0;
    resolve_setup(probe, paper);
  }
  r.recording = read_bounce_recording(recording_path);
  r.checked = check_bounce_recording(r.recording);
  const std::string path = r.recording.path.string();
  if (compare_all_laws) {
    BounceLawComparison c = compare_laws_on_bounces(r.checked, path, base, paper, settings);
    r.fits = std::move(c.fits);
    r.failures = std::move(c.failures);
  } else {
    r.fits.push_back(fit_bounce_recording(r.checked, path, base, paper, settings));
    if (settings.cross_validate)
      r.fits.back().cross_validation = cross_validate_bounces(r.checked, path, base, paper, settings, r.fits.back());
  }
  return r;
}

std::vector<RunDiagnostic> bounce_fit_diagnostics(const BounceFitRun& run, const BounceFit& f) {
  std::vector<RunDiagnostic> w;
  auto warn = [&w](const char* code, std::string message) { w.push_back({"warning", code, std::move(message), {}}); };
  const std::string law = run.fits.size() > 1 ? " (" + f.law + ")" : "";
  if (run.recording.synthetic)
    warn("synthetic_recording", "the bounce recording says 'synthetic: true': it is not a measurement");
  w.push_back({"note", "sigma_estimated",
               fmt::format("one common timing scatter is estimated from the residuals{}, sigma = {:.3g} s; the "
                           "standard errors come from sigma^2 (J^T J)^-1 and the reduced chi-square is 1 by "
                           "construction",
                           law, f.sigma),
               {}});
  if (!f.converged)
    warn("not_converged",
         fmt::format("the fit{} did not converge ({}): the estimates are where it stopped", law, f.stop_reason));
  if (f.failed)
    warn("fit_failed", fmt::format("the fit{} failed: {}; its estimates are where it stopped, not results", law, f.failure));
  else if (!f.identifiable)
    warn("not_identifiable",
         fmt::format("the recording does not determine the law's parameters{}: a correlation beyond {:g} or an "
                     "infinite standard error; fit fewer parameters",
                     law, identifiable_correlation_limit));
  for (const FittedParameter& p : f.parameters)
    if (p.at_bound)
      warn("at_bound", fmt::format("{}{} ended at a bound ({:.6g}); its standard error does not hold", p.name, law, p.estimate));
  if (f.cross_validation && !f.cross_validation->failure.empty())
    warn("cross_validation_failed", fmt::format("the cross-validation{} failed: {}", law, f.cross_validation->failure));
  return w;
}

std::vector<RunDiagnostic> bounce_fit_diagnostics(const BounceFitRun& run) {
  std::vector<RunDiagnostic> all;
  for (const BounceFlag& f : run.checked.flagged)
    all.push_back({"warning", "flagged",
                   fmt::format("drop '{}'{}: {}: {}", f.drop, f.index ? fmt::format(" index {}", *f.index) : "", f.kind,
                               f.reason),
                   {}});
  for (const std::string& note : run.checked.notes) all.push_back({"note", "bounce_check", note, {}});
  for (const BounceFit& f : run.fits)
    for (RunDiagnostic& d : bounce_fit_diagnostics(run, f)) {
      const bool once = d.code == "synthetic_recording" || d.code == "sigma_estimated";
      if (once && &f != &run.fits.front()) continue;
      if (d.code == "sigma_estimated" && run.fits.size() > 1)
        d.message = "each law's fit estimates one common timing scatter from its residuals (its sigma); the standard "
                    "errors come from sigma^2 (J^T J)^-1";
      all.push_back(std::move(d));
    }
  if (run.fits.empty() && run.recording.synthetic)
    all.push_back({"warning", "synthetic_recording", "the bounce recording says 'synthetic: true': it is not a measurement", {}});
  return all;
}

namespace {

nlohmann::ordered_json parameter_json(const FittedParameter& p) {
  return {{"estimate", number_or_null(p.estimate)},
          {"standard_error", number_or_null(p.standard_error)},
          {"initial", number_or_null(p.initial)}};
}

}  // namespace

nlohmann::ordered_json to_json(const BounceFitRun& run, const BounceFit& f) {
  nlohmann::ordered_json j;
  j["law"] = f.law;
  if (!f.left_out.empty()) j["left_out"] = f.left_out;
  j["parameters"] = report_detail::to_json(f.parameters);
  j["correlation"] = correlation_json(f.correlation);
  nlohmann::ordered_json drops = nlohmann::ordered_json::array();
  for (const BounceDropFit& d : f.drops)
    drops.push_back({{"drop", d.label},
                     {"impacts", d.impacts},
                     {"drop_height_m", d.drop_height_m > 0 ? nlohmann::ordered_json(d.drop_height_m) : nullptr},
                     {"first_impact_speed_mps", parameter_json(d.first_impact_speed)},
                     {"clock_offset_s", parameter_json(d.clock_offset)}});
  j["drops"] = drops;
  j["times"] = f.times;
  j["fitted_parameters"] = f.fitted;
  j["sigma_s"] = number_or_null(f.sigma);
  j["chi_square"] = f.chi_square;
  j["reduced_chi_square"] = number_or_null(f.reduced_chi_square);
  j["aic"] = f.aic;
  j["bic"] = f.bic;
  j["e_effective_range"] = {number_or_null(f.e_min), number_or_null(f.e_max)};
  j["identifiable"] = f.identifiable;
  j["iterations"] = f.iterations;
  j["model_runs"] = f.model_runs;
  j["integrator_used"] = f.integrator_used;
  j["stop_reason"] = f.stop_reason;
  j["converged"] = f.converged;
  j["failed"] = f.failed;
  j["failure"] = f.failure;
  if (f.cross_validation) {
    const BounceCrossValidation& cv = *f.cross_validation;
    const bool ok = cv.failure.empty();
    j["cross_validation"] = {{"folds", cv.folds},
                             {"rms_prediction_error_s", ok ? number_or_null(cv.rms_prediction_error) : nullptr},
                             {"scatter_s", ok ? number_or_null(cv.scatter) : nullptr},
                             {"ratio_to_scatter", ok ? number_or_null(cv.ratio) : nullptr},
                             {"failure", cv.failure}};
  }
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (const BouncePoint& p : f.points)
    points.push_back({{"drop", p.drop},
                      {"index", p.index},
                      {"impact_number", p.impact_number},
                      {"impact_speed_mps", number_or_null(p.impact_speed_mps)},
                      {"measured", p.measured},
                      {"model", number_or_null(p.model)},
                      {"residual", number_or_null(p.residual)}});
  j["points"] = points;
  j["warnings"] = to_json(bounce_fit_diagnostics(run, f));
  return j;
}

nlohmann::ordered_json to_json(const BounceFitRun& run) {
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["recording"] = {{"path", run.recording.path.string()},
                    {"source", run.recording.source},
                    {"synthetic", run.recording.synthetic},
                    {"drops", run.recording.drops.size()},
                    {"impacts", run.recording.impacts()},
                    {"used", run.checked.times()}};
  nlohmann::ordered_json flagged = nlohmann::ordered_json::array();
  for (const BounceFlag& f : run.checked.flagged)
    flagged.push_back({{"drop", f.drop},
                       {"index", f.index ? nlohmann::ordered_json(*f.index) : nullptr},
                       {"kind", f.kind},
                       {"reason", f.reason}});
  j["flagged"] = flagged;
  nlohmann::ordered_json fits = nlohmann::ordered_json::array();
  for (const BounceFit& f : run.fits) fits.push_back(to_json(run, f));
  j["fits"] = fits;
  nlohmann::ordered_json failures = nlohmann::ordered_json::array();
  for (const auto& [law, why] : run.failures) failures.push_back({{"law", law}, {"error", why}});
  j["failures"] = failures;
  j["warnings"] = to_json(bounce_fit_diagnostics(run));
  j["git_revision"] = git_revision();
  return j;
}

}  // namespace hertzdash
