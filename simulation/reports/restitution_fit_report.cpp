// `fit --restitution-table`'s run and report (simulation/reports/run_reports.hpp): read a
// restitution table, fit one law or every law (and cross-validate), the fit's warnings, its JSON.
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/simulation/fit/restitution_fit.hpp"
#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>

#include <cmath>

namespace hertzdash {

using report_detail::correlation_json;
using report_detail::number_or_null;

RestitutionFitRun run_restitution_fit(const std::string& table_path, const RunOptions& base,
                                      const PaperParameters& paper, const RestitutionFitSettings& settings,
                                      bool compare_all_laws) {
  RestitutionFitRun r;
  r.settings = settings;
  if (compare_all_laws && base.damping != RunOptions{}.damping)
    throw InvalidParameter("damping", base.damping, "omitted with `compare-laws` (every registered law is fitted)");
  check_restitution_fit_options(base);
  {  // bad options are reported before the file is read
    RunOptions probe = base;
    if (compare_all_laws) probe.damping = RunOptions{}.damping;
    resolve_setup(probe, paper);
  }
  r.table = read_restitution_table(table_path);
  if (compare_all_laws) {
    RestitutionLawComparison c = compare_laws_on_restitution(r.table, base, paper, settings);
    r.fits = std::move(c.fits);
    r.failures = std::move(c.failures);
  } else {
    r.fits.push_back(fit_restitution_table(r.table, base, paper, settings));
    if (settings.cross_validate)
      r.fits.back().cross_validation = cross_validate_restitution(r.table, base, paper, settings, r.fits.back());
  }
  return r;
}

std::vector<RunDiagnostic> restitution_fit_diagnostics(const RestitutionFitRun& run, const RestitutionFit& f) {
  std::vector<RunDiagnostic> w;
  auto warn = [&w](const char* code, std::string message) { w.push_back({"warning", code, std::move(message), {}}); };
  const std::string law = run.fits.size() > 1 ? " (" + f.law + ")" : "";
  if (run.table.synthetic)
    warn("synthetic_table", "the restitution table says 'synthetic: true': it is not a measurement");
  if (f.sigma_estimated)
    w.push_back({"note", "sigma_estimated",
                 fmt::format("the table has no e_sd: one common scatter of e is estimated from the residuals{}, "
                             "sigma = {:.3g}; the standard errors come from sigma^2 (J^T J)^-1 and the reduced "
                             "chi-square is 1 by construction",
                             law, f.sigma),
                 {}});
  if (!f.converged)
    warn("not_converged",
         fmt::format("the fit{} did not converge ({}): the estimates are where it stopped", law, f.stop_reason));
  if (f.failed)
    warn("fit_failed",
         fmt::format("the fit{} failed: {}; its estimates are where it stopped, not results", law, f.failure));
  else if (!f.identifiable)
    warn("not_identifiable",
         fmt::format("the table does not determine the parameters{}: a correlation beyond {:g} or an infinite "
                     "standard error; fit fewer parameters",
                     law, identifiable_correlation_limit));
  for (const FittedParameter& p : f.parameters)
    if (p.at_bound)
      warn("at_bound",
           fmt::format("{}{} ended at a bound ({:.6g}); its standard error does not hold", p.name, law, p.estimate));
  if (!f.sigma_estimated && f.reduced_chi_square > 2)
    warn("poor_fit", fmt::format("the law{} does not explain the table to its e_sd: reduced chi-square {:.3g} (about 1 "
                                 "if it did); the standard errors are scaled by it",
                                 law, f.reduced_chi_square));
  if (f.cross_validation && !f.cross_validation->failure.empty())
    warn("cross_validation_failed", fmt::format("the cross-validation{} failed: {}", law, f.cross_validation->failure));
  return w;
}

std::vector<RunDiagnostic> restitution_fit_diagnostics(const RestitutionFitRun& run) {
  std::vector<RunDiagnostic> all;
  for (const RestitutionFit& f : run.fits)
    for (RunDiagnostic& d : restitution_fit_diagnostics(run, f)) {
      const bool once = d.code == "synthetic_table" || d.code == "sigma_estimated";
      if (once && &f != &run.fits.front()) continue;
      if (d.code == "sigma_estimated" && run.fits.size() > 1)
        d.message = "the table has no e_sd: each law's fit estimates one common scatter of e from its residuals "
                    "(its sigma); the standard errors come from sigma^2 (J^T J)^-1";
      all.push_back(std::move(d));
    }
  if (run.fits.empty() && run.table.synthetic)
    all.push_back({"warning", "synthetic_table", "the restitution table says 'synthetic: true': it is not a measurement", {}});
  return all;
}

nlohmann::ordered_json to_json(const RestitutionFitRun& run, const RestitutionFit& f) {
  nlohmann::ordered_json j;
  j["law"] = f.law;
  if (!f.left_out.empty()) j["left_out"] = f.left_out;
  j["parameters"] = report_detail::to_json(f.parameters);
  j["correlation"] = correlation_json(f.correlation);
  j["rows"] = f.rows;
  j["sigma_estimated"] = f.sigma_estimated;
  j["sigma"] = f.sigma_estimated ? number_or_null(f.sigma) : nlohmann::ordered_json(nullptr);
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
    const RestitutionCrossValidation& cv = *f.cross_validation;
    nlohmann::ordered_json c;
    c["folds"] = cv.folds;
    const bool ok = cv.failure.empty();
    c["rms_prediction_error"] = ok ? number_or_null(cv.rms_prediction_error) : nullptr;
    c["scatter"] = ok ? number_or_null(cv.scatter) : nullptr;
    c["ratio_to_scatter"] = ok ? number_or_null(cv.ratio) : nullptr;
    c["failure"] = cv.failure;
    j["cross_validation"] = c;
  }
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (const RestitutionPoint& p : f.points)
    points.push_back({{"impact_speed_mps", p.impact_speed_mps},
                      {"measured", p.measured},
                      {"model", number_or_null(p.model)},
                      {"residual", number_or_null(p.residual)}});
  j["points"] = points;
  j["warnings"] = to_json(restitution_fit_diagnostics(run, f));
  return j;
}

nlohmann::ordered_json to_json(const RestitutionFitRun& run) {
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["table"] = {{"path", run.table.path.string()},
                {"source", run.table.source},
                {"synthetic", run.table.synthetic},
                {"rows", run.table.rows()},
                {"e_sd", run.table.has_sd()}};
  nlohmann::ordered_json fits = nlohmann::ordered_json::array();
  for (const RestitutionFit& f : run.fits) fits.push_back(to_json(run, f));
  j["fits"] = fits;
  nlohmann::ordered_json failures = nlohmann::ordered_json::array();
  for (const auto& [law, why] : run.failures) failures.push_back({{"law", law}, {"error", why}});
  j["failures"] = failures;
  j["warnings"] = to_json(restitution_fit_diagnostics(run));
  j["git_revision"] = git_revision();
  return j;
}

}  // namespace hertzdash
