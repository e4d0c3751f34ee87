// `hertzdash fit`: identify parameters from measured data by weighted least squares, one engine
// for every kind (simulation/fit/fit_engine.hpp): a measured trace (--trace,
// data/measurements/README.md), a restitution table (--restitution-table) or a bounce recording
// (--bounce-times, its dirty data flagged first): the estimates, their standard errors and
// correlation (with --profile-intervals their profile-likelihood intervals), the residuals,
// whether the data determine the parameters; --compare-laws fits every registered law and ranks
// them by AIC; --cross-validate leaves out each fold in turn; --curves writes a trace, the fitted
// model and the residuals for a figure (validation/identification/identification_fit.gp draws
// two). The options are declared in simulation/reports/fit_request.hpp.
#include "cli/command.hpp"
#include "cli/figure_file.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/setup_options.hpp"
#include "hertzdash/simulation/reports/fit_curves.hpp"
#include "hertzdash/simulation/reports/fit_request.hpp"
#include "hertzdash/simulation/reports/fit_verdict.hpp"
#include "hertzdash/simulation/reports/result_output.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <map>
#include <memory>

namespace hertzdash::cli {

namespace {

struct FitCommandOptions {
  RunOptions run;
  std::map<std::string, std::string> text;  // fit_command_options()' values, by key
  std::map<std::string, bool> flags;
};

// Exit status of a fit that ran and determined nothing (FitResult::failed; docs/fit.md).
constexpr int exit_fit_failed = 3;

// The set-up options given on the command line, even at their default value (--rod steel):
// the trace's header may not contradict them (simulation/fit/trace_setup.hpp).
std::vector<std::string> given_options(const CLI::App& sub) {
  std::vector<std::string> given;
  for (const RunOption& o : run_options())
    if (const CLI::Option* option = sub.get_option_no_throw("--" + o.name); option && option->count() > 0)
      given.push_back(o.name);
  return given;
}

// The profile-likelihood intervals, where computed (--profile-intervals).
void print_profile_intervals(const std::vector<FittedParameter>& parameters) {
  for (const FittedParameter& p : parameters)
    if (p.profile)
      std::cout << fmt::format("  {:<24} profile interval (1 sigma) [{:.8g}{}, {:.8g}{}]{}\n", p.name, p.profile->lower,
                               p.profile->lower_open ? " (open: the bound)" : "", p.profile->upper,
                               p.profile->upper_open ? " (open: the bound)" : "",
                               p.profile->failure.empty() ? "" : "; " + p.profile->failure);
}

// A fit in full: the parameters, then what its kind shows of its rows and groups, the
// criteria, the cross-validation, the solver's work.
void print_fit(const FitRun& r, const FitResult& f) {
  const bool trace = r.kind == FitDataKind::trace, bounce = r.kind == FitDataKind::bounce_times;
  std::cout << fmt::format("  {:<24} {:>14} {:>14} {:>14} {:>9}\n", "parameter", "initial", "estimate", "std_error",
                           "rel_%");
  for (const FittedParameter& p : f.parameters)
    std::cout << fmt::format("  {:<24} {:>14.6g} {:>14.8g} {:>14.3g} {:>9}\n", p.name, p.initial, p.estimate,
                             p.standard_error,
                             p.name == "onset-time" ? "-" : fmt::format("{:.3g}", 100 * p.standard_error / std::abs(p.estimate)));
  print_profile_intervals(f.parameters);
  if (trace) {
    std::cout << "  correlation:\n";
    for (std::size_t i = 0; i < f.correlation.size(); ++i) {
      std::cout << fmt::format("    {:<22}", f.parameters[i].name);
      for (double c : f.correlation[i]) std::cout << fmt::format(" {:>7.3f}", c);
      std::cout << "\n";
    }
    for (const FitGroup& c : f.groups)
      std::cout << fmt::format("  channel {:<16} {:>6} samples, noise sigma {:.4g}, residual RMS {:.4g}\n", c.label,
                               c.rows, c.unit, c.residual_rms);
    std::cout << fmt::format("  reduced chi-square {:.4g} ({} residuals), condition number {:.4g} ({}), AIC {:.6g}, BIC {:.6g}\n",
                             f.reduced_chi_square, f.n, f.condition_number,
                             f.failed ? "fit failed" : f.identifiable ? "identifiable" : "NOT identifiable", f.aic, f.bic);
  } else if (bounce) {
    std::cout << fmt::format("  {:<16} {:>7} {:>12} {:>11} {:>14} {:>11}\n", "drop", "impacts", "v0_mps", "v0_se",
                             "clock_offset_s", "offset_se");
    for (const FitGroup& d : f.groups)
      std::cout << fmt::format("  {:<16} {:>7} {:>12.6g} {:>11.3g} {:>14.9g} {:>11.3g}\n", d.label, d.rows,
                               d.nuisances[0].estimate, d.nuisances[0].standard_error, d.nuisances[1].estimate,
                               d.nuisances[1].standard_error);
    std::cout << (f.sigma_estimated ? fmt::format("  timing sigma {:.4g} s (estimated)", f.sigma)
                                    : fmt::format("  timing sd {:.4g} s (stated), reduced chi-square {:.4g}",
                                                  r.checked.timing_sd_s, f.reduced_chi_square))
              << fmt::format(", {} times, {} parameters, AIC {:.6g}, BIC {:.6g}, {}\n", f.n, f.p, f.aic, f.bic,
                             f.failed ? "fit failed" : f.identifiable ? "identifiable" : "NOT identifiable");
  } else {
    std::cout << fmt::format("  {:>12} {:>10} {:>10} {:>11}\n", "speed_mps", "e", "model", "residual");
    for (const FitPoint& p : f.points)
      std::cout << fmt::format("  {:>12.6g} {:>10.6f} {:>10.6f} {:>11.3e}\n", p.x, p.measured, p.model, p.residual);
    std::cout << (f.sigma_estimated ? fmt::format("  sigma {:.4g} (estimated: no e_sd), {} rows", f.sigma, f.n)
                                    : fmt::format("  reduced chi-square {:.4g} ({} rows)", f.reduced_chi_square, f.n))
              << fmt::format(", AIC {:.6g}, BIC {:.6g}, {}\n", f.aic, f.bic,
                             f.failed ? "fit failed" : f.identifiable ? "identifiable" : "NOT identifiable");
  }
  if (f.cross_validation) {
    const CrossValidation& cv = *f.cross_validation;
    const char* folds = trace ? "sets of interleaved samples" : bounce ? "drops" : "speeds";
    const char* unit = bounce ? " s" : "";
    if (cv.failure.empty())
      std::cout << fmt::format("  cross-validation ({} {} left out in turn): RMS prediction error {:.4g}{}, {:.3g} "
                               "times the {} {:.4g}{}\n",
                               cv.folds, folds, cv.rms_prediction_error, unit, cv.ratio,
                               bounce ? "timing sigma" : trace ? "standardized noise" : "data's scatter", cv.scatter, unit);
    else std::cout << fmt::format("  cross-validation failed: {}\n", cv.failure);
  }
  if (trace) {
    std::cout << fmt::format("  {} iterations, {} model runs, stopped: {}; fitted contact time {:.6g} s\n", f.iterations,
                             f.model_runs, f.stop_reason, f.model_impact ? f.model_impact->contact_time_s : NAN);
    if (f.model_impact) std::cout << law_coefficients_line(f.model_impact->law_coefficients);
  } else
    std::cout << fmt::format("  {} iterations, {} model runs ({}), stopped: {}\n", f.iterations, f.model_runs,
                             f.integrator_used, f.stop_reason);
  if (f.failed) std::cout << fmt::format("  FIT FAILED: {}\n", f.failure);
}

// The ranked table of a law comparison, then the best fit in full.
void print_law_ranking(const FitRun& r) {
  const bool trace = r.kind == FitDataKind::trace, cv = r.settings.cross_validate;
  const char* cv_header = r.kind == FitDataKind::bounce_times ? "cv_rms_s" : "cv_rms";
  if (trace)
    std::cout << fmt::format("  {:>3} {:<22} {:>12} {:>12} {:>12} {:>10} {:>10}", "", "law (best first)", "AIC", "dAIC",
                             "BIC", "chi2/dof", "condition");
  else
    std::cout << fmt::format("  {:>3} {:<22} {:>12} {:>10} {:>12} {:>21}", "", "law (best first)", "AIC", "dAIC", "BIC",
                             "model e range");
  std::cout << (cv ? fmt::format(" {:>12} {:>8}", cv_header, "cv_rank") : "") << "\n";
  const std::vector<std::size_t> cv_rank = cv_ranks(r.fits);
  std::string ties;
  const std::vector<std::size_t> rank = aic_ranks(r.fits);
  for (std::size_t i = 0; i < r.fits.size(); ++i) {
    const FitResult& f = r.fits[i];
    const double gap = f.aic - r.fits.front().aic;
    if (i > 0 && gap < aic_preference) ties += (ties.empty() ? "" : ", ") + f.law;
    if (trace)
      std::cout << fmt::format("  {:>3} {:<22} {:>12.6g} {:>12.4g} {:>12.6g} {:>10.4g} {:>10.3g}", rank[i], f.law, f.aic,
                               gap, f.bic, f.reduced_chi_square, f.condition_number);
    else
      std::cout << fmt::format("  {:>3} {:<22} {:>12.6g} {:>10.4g} {:>12.6g} {:>10.6f}-{:<10.6f}", rank[i], f.law, f.aic,
                               gap, f.bic, f.e_effective.min, f.e_effective.max);
    if (cv)
      std::cout << (cv_rank[i] ? fmt::format(" {:>12.4g} {:>8}", f.cross_validation->rms_prediction_error, cv_rank[i])
                               : fmt::format(" {:>12} {:>8}", "-", "-"));
    std::cout << "\n";
  }
  for (const auto& [law, why] : r.failures)
    std::cout << fmt::format("  {}: not fitted: {}\n", law, spell_key_references(why, KeySpelling::command_line));
  for (const FitResult& f : r.fits)
    if (f.failed) std::cout << fmt::format("  {}: fit failed: {}\n", f.law, f.failure);
  if (r.fits.empty()) {
    std::cout << "  best: none, no law could be fitted\n";
    return;
  }
  if (r.fits.front().failed) std::cout << "  best: none, every fit failed\n";
  else std::cout << fmt::format("  best: '{}'{}\n", r.fits.front().law,
                           ties.empty() ? "" : fmt::format(" (not preferred by AIC over: {}, within dAIC < {:g})", ties, aic_preference));
  if (!trace) std::cout << fmt::format("  damping law '{}'\n", r.fits.front().law);
  print_fit(r, r.fits.front());
}

// The physical e first (issue 46): the fitted model's mean e over the data's impacts and its error,
// with its range over their speeds where it has one.
void print_effective_restitution(const FitRun& r, const FitResult& f) {
  const EffectiveRestitution& e = f.e_effective;
  if (!std::isfinite(e.value)) {
    std::cout << "  e_effective: none (the fitted model's impacts do not separate, or it has none)\n";
    return;
  }
  const std::string over = r.kind == FitDataKind::trace
                               ? std::string("the fitted model's impact")
                               : fmt::format("the fitted model's mean over the data's {} impact{}", e.impacts.size(), e.impacts.size() == 1 ? "" : "s");
  std::cout << fmt::format("  e_effective {:.4f} +- {:.2g} (1 sigma), {}", e.value, e.standard_error, over)
            << (constant_e(e) ? std::string()
                                                : fmt::format(": {:.4f} at {:.3g} m/s to {:.4f} at {:.3g} m/s", e.min,
                                                              e.speed_at_min_mps, e.max, e.speed_at_max_mps))
            << "\n";
}

void print_text(const FitRun& r, const PaperParameters& paper) {
  const std::string body = default_body_notice(r, paper);
  const std::string on = body.empty() ? "" : "; " + spell_key_references(body, KeySpelling::command_line);
  switch (r.kind) {
    case FitDataKind::trace:
      std::cout << fmt::format("hertzdash fit: {} ({} samples{}; rod {}, h = {:g} m)\n", r.trace.path.string(),
                               r.trace.t_s.size(), r.trace.synthetic ? ", SYNTHETIC" : "", r.trace.rod, r.trace.height_m);
      break;
    case FitDataKind::restitution_table:
      std::cout << fmt::format("hertzdash fit: {} ({} rows{}{}){}\n", r.table.path.string(), r.table.rows(),
                               r.table.has_sd() ? ", weighted by e_sd" : "", r.table.synthetic ? ", SYNTHETIC" : "", on);
      break;
    case FitDataKind::bounce_times:
      std::cout << fmt::format("hertzdash fit: {} ({} drop{}, {} impacts, {} used, {} flagged{}){}\n",
                               r.recording.path.string(), r.recording.drops.size(),
                               r.recording.drops.size() == 1 ? "" : "s", r.recording.impacts(),
                               r.checked.times(), r.checked.flagged.size(), r.recording.synthetic ? ", SYNTHETIC" : "", on);
      break;
  }
  if (!r.fits.empty()) print_effective_restitution(r, r.fits.front());
  std::cout << "  verdict: " << spell_key_references(fit_verdict(r, paper), KeySpelling::command_line) << "\n";
  if (r.fits.size() == 1 && r.failures.empty()) {
    std::cout << fmt::format("  damping law '{}'\n", r.fits[0].law);
    print_fit(r, r.fits[0]);
    return;
  }
  print_law_ranking(r);
}

// --curves and --figure of the best fit (cli/figure_file.hpp; simulation/reports/fit_curves.hpp).
void write_fit_outputs(const FitRun& r, const PaperParameters& paper, const std::string& curves,
                       const std::string& figure, bool mkdir) {
  const FitResult& f = r.fits.front();
  const bool trace = r.kind == FitDataKind::trace;
  const CsvWriter points = trace ? fit_curves_csv(f, r.trace) : restitution_curves_csv(r, f, paper);
  if (!curves.empty()) {
    create_output_directories(curves, mkdir);
    points.save(curves);
  }
  if (figure.empty()) return;
  create_output_directories(figure, mkdir);
  const std::filesystem::path data = trace ? r.trace.path : r.kind == FitDataKind::bounce_times ? r.recording.path : r.table.path;
  if (trace) {
    std::string channels;
    for (const FitGroup& g : f.groups) channels += (channels.empty() ? "" : " ") + g.label;
    draw_figure("fit_figure.gp", "trace", {&points}, {fmt::format("fitted model, '{}'", f.law), channels}, figure);
    return;
  }
  const CsvWriter law = law_curve_csv(r, f);
  const std::string title = fmt::format("{}{}: '{}', e_effective {:.4f} ± {:.2g}", data.filename().string(),
                                        r.kind == FitDataKind::bounce_times ? (r.recording.synthetic ? " (SYNTHETIC)" : "")
                                                                            : (r.table.synthetic ? " (SYNTHETIC)" : ""),
                                        f.law, f.e_effective.value, f.e_effective.standard_error);
  draw_figure("fit_figure.gp", "e", {&points, &law},
              {title, r.kind == FitDataKind::bounce_times ? "each bounce, drag-corrected" : "the table's rows"}, figure);
}

}  // namespace

Command add_fit_command(CLI::App& app) {
  auto opt = std::make_shared<FitCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "fit", "Identify parameters (by default the hemisphere's modulus and e) from a measured trace, a restitution "
             "table or a bounce recording");
  bool setup_added = false;
  for (const FitOption& o : fit_command_options()) {
    const std::string key(o.decl.key), help(o.decl.help);
    if (key == "fit" && !setup_added) add_run_options(*sub, opt->run, RunOption::Group::setup), setup_added = true;
    if (o.decl.type == ParameterType::flag) sub->add_flag("--" + key, opt->flags[key], help);
    else if (key == "curves" || key == "figure") add_output_file_option(*sub, "--" + key, opt->text[key], help);
    else if (o.decl.type == ParameterType::number)  // read as decimal text, its range checked by fit_request
      add_number_option(*sub, "--" + key, [opt, key](double v) { opt->text[key] = fmt::format("{}", v); },
                        help + (o.decl.default_value.empty() ? "" : " (default: " + std::string(o.decl.default_value) + ")"));
    else
      sub->add_option("--" + key, opt->text[key],
                      help + (o.decl.default_value.empty() ? "" : " (default: " + std::string(o.decl.default_value) + ")"));
  }

  return {sub, [opt, sub]() {
            std::map<std::string, std::string> given;
            for (const auto& [key, value] : opt->text)
              if (sub->get_option("--" + key)->count() > 0) given[key] = value;
            for (const auto& [key, on] : opt->flags)
              if (on && key != "json" && key != "mkdir") given[key] = "true";
            if (!given.contains("trace") && !given.contains("restitution-table") && !given.contains("bounce-times"))
              throw CLI::RequiredError(
                  "--trace is required (or --restitution-table, a restitution table, or --bounce-times, a bounce "
                  "recording)",
                  CLI::ExitCodes::RequiredError);
            if (opt->flags["mkdir"]) given["mkdir"] = "true";
            FitRequest request = fit_request(given, opt->run);
            request.given = given_options(*sub);
            request.settings.progress = [](const std::string& line) { std::cerr << "hertzdash: fit: " << line << "\n"; };
            const std::string &curves = opt->text["curves"], &figure = opt->text["figure"];
            const bool mkdir = opt->flags["mkdir"];
            if (!figure.empty()) require_gnuplot("figure", figure);
            prepare_output_file("--curves", curves, mkdir);
            prepare_output_file("--figure", figure, mkdir);
            refuse_shared_files({{"--" + std::string(fit_kind_option(request.kind)), request.path}},
                                {{"--curves", curves}, {"--figure", figure}});
            const PaperParameters paper = load_paper_parameters();
            const FitRun r = run_fit(request, paper);
            if (r.fits.empty() && r.kind == FitDataKind::trace)
              throw std::runtime_error("no damping law could be fitted to the trace");
            report_diagnostics(fit_diagnostics(r, paper));
            if (opt->flags["json"]) std::cout << to_json(r, paper).dump(2) << "\n";
            else print_text(r, paper);
            std::cout.flush();  // the result stands even if its figure cannot be drawn
            if (!r.fits.empty()) write_fit_outputs(r, paper, curves, figure, mkdir);
            if (r.fits.empty()) return exit_fit_failed;
            return r.fits.front().failed ? exit_fit_failed : 0;
          }};
}

}  // namespace hertzdash::cli
