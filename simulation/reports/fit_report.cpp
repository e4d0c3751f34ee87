// `fit`'s run and report for every kind of data (simulation/reports/fit_report.hpp): read the
// data, fit one law or every law, the warnings, the JSON of the run and of each fit (one core,
// each kind's own keys beside it), the curves file.
#include "hertzdash/simulation/reports/fit_report.hpp"

#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/fit/trace_setup.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/reports/result_output.hpp"
#include "hertzdash/simulation/reports/fit_verdict.hpp"
#include "hertzdash/simulation/reports/report_json.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <map>

namespace hertzdash {

using report_detail::correlation_json;
using report_detail::json_value;
using report_detail::number_or_null;
using json = nlohmann::ordered_json;

namespace {

// What differs between the kinds in their reports.
struct KindWords {
  const char* data;        // "trace": the data's noun in messages and its JSON key
  const char* synthetic;   // the warning code of a synthetic data set
  const char* count_key;   // the JSON key of n
  const char* unit;        // the suffix of a key in the data's unit ("_s"), or ""
  const char* sigma_note;  // the note sigma_estimated, one fit ({} the law, {:.3g} sigma)
  const char* sigma_many;  // the same, comparing laws
};

const KindWords& words(FitDataKind kind) {
  static const KindWords table[] = {
      {"trace", "synthetic_trace", "samples", "", "", ""},
      {"restitution table", "synthetic_table", "rows", "",
       "the table has no e_sd: one common scatter of e is estimated from the residuals{}, sigma = {:.3g}; the standard "
       "errors come from sigma^2 (J^T J)^-1 and the reduced chi-square is 1 by construction",
       "the table has no e_sd: each law's fit estimates one common scatter of e from its residuals (its sigma); the "
       "standard errors come from sigma^2 (J^T J)^-1"},
      {"bounce recording", "synthetic_recording", "times", "_s",
       "one common timing scatter is estimated from the residuals{}, sigma = {:.3g} s; the standard errors come from "
       "sigma^2 (J^T J)^-1 and the reduced chi-square is 1 by construction",
       "each law's fit estimates one common timing scatter from its residuals (its sigma); the standard errors come "
       "from sigma^2 (J^T J)^-1"}};
  return table[static_cast<int>(kind)];
}

bool synthetic(const FitRun& run) {
  switch (run.kind) {
    case FitDataKind::trace: return run.trace.synthetic;
    case FitDataKind::restitution_table: return run.table.synthetic;
    case FitDataKind::bounce_times: return run.recording.synthetic;
  }
  return false;
}

json nuisance_json(const FittedParameter& p) {
  return {{"estimate", number_or_null(p.estimate)},
          {"standard_error", number_or_null(p.standard_error)},
          {"initial", number_or_null(p.initial)}};
}

json effective_restitution_json(const EffectiveRestitution& e) {
  return {{"value", number_or_null(e.value)},
          {"standard_error", number_or_null(e.standard_error)},
          {"range", {number_or_null(e.min), number_or_null(e.max)}},
          {"speeds_mps", {number_or_null(e.speed_at_min_mps), number_or_null(e.speed_at_max_mps)}},
          {"impacts", e.impacts.size()}};
}

json fit_json(const FitRun& run, const FitResult& f, const PaperParameters& paper) {
  const KindWords& w = words(run.kind);
  const bool trace = run.kind == FitDataKind::trace, bounce = run.kind == FitDataKind::bounce_times;
  json j;
  j["e_effective"] = effective_restitution_json(f.e_effective);
  j["law"] = f.law;
  if (!f.left_out.empty()) j["left_out"] = f.left_out;  // compare_laws: options this law does not read
  j["parameters"] = report_detail::to_json(f.parameters);
  j["correlation"] = correlation_json(f.correlation);
  if (trace) {
    json channels = json::array();
    for (const FitGroup& g : f.groups)
      channels.push_back(
          {{"name", g.label}, {"samples", g.rows}, {"noise_sigma", g.unit}, {"residual_rms", g.residual_rms}});
    j["channels"] = channels;
  }
  if (bounce) {
    json drops = json::array();
    for (std::size_t d = 0; d < f.groups.size(); ++d) {
      const double h = run.checked.drops[d].drop_height_m;
      drops.push_back({{"drop", f.groups[d].label},
                       {"impacts", f.groups[d].rows},
                       {"drop_height_m", h > 0 ? json(h) : nullptr},
                       {"first_impact_speed_mps", nuisance_json(f.groups[d].nuisances[0])},
                       {"clock_offset_s", nuisance_json(f.groups[d].nuisances[1])}});
    }
    j["drops"] = drops;
  }
  j[w.count_key] = f.n;
  if (bounce) j["fitted_parameters"] = f.p;
  if (run.kind == FitDataKind::restitution_table) {
    j["sigma_estimated"] = f.sigma_estimated;
    j["sigma"] = f.sigma_estimated ? number_or_null(f.sigma) : json(nullptr);
  }
  if (bounce) j["sigma_s"] = number_or_null(f.sigma);
  j["chi_square"] = f.chi_square;
  j["reduced_chi_square"] = number_or_null(f.reduced_chi_square);
  j["condition_number"] = number_or_null(f.condition_number);
  j["identifiable"] = f.identifiable;
  j["aic"] = f.aic;
  j["bic"] = f.bic;
  j["iterations"] = f.iterations;
  j["model_runs"] = f.model_runs;
  if (!trace) j["integrator_used"] = f.integrator_used;
  j["stop_reason"] = f.stop_reason;
  j["converged"] = f.converged;
  j["failed"] = f.failed;
  j["failure"] = f.failure;
  if (trace) {
    j["work"] = f.work;
    j["contact_time_s"] = f.model_impact ? f.model_impact->contact_time_s : NAN;
    // The fitted law's constants (its coefficients at the fitted e, the paper's c_e, ...).
    j["law_coefficients"] = law_coefficients_json(f.model_impact ? f.model_impact->law_coefficients : std::vector<NamedValue>{});
  }
  if (f.cross_validation) {
    const CrossValidation& cv = *f.cross_validation;
    const bool ok = cv.failure.empty();
    j["cross_validation"] = {{"folds", cv.folds},
                             {std::string("rms_prediction_error") + w.unit, ok ? number_or_null(cv.rms_prediction_error) : nullptr},
                             {std::string("scatter") + w.unit, ok ? number_or_null(cv.scatter) : nullptr},
                             {"ratio_to_scatter", ok ? number_or_null(cv.ratio) : nullptr},
                             {"failure", cv.failure}};
  }
  if (trace) {
    json in;
    const DropTestSetup s = resolve_setup(f.fitted_options, paper);
    for (const auto& [name, value] : describe_run(s, f.law, f.model_solver)) in[name] = json_value(value);
    j["fitted_inputs"] = in;
    return j;
  }
  json points = json::array();
  for (const FitPoint& p : f.points) {
    json pt;
    if (bounce) pt = {{"drop", f.groups[*p.group].label}, {"index", p.index}, {"impact_number", p.number}};
    pt["impact_speed_mps"] = number_or_null(p.x);
    pt["measured"] = p.measured;
    pt["model"] = number_or_null(p.model);
    pt["residual"] = number_or_null(p.residual);
    points.push_back(pt);
  }
  j["points"] = points;
  j["warnings"] = to_json(fit_diagnostics(run, f, paper));
  return j;
}

}  // namespace

FitRun run_fit(const FitRequest& request, const PaperParameters& paper) {
  FitRun r;
  r.kind = request.kind;
  r.settings = request.settings;
  const RunOptions& base = request.options;
  if (request.compare_laws && base.damping != RunOptions{}.damping)
    throw InvalidParameter("damping", base.damping, "omitted with `compare-laws` (every registered law is fitted)");
  {  // bad options are reported before the file is read
    RunOptions probe = base;
    if (request.compare_laws) probe.damping = RunOptions{}.damping;
    if (r.kind == FitDataKind::restitution_table) check_restitution_fit_options(base);
    if (r.kind == FitDataKind::bounce_times) check_bounce_fit_setup(probe, paper);
    else resolve_setup(probe, paper);
  }
  const std::string fit = request.fit.empty() && r.kind == FitDataKind::trace ? "ball-E,restitution" : request.fit;
  r.settings.parameters = fit.empty() ? std::vector<FitParameter>{} : parse_fit_parameters(fit);
  LawComparison c;
  switch (r.kind) {
    case FitDataKind::trace: {
      r.trace = read_measured_trace(request.path);
      const RunOptions options = trace_setup_options(r.trace, base, paper, request.given);  // the trace's rod and height
      if (request.compare_laws) c = compare_laws(r.trace, options, paper, r.settings);
      else c.fits.push_back(fit_trace(r.trace, options, paper, r.settings));
      break;
    }
    case FitDataKind::restitution_table:
      r.table = read_restitution_table(request.path);
      if (request.compare_laws) c = compare_laws_on_restitution(r.table, base, paper, r.settings);
      else c.fits.push_back(fit_restitution_table(r.table, base, paper, r.settings));
      break;
    case FitDataKind::bounce_times: {
      r.recording = read_bounce_recording(request.path);
      r.checked = check_bounce_recording(r.recording);
      r.checked.timing_sd_s = request.timing_sd_s;
      const std::string path = r.recording.path.string();
      if (request.compare_laws) c = compare_laws_on_bounces(r.checked, path, base, paper, r.settings);
      else c.fits.push_back(fit_bounce_recording(r.checked, path, base, paper, r.settings));
      break;
    }
  }
  r.fits = std::move(c.fits);
  r.failures = std::move(c.failures);
  return r;
}

FitRun run_fit(const std::string& trace_path, const RunOptions& base, const PaperParameters& paper,
               const TraceFitSettings& settings, bool compare_all_laws, const std::vector<std::string>& given) {
  FitRequest request{FitDataKind::trace, trace_path, base, {}, settings, compare_all_laws, given};
  for (const FitParameter& p : settings.parameters) request.fit += (request.fit.empty() ? "" : ",") + p.option;
  FitRun r = run_fit(request, paper);
  return r;
}

std::vector<RunDiagnostic> fit_diagnostics(const FitRun& run, const FitResult& f, const PaperParameters& paper) {
  const KindWords& kw = words(run.kind);
  std::vector<RunDiagnostic> w;
  auto warn = [&w](const char* code, std::string message) { w.push_back({"warning", code, std::move(message), {}}); };
  const std::string law = run.fits.size() > 1 ? " (" + f.law + ")" : "";
  if (run.kind != FitDataKind::trace && synthetic(run))
    warn(kw.synthetic, fmt::format("the {} says 'synthetic: true': it is not a measurement", kw.data));
  if (f.sigma_estimated) w.push_back({"note", "sigma_estimated", fmt::format(fmt::runtime(kw.sigma_note), law, f.sigma), {}});
  if (!f.converged)
    warn("not_converged",
         fmt::format("the fit{} did not converge ({}): the estimates are where it stopped", law, f.stop_reason));
  if (f.failed)
    warn("fit_failed", fmt::format("the fit{} failed: {}; its estimates are where it stopped, not results", law, f.failure));
  else if (!f.identifiable)
    warn("not_identifiable",
         fmt::format("the {} does not determine the parameters{}: condition number {:.3g} (limit {:g}), a correlation "
                     "beyond {:g} or an infinite standard error; fit fewer parameters{}",
                     kw.data, law, f.condition_number, identifiable_condition_limit, identifiable_correlation_limit,
                     run.kind == FitDataKind::trace ? " or add a channel" : ""));
  for (const FittedParameter& p : f.parameters)
    if (p.at_bound)
      warn("at_bound", fmt::format("{}{} ended at a bound ({:.6g}); its standard error does not hold", p.name, law, p.estimate));
  if (poor_fit(f))
    warn("poor_fit", fmt::format("the model{} does not explain the {} to its stated precision: reduced chi-square {:.3g} "
                                 "(about 1 if it did; the probability of one as large from that scatter alone is below "
                                 "{:g}); the standard errors are scaled up by it",
                                 law, kw.data, f.reduced_chi_square, poor_fit_probability));
  if (f.cross_validation && !f.cross_validation->failure.empty())
    warn("cross_validation_failed", fmt::format("the cross-validation{} failed: {}", law, f.cross_validation->failure));
  if (f.model_impact) {  // a trace's fitted impact, from contact onset
    DropTestSetup s = resolve_setup(f.fitted_options, paper);
    s.impact_velocity_mps = approach_speed(s);
    for (RunDiagnostic& d : impact_diagnostic_list(*f.model_impact, s, f.model_solver, {})) {
      // A fitted modulus or radius estimates the pair the trace was measured on; it does not change it.
      if (d.code == diagnostic_info(Diagnostic::preset_restitution).name && !own_body(f)) continue;
      d.message = "the fitted model" + law + ": " + d.message;
      w.push_back(std::move(d));
    }
  }
  return w;
}

std::vector<RunDiagnostic> fit_diagnostics(const FitRun& run, const PaperParameters& paper) {
  const KindWords& kw = words(run.kind);
  std::vector<RunDiagnostic> all;
  if (run.kind == FitDataKind::trace && synthetic(run))
    all.push_back({"warning", kw.synthetic, "the trace says 'synthetic: true': it is not a measurement", {}});
  if (!run.trace.model_columns.empty())
    all.push_back({"note", "model_columns",
                   fmt::format("the trace's model columns ({}) are not fitted: no instrument of the drop test measures "
                               "them (data/measurements/README.md)",
                               fmt::join(run.trace.model_columns, ", ")),
                   {}});
  for (const BounceFlag& f : run.checked.flagged)
    all.push_back({"warning", "flagged",
                   fmt::format("drop '{}'{}: {}: {}", f.drop, f.index ? fmt::format(" index {}", *f.index) : "", f.kind,
                               f.reason),
                   {}});
  for (const std::string& note : run.checked.notes) all.push_back({"note", "bounce_check", note, {}});
  for (RunDiagnostic& d : unit_diagnostics(run, paper)) all.push_back(std::move(d));
  for (const FitResult& f : run.fits)
    for (RunDiagnostic& d : fit_diagnostics(run, f, paper)) {
      const bool once = d.code == kw.synthetic || d.code == "sigma_estimated";
      if (once && &f != &run.fits.front()) continue;
      if (d.code == "sigma_estimated" && run.fits.size() > 1) d.message = kw.sigma_many;
      all.push_back(std::move(d));
    }
  if (run.fits.empty() && run.kind != FitDataKind::trace && synthetic(run))
    all.push_back({"warning", kw.synthetic, fmt::format("the {} says 'synthetic: true': it is not a measurement", kw.data), {}});
  return all;
}

json to_json(const FitRun& run, const PaperParameters& paper) {
  json j;
  j["schema_version"] = json_schema_version;
  // What the fit means, first (issue 46): the best fit's physical e, the verdict, the body.
  j["e_effective"] = run.fits.empty() ? json(nullptr) : effective_restitution_json(run.fits.front().e_effective);
  j["verdict"] = fit_verdict(run, paper);
  const std::string body = default_body_notice(run, paper);
  j["default_body"] = body.empty() ? json(nullptr) : json(body);
  switch (run.kind) {
    case FitDataKind::trace:
      j["trace"] = {{"path", run.trace.path.string()}, {"source", run.trace.source},
                    {"rod", run.trace.rod},             {"height_m", run.trace.height_m},
                    {"synthetic", run.trace.synthetic}, {"samples", run.trace.t_s.size()},
                    {"model_columns", run.trace.model_columns}};
      break;
    case FitDataKind::restitution_table:
      j["table"] = {{"path", run.table.path.string()}, {"source", run.table.source}, {"synthetic", run.table.synthetic},
                    {"rows", run.table.rows()},         {"e_sd", run.table.has_sd()}};
      break;
    case FitDataKind::bounce_times: {
      j["recording"] = {{"path", run.recording.path.string()}, {"source", run.recording.source},
                        {"synthetic", run.recording.synthetic}, {"drops", run.recording.drops.size()},
                        {"impacts", run.recording.impacts()},   {"used", run.checked.times()}};
      json flagged = json::array();
      for (const BounceFlag& f : run.checked.flagged)
        flagged.push_back({{"drop", f.drop}, {"index", f.index ? json(*f.index) : nullptr}, {"kind", f.kind}, {"reason", f.reason}});
      j["flagged"] = flagged;
      break;
    }
  }
  json fits = json::array();
  const std::vector<std::size_t> ranks = aic_ranks(run.fits), cv = cv_ranks(run.fits);
  for (std::size_t i = 0; i < run.fits.size(); ++i) {
    fits.push_back(fit_json(run, run.fits[i], paper));
    fits.back()["aic_rank"] = ranks[i];
    if (run.fits[i].cross_validation) fits.back()["cv_rank"] = cv[i] ? json(cv[i]) : json(nullptr);
  }
  j["fits"] = fits;
  json failures = json::array();
  for (const auto& [law, why] : run.failures) failures.push_back({{"law", law}, {"error", why}});
  j["failures"] = failures;
  j["warnings"] = to_json(fit_diagnostics(run, paper));
  j["git_revision"] = git_revision();
  return j;
}

void write_fit_curves(const FitResult& f, const MeasuredTrace& trace, const std::filesystem::path& path) {
  fit_curves_csv(f, trace).save(path);
}

CsvWriter fit_curves_csv(const FitResult& f, const MeasuredTrace& trace) {
  std::vector<std::string> columns{"t_s"};
  for (const FitGroup& g : f.groups)
    for (const char* what : {"measured", "model", "residual"}) columns.push_back(g.label + "_" + what);
  Parameters header{{"trace", trace.path.string()}, {"trace_source", trace.source},
                    {"synthetic", trace.synthetic ? "true" : "false"}, {"damping", f.law}};
  for (const FittedParameter& p : f.parameters) header.emplace_back(p.name + "_estimate", fmt::format("{}", p.estimate));
  CsvWriter csv("hertzdash fit: the trace, the fitted model and the residuals (time on the trace's clock)", header,
                columns);
  std::map<double, std::vector<CsvWriter::Cell>> rows;  // by sample time: channels may have gaps
  for (const FitPoint& p : f.points) {
    auto& row = rows[p.x];
    if (row.empty()) row.assign(columns.size(), std::string());
    row[0] = p.x;
    row[1 + 3 * *p.group] = p.measured;
    row[2 + 3 * *p.group] = p.model;
    row[3 + 3 * *p.group] = p.measured - p.model;
  }
  for (const auto& [t, row] : rows) csv.add_row(row);
  return csv;
}

}  // namespace hertzdash
