// `fit`'s run and report (simulation/reports/run_reports.hpp): read a measured trace and fit it (one law,
// or every law ranked), the JSON of a fit and of the run, the curves file, and the fit's
// warnings.
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/simulation/fit/trace_setup.hpp"
#include "hertzdash/simulation/options/run_description.hpp"
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

FitRun run_fit(const std::string& trace_path, const RunOptions& base, const PaperParameters& paper,
               const TraceFitSettings& settings, bool compare_all_laws, const std::vector<std::string>& given) {
  FitRun r;
  r.settings = settings;
  resolve_setup(base, paper);  // bad options are reported before the file is read
  if (compare_all_laws && base.damping != RunOptions{}.damping)
    throw InvalidParameter("damping", base.damping, "omitted with `compare-laws` (every registered law is fitted)");
  r.trace = read_measured_trace(trace_path);
  const RunOptions options = trace_setup_options(r.trace, base, paper, given);  // the trace's rod and height
  if (compare_all_laws) {
    LawComparison c = compare_laws(r.trace, options, paper, settings);
    r.fits = std::move(c.fits);
    r.failures = std::move(c.failures);
  } else {
    r.fits.push_back(fit_trace(r.trace, options, paper, settings));
  }
  return r;
}

nlohmann::ordered_json to_json(const TraceFit& f, const PaperParameters& paper) {
  nlohmann::ordered_json j;
  j["law"] = f.law;
  if (!f.left_out.empty()) j["left_out"] = f.left_out;  // compare_laws: options this law does not read
  j["parameters"] = report_detail::to_json(f.parameters);
  j["correlation"] = correlation_json(f.correlation);
  nlohmann::ordered_json channels = nlohmann::ordered_json::array();
  for (const ChannelFit& c : f.channels)
    channels.push_back({{"name", c.name},
                        {"samples", c.samples},
                        {"noise_sigma", c.noise_sigma},
                        {"residual_rms", c.residual_rms}});
  j["channels"] = channels;
  j["samples"] = f.samples;
  j["chi_square"] = f.chi_square;
  j["reduced_chi_square"] = f.reduced_chi_square;
  j["condition_number"] = number_or_null(f.condition_number);
  j["identifiable"] = f.identifiable;
  j["aic"] = f.aic;
  j["bic"] = f.bic;
  j["iterations"] = f.iterations;
  j["model_runs"] = f.model_runs;
  j["stop_reason"] = f.stop_reason;
  j["converged"] = f.converged;
  j["failed"] = f.failed;
  j["failure"] = f.failure;
  j["work"] = f.work;
  j["contact_time_s"] = f.contact_time_s;
  nlohmann::ordered_json in;
  const DropTestSetup s = resolve_setup(f.fitted_options, paper);
  for (const auto& [name, value] : describe_run(s, f.law, f.model_solver)) in[name] = json_value(value);
  j["fitted_inputs"] = in;
  return j;
}

nlohmann::ordered_json to_json(const FitRun& run, const PaperParameters& paper) {
  nlohmann::ordered_json j;
  j["schema_version"] = json_schema_version;
  j["trace"] = {{"path", run.trace.path.string()},   {"source", run.trace.source},
                {"rod", run.trace.rod},               {"height_m", run.trace.height_m},
                {"synthetic", run.trace.synthetic},   {"samples", run.trace.t_s.size()},
                {"model_columns", run.trace.model_columns}};
  nlohmann::ordered_json fits = nlohmann::ordered_json::array();
  for (const TraceFit& f : run.fits) fits.push_back(to_json(f, paper));
  j["fits"] = fits;
  nlohmann::ordered_json failures = nlohmann::ordered_json::array();
  for (const auto& [law, why] : run.failures) failures.push_back({{"law", law}, {"error", why}});
  j["failures"] = failures;
  j["warnings"] = to_json(fit_diagnostics(run, paper));
  j["git_revision"] = git_revision();
  return j;
}

void write_fit_curves(const TraceFit& f, const MeasuredTrace& trace, const std::filesystem::path& path) {
  std::vector<std::string> columns{"t_s"};
  for (const ChannelFit& c : f.channels)
    for (const char* what : {"measured", "model", "residual"}) columns.push_back(c.name + "_" + what);
  Parameters header{{"trace", trace.path.string()}, {"trace_source", trace.source},
                    {"synthetic", trace.synthetic ? "true" : "false"}, {"damping", f.law}};
  for (const FittedParameter& p : f.parameters) header.emplace_back(p.name + "_estimate", fmt::format("{}", p.estimate));
  CsvWriter csv("hertzdash fit: the trace, the fitted model and the residuals (time on the trace's clock)", header,
                columns);
  std::map<double, std::vector<CsvWriter::Cell>> rows;  // by sample time: channels may have gaps
  for (std::size_t c = 0; c < f.channels.size(); ++c) {
    const ChannelFit& ch = f.channels[c];
    for (std::size_t i = 0; i < ch.t_s.size(); ++i) {
      auto& row = rows[ch.t_s[i]];
      if (row.empty()) row.assign(columns.size(), std::string());
      row[0] = ch.t_s[i];
      row[1 + 3 * c] = ch.measured[i];
      row[2 + 3 * c] = ch.model[i];
      row[3 + 3 * c] = ch.measured[i] - ch.model[i];
    }
  }
  for (const auto& [t, row] : rows) csv.add_row(row);
  csv.save(path);
}

namespace {

// Whether the user gave the preset's pair a mass, modulus, Poisson ratio or radius of its own:
// one of those set in the fitted options that the fit did not estimate.
bool pair_given(const TraceFit& f) {
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

}  // namespace

std::vector<RunDiagnostic> fit_diagnostics(const FitRun& run, const PaperParameters& paper) {
  std::vector<RunDiagnostic> w;
  auto warn = [&w](const char* code, std::string message) { w.push_back({"warning", code, std::move(message), {}}); };
  if (run.trace.synthetic) warn("synthetic_trace", "the trace says 'synthetic: true': it is not a measurement");
  if (!run.trace.model_columns.empty())
    w.push_back({"note", "model_columns",
                 fmt::format("the trace's model columns ({}) are not fitted: no instrument of the drop test measures "
                             "them (data/measurements/README.md)",
                             fmt::join(run.trace.model_columns, ", ")),
                 {}});
  for (const TraceFit& f : run.fits) {
    const std::string law = run.fits.size() > 1 ? " (" + f.law + ")" : "";
    if (!f.converged)
      warn("not_converged",
           fmt::format("the fit{} did not converge ({}): the estimates are where it stopped", law, f.stop_reason));
    if (f.failed)
      warn("fit_failed", fmt::format("the fit{} failed: {}; its estimates are where it stopped, not results", law,
                                     f.failure));
    else if (!f.identifiable)
      warn("not_identifiable",
           fmt::format("the trace does not determine the parameters{}: condition number {:.3g} (limit {:g}), a "
                       "correlation beyond {:g} or an infinite standard error; fit fewer parameters or add a channel",
                       law, f.condition_number, identifiable_condition_limit, identifiable_correlation_limit));
    for (const FittedParameter& p : f.parameters)
      if (p.at_bound)
        warn("at_bound", fmt::format("{}{} ended at a bound ({:.6g}); its standard error does not hold", p.name, law,
                                     p.estimate));
    if (f.reduced_chi_square > 2)
      warn("poor_fit", fmt::format("the model{} does not explain the trace to its noise: reduced chi-square {:.3g} "
                                   "(about 1 if it did); the standard errors are scaled by it",
                                   law, f.reduced_chi_square));
    DropTestSetup s = resolve_setup(f.fitted_options, paper);
    s.impact_velocity_mps = approach_speed(s);  // the fit's model starts at contact onset
    for (RunDiagnostic& d : impact_diagnostic_list(f.model_summary, s, f.model_solver, {})) {
      // A fitted modulus or radius estimates the pair the trace was measured on; it does not change it.
      if (d.code == diagnostic_info(Diagnostic::preset_restitution).name && !pair_given(f)) continue;
      d.message = "the fitted model" + law + ": " + d.message;
      w.push_back(std::move(d));
    }
  }
  return w;
}

}  // namespace hertzdash
