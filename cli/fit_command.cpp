// `hertzdash fit`: identify parameters of the drop test from a measured trace
// (data/measurements/README.md) by weighted least squares (simulation/fit/trace_fit.hpp): the
// estimates, their standard errors and correlation, the residuals per channel, whether the
// trace determines the parameters; --compare-laws fits every registered law and ranks them by
// AIC; --curves writes the trace, the fitted model and the residuals for a figure
// (validation/identification/identification_fit.gp draws two). --restitution-table fits a
// law's own parameters to e against the impact speed instead (simulation/fit/restitution_fit.hpp),
// optionally cross-validated (--cross-validate); --bounce-times to the impact times of a bounce
// recording, its dirty data flagged first (simulation/fit/bounce_fit.hpp).
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/setup_options.hpp"
#include "hertzdash/simulation/fit/virtual_measurement.hpp"
#include "hertzdash/simulation/reports/bounce_fit_report.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>

namespace hertzdash::cli {

namespace {

struct FitCommandOptions {
  RunOptions run;
  std::string trace_path, table_path, bounce_path, fit = "ball-E,restitution", channels, curves_path;
  double resample_Hz = 0;
  bool compare_laws = false, cross_validate = false, json = false, mkdir = false;
  bool profile_intervals = false;  // --profile-intervals
};

// Exit status of a fit that ran and determined nothing (TraceFit::failed; docs/fit.md).
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

// AIC differences below 2 do not prefer one model over another (Burnham and Anderson).
constexpr double aic_tie = 2.0;

// The profile-likelihood intervals, where computed (--profile-intervals).
void print_profile_intervals(const std::vector<FittedParameter>& parameters) {
  for (const FittedParameter& p : parameters)
    if (p.profile)
      std::cout << fmt::format("  {:<24} profile interval (1 sigma) [{:.8g}{}, {:.8g}{}]{}\n", p.name, p.profile->lower,
                               p.profile->lower_open ? " (open: the bound)" : "", p.profile->upper,
                               p.profile->upper_open ? " (open: the bound)" : "",
                               p.profile->failure.empty() ? "" : "; " + p.profile->failure);
}

void print_fit(const TraceFit& f) {
  std::cout << fmt::format("  {:<24} {:>14} {:>14} {:>14} {:>9}\n", "parameter", "initial", "estimate", "std_error",
                           "rel_%");
  for (const FittedParameter& p : f.parameters)
    std::cout << fmt::format("  {:<24} {:>14.6g} {:>14.8g} {:>14.3g} {:>9}\n", p.name, p.initial, p.estimate,
                             p.standard_error,
                             p.name == "onset-time" ? "-" : fmt::format("{:.3g}", 100 * p.standard_error / std::abs(p.estimate)));
  print_profile_intervals(f.parameters);
  std::cout << "  correlation:\n";
  for (std::size_t i = 0; i < f.correlation.size(); ++i) {
    std::cout << fmt::format("    {:<22}", f.parameters[i].name);
    for (double c : f.correlation[i]) std::cout << fmt::format(" {:>7.3f}", c);
    std::cout << "\n";
  }
  for (const ChannelFit& c : f.channels)
    std::cout << fmt::format("  channel {:<16} {:>6} samples, noise sigma {:.4g}, residual RMS {:.4g}\n", c.name,
                             c.samples, c.noise_sigma, c.residual_rms);
  std::cout << fmt::format("  reduced chi-square {:.4g} ({} residuals), condition number {:.4g} ({}), AIC {:.6g}, BIC {:.6g}\n",
                           f.reduced_chi_square, f.samples, f.condition_number,
                           f.failed ? "fit failed" : f.identifiable ? "identifiable" : "NOT identifiable", f.aic, f.bic);
  std::cout << fmt::format("  {} iterations, {} model runs, stopped: {}; fitted contact time {:.6g} s\n", f.iterations,
                           f.model_runs, f.stop_reason, f.contact_time_s);
  if (f.failed) std::cout << fmt::format("  FIT FAILED: {}\n", f.failure);
}

void print_text(const FitRun& r) {
  std::cout << fmt::format("hertzdash fit: {} ({} samples{}; rod {}, h = {:g} m)\n", r.trace.path.string(),
                           r.trace.t_s.size(), r.trace.synthetic ? ", SYNTHETIC" : "", r.trace.rod, r.trace.height_m);
  if (r.fits.size() == 1) {
    std::cout << fmt::format("  damping law '{}'\n", r.fits[0].law);
    print_fit(r.fits[0]);
    return;
  }
  std::cout << fmt::format("  {:>3} {:<22} {:>12} {:>12} {:>12} {:>10} {:>10}\n", "", "law (best first)", "AIC", "dAIC",
                           "BIC", "chi2/dof", "condition");
  std::string ties;
  for (std::size_t i = 0; i < r.fits.size(); ++i) {
    const TraceFit& f = r.fits[i];
    const double gap = f.aic - r.fits.front().aic;
    if (i > 0 && gap < aic_tie) ties += (ties.empty() ? "" : ", ") + f.law;
    std::cout << fmt::format("  {:>3} {:<22} {:>12.6g} {:>12.4g} {:>12.6g} {:>10.4g} {:>10.3g}\n", i + 1, f.law, f.aic, gap,
                             f.bic, f.reduced_chi_square, f.condition_number);
  }
  for (const auto& [law, why] : r.failures) std::cout << fmt::format("  {}: not fitted: {}\n", law, why);
  for (const TraceFit& f : r.fits)
    if (f.failed) std::cout << fmt::format("  {}: fit failed: {}\n", f.law, f.failure);
  if (r.fits.front().failed) std::cout << "  best: none, every fit failed\n";
  else std::cout << fmt::format("  best: '{}'{}\n", r.fits.front().law,
                           ties.empty() ? "" : fmt::format(" (tied within dAIC < {:g}: {})", aic_tie, ties));
  print_fit(r.fits.front());
}

void print_restitution_fit(const RestitutionFit& f) {
  std::cout << fmt::format("  {:<24} {:>14} {:>14} {:>14} {:>9}\n", "parameter", "initial", "estimate", "std_error",
                           "rel_%");
  for (const FittedParameter& p : f.parameters)
    std::cout << fmt::format("  {:<24} {:>14.6g} {:>14.8g} {:>14.3g} {:>9.3g}\n", p.name, p.initial, p.estimate,
                             p.standard_error, 100 * p.standard_error / std::abs(p.estimate));
  print_profile_intervals(f.parameters);
  std::cout << fmt::format("  {:>12} {:>10} {:>10} {:>11}\n", "speed_mps", "e", "model", "residual");
  for (const RestitutionPoint& p : f.points)
    std::cout << fmt::format("  {:>12.6g} {:>10.6f} {:>10.6f} {:>11.3e}\n", p.impact_speed_mps, p.measured, p.model,
                             p.residual);
  std::cout << fmt::format("  model e over the table's speeds: {:.6f} to {:.6f}\n", f.e_min, f.e_max);
  std::cout << (f.sigma_estimated
                    ? fmt::format("  sigma {:.4g} (estimated: no e_sd), {} rows", f.sigma, f.rows)
                    : fmt::format("  reduced chi-square {:.4g} ({} rows)", f.reduced_chi_square, f.rows))
            << fmt::format(", AIC {:.6g}, BIC {:.6g}, {}\n", f.aic, f.bic,
                           f.failed ? "fit failed" : f.identifiable ? "identifiable" : "NOT identifiable");
  if (f.cross_validation) {
    const RestitutionCrossValidation& cv = *f.cross_validation;
    if (cv.failure.empty())
      std::cout << fmt::format("  cross-validation ({} speeds left out in turn): RMS prediction error {:.4g}, {:.3g} "
                               "times the data's scatter {:.4g}\n",
                               cv.folds, cv.rms_prediction_error, cv.ratio, cv.scatter);
    else std::cout << fmt::format("  cross-validation failed: {}\n", cv.failure);
  }
  std::cout << fmt::format("  {} iterations, {} model runs ({}), stopped: {}\n", f.iterations, f.model_runs,
                           f.integrator_used, f.stop_reason);
  if (f.failed) std::cout << fmt::format("  FIT FAILED: {}\n", f.failure);
}

// The ranked table of a law comparison (a restitution table's or a bounce recording's fits: each
// has law, aic, bic, e_min, e_max, failed, failure and an optional cross_validation), then the
// best fit in full by `print_best`; `cv_header` names the cross-validation error's column.
template <class Run, class PrintBest>
void print_law_ranking(const Run& r, const char* cv_header, PrintBest print_best) {
  const bool cv = r.settings.cross_validate;
  std::cout << fmt::format("  {:>3} {:<22} {:>12} {:>10} {:>12} {:>21}{}\n", "", "law (best first)", "AIC", "dAIC", "BIC",
                           "model e range", cv ? fmt::format(" {:>12} {:>8}", cv_header, "cv_rank") : "");
  std::vector<std::size_t> cv_rank(r.fits.size(), 0);
  if (cv) {
    std::vector<std::size_t> order;
    for (std::size_t i = 0; i < r.fits.size(); ++i)
      if (r.fits[i].cross_validation && r.fits[i].cross_validation->failure.empty()) order.push_back(i);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return r.fits[a].cross_validation->rms_prediction_error < r.fits[b].cross_validation->rms_prediction_error;
    });
    for (std::size_t k = 0; k < order.size(); ++k) cv_rank[order[k]] = k + 1;
  }
  std::string ties;
  for (std::size_t i = 0; i < r.fits.size(); ++i) {
    const auto& f = r.fits[i];
    const double gap = f.aic - r.fits.front().aic;
    if (i > 0 && gap < aic_tie) ties += (ties.empty() ? "" : ", ") + f.law;
    std::string cv_columns;
    if (cv)
      cv_columns = cv_rank[i] ? fmt::format(" {:>12.4g} {:>8}", f.cross_validation->rms_prediction_error, cv_rank[i])
                              : fmt::format(" {:>12} {:>8}", "-", "-");
    std::cout << fmt::format("  {:>3} {:<22} {:>12.6g} {:>10.4g} {:>12.6g} {:>10.6f}-{:<10.6f}{}\n", i + 1, f.law, f.aic,
                             gap, f.bic, f.e_min, f.e_max, cv_columns);
  }
  for (const auto& [law, why] : r.failures)
    std::cout << fmt::format("  {}: not fitted: {}\n", law, spell_key_references(why, KeySpelling::command_line));
  for (const auto& f : r.fits)
    if (f.failed) std::cout << fmt::format("  {}: fit failed: {}\n", f.law, f.failure);
  if (r.fits.empty()) {
    std::cout << "  best: none, no law could be fitted\n";
    return;
  }
  if (r.fits.front().failed) std::cout << "  best: none, every fit failed\n";
  else std::cout << fmt::format("  best: '{}'{}\n", r.fits.front().law,
                           ties.empty() ? "" : fmt::format(" (tied within dAIC < {:g}: {})", aic_tie, ties));
  std::cout << fmt::format("  damping law '{}'\n", r.fits.front().law);
  print_best(r.fits.front());
}

void print_restitution_text(const RestitutionFitRun& r) {
  std::cout << fmt::format("hertzdash fit: {} ({} rows{}{})\n", r.table.path.string(), r.table.rows(),
                           r.table.has_sd() ? ", weighted by e_sd" : "", r.table.synthetic ? ", SYNTHETIC" : "");
  if (r.fits.size() == 1 && r.failures.empty()) {
    std::cout << fmt::format("  damping law '{}'\n", r.fits[0].law);
    print_restitution_fit(r.fits[0]);
    return;
  }
  print_law_ranking(r, "cv_rms", print_restitution_fit);
}

// Options that mean nothing for the input given: refused naming both.
void refuse_with(const CLI::App& sub, const std::string& option, const std::string& value, const std::string& with,
                 const std::string& why) {
  if (const CLI::Option* o = sub.get_option_no_throw("--" + option); o && o->count() > 0)
    throw InvalidParameter(option, value, "omitted with `" + with + "` (" + why + ")");
}

int run_restitution_table_fit(const FitCommandOptions& opt, const CLI::App& sub) {
  const std::string table = "restitution-table";
  refuse_with(sub, "channels", opt.channels, table, "a restitution table has no channels");
  refuse_with(sub, "resample", fmt::format("{}", opt.resample_Hz), table, "a restitution table has no samples in time");
  refuse_with(sub, "curves", opt.curves_path, table, "the points of each fit are in --json");
  refuse_with(sub, "trace", opt.trace_path, table, "one input per fit");
  refuse_with(sub, "mkdir", "true", table, "it writes no file");
  RestitutionFitSettings settings;
  if (const CLI::Option* o = sub.get_option_no_throw("--fit"); o && o->count() > 0)
    settings.parameters = parse_fit_parameters(opt.fit);
  settings.cross_validate = opt.cross_validate;
  settings.profile_intervals = opt.profile_intervals;
  const PaperParameters paper = load_paper_parameters();
  const RestitutionFitRun r = run_restitution_fit(opt.table_path, opt.run, paper, settings, opt.compare_laws);
  report_diagnostics(restitution_fit_diagnostics(r));
  if (opt.json) std::cout << to_json(r).dump(2) << "\n";
  else print_restitution_text(r);
  if (r.fits.empty()) return exit_fit_failed;
  return r.fits.front().failed ? exit_fit_failed : 0;
}

void print_bounce_fit(const BounceFit& f) {
  std::cout << fmt::format("  {:<24} {:>14} {:>14} {:>14} {:>9}\n", "parameter", "initial", "estimate", "std_error",
                           "rel_%");
  for (const FittedParameter& p : f.parameters)
    std::cout << fmt::format("  {:<24} {:>14.6g} {:>14.8g} {:>14.3g} {:>9.3g}\n", p.name, p.initial, p.estimate,
                             p.standard_error, 100 * p.standard_error / std::abs(p.estimate));
  std::cout << fmt::format("  {:<16} {:>7} {:>12} {:>11} {:>14} {:>11}\n", "drop", "impacts", "v0_mps", "v0_se",
                           "clock_offset_s", "offset_se");
  for (const BounceDropFit& d : f.drops)
    std::cout << fmt::format("  {:<16} {:>7} {:>12.6g} {:>11.3g} {:>14.9g} {:>11.3g}\n", d.label, d.impacts,
                             d.first_impact_speed.estimate, d.first_impact_speed.standard_error,
                             d.clock_offset.estimate, d.clock_offset.standard_error);
  std::cout << fmt::format("  model e over the data's impacts: {:.6f} to {:.6f}\n", f.e_min, f.e_max);
  std::cout << fmt::format("  timing sigma {:.4g} s (estimated), {} times, {} parameters, AIC {:.6g}, BIC {:.6g}, {}\n",
                           f.sigma, f.times, f.fitted, f.aic, f.bic,
                           f.failed ? "fit failed" : f.identifiable ? "identifiable" : "NOT identifiable");
  if (f.cross_validation) {
    const BounceCrossValidation& cv = *f.cross_validation;
    if (cv.failure.empty())
      std::cout << fmt::format("  cross-validation ({} drops left out in turn): RMS prediction error {:.4g} s, {:.3g} "
                               "times the timing sigma {:.4g} s\n",
                               cv.folds, cv.rms_prediction_error, cv.ratio, cv.scatter);
    else std::cout << fmt::format("  cross-validation failed: {}\n", cv.failure);
  }
  std::cout << fmt::format("  {} iterations, {} model runs ({}), stopped: {}\n", f.iterations, f.model_runs,
                           f.integrator_used, f.stop_reason);
  if (f.failed) std::cout << fmt::format("  FIT FAILED: {}\n", f.failure);
}

void print_bounce_text(const BounceFitRun& r) {
  std::cout << fmt::format("hertzdash fit: {} ({} drops, {} impacts, {} used, {} flagged{})\n",
                           r.recording.path.string(), r.recording.drops.size(), r.recording.impacts(),
                           r.checked.times(), r.checked.flagged.size(), r.recording.synthetic ? ", SYNTHETIC" : "");
  if (r.fits.size() == 1 && r.failures.empty()) {
    std::cout << fmt::format("  damping law '{}'\n", r.fits[0].law);
    print_bounce_fit(r.fits[0]);
    return;
  }
  print_law_ranking(r, "cv_rms_s", print_bounce_fit);
}

int run_bounce_times_fit(const FitCommandOptions& opt, const CLI::App& sub) {
  const std::string bounce = "bounce-times";
  refuse_with(sub, "channels", opt.channels, bounce, "a bounce recording has no channels");
  refuse_with(sub, "resample", fmt::format("{}", opt.resample_Hz), bounce, "a bounce recording has no samples in time");
  refuse_with(sub, "curves", opt.curves_path, bounce, "the points of each fit are in --json");
  refuse_with(sub, "trace", opt.trace_path, bounce, "one input per fit");
  refuse_with(sub, "restitution-table", opt.table_path, bounce, "one input per fit");
  refuse_with(sub, "mkdir", "true", bounce, "it writes no file");
  refuse_with(sub, "profile-intervals", "true", bounce,
              "not computed for a recording yet (the coverage of its standard errors is tested)");
  BounceFitSettings settings;
  if (const CLI::Option* o = sub.get_option_no_throw("--fit"); o && o->count() > 0)
    settings.parameters = parse_fit_parameters(opt.fit);
  settings.cross_validate = opt.cross_validate;
  const PaperParameters paper = load_paper_parameters();
  const BounceFitRun r = run_bounce_fit(opt.bounce_path, opt.run, paper, settings, opt.compare_laws);
  report_diagnostics(bounce_fit_diagnostics(r));
  if (opt.json) std::cout << to_json(r).dump(2) << "\n";
  else print_bounce_text(r);
  if (r.fits.empty()) return exit_fit_failed;
  return r.fits.front().failed ? exit_fit_failed : 0;
}

}  // namespace

Command add_fit_command(CLI::App& app) {
  auto opt = std::make_shared<FitCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "fit", "Identify parameters (by default the hemisphere's modulus and e) from a measured trace");
  sub->add_option("--trace", opt->trace_path, "Measured trace, CSV (data/measurements/README.md); or --restitution-table");
  sub->add_option("--restitution-table", opt->table_path,
                  "Restitution table, CSV: e against the impact speed (data/measurements/README.md); fits the law's own "
                  "parameters (docs/fit.md); or --trace");
  sub->add_option("--bounce-times", opt->bounce_path,
                  "Bounce recording, CSV: the detected impact times of one or more drops (data/measurements/README.md); "
                  "flags doubled, missed and out-of-order detections, fits the law's own parameters and each drop's "
                  "first impact speed and clock offset (docs/fit.md); or --trace");
  add_run_options(*sub, opt->run, RunOption::Group::setup);
  sub->add_option("--fit", opt->fit,
                  "Parameters to fit besides the onset time: NAME or NAME:LOWER:UPPER, comma-separated; NAME one of: " +
                      fittable_option_names() + "; the starting values are the run options (or the paper's); with "
                      "--restitution-table and --bounce-times the default is the law's own (restitution, or viscous-time-constant)")
      ->capture_default_str();
  sub->add_option("--channels", opt->channels, "Channels of the trace to fit (default: all it has)");
  add_number_option(*sub, "--resample", opt->resample_Hz, "Average the trace into bins of 1/RATE first [Hz]; 0 = as sampled");
  sub->add_flag("--compare-laws", opt->compare_laws, "Fit every registered damping law and rank them by AIC");
  sub->add_flag("--cross-validate", opt->cross_validate,
                "With --restitution-table: leave out each distinct speed in turn, fit the rest, predict it; with "
                "--bounce-times: each drop; rank by the prediction error too");
  sub->add_flag("--profile-intervals", opt->profile_intervals,
                "Each fitted parameter's profile-likelihood 1-sigma interval too (a re-fit per point; docs/fit.md)");
  add_output_file_option(*sub, "--curves", opt->curves_path, "Write the trace, the fitted model and the residuals to this CSV file");
  sub->add_flag("--json", opt->json, "Print the result as one JSON object");
  add_mkdir_flag(*sub, opt->mkdir);

  return {sub, [opt, sub]() {
            if (!opt->bounce_path.empty()) return run_bounce_times_fit(*opt, *sub);
            if (!opt->table_path.empty()) return run_restitution_table_fit(*opt, *sub);
            if (opt->trace_path.empty())
              throw CLI::RequiredError(
                  "--trace is required (or --restitution-table, a restitution table, or --bounce-times, a bounce "
                  "recording)",
                  CLI::ExitCodes::RequiredError);
            if (opt->cross_validate)
              throw InvalidParameter("cross-validate", "true",
                                     "given only with `restitution-table` or `bounce-times` (a trace's fit is not "
                                     "cross-validated)");
            prepare_output_file("--curves", opt->curves_path, opt->mkdir);
            refuse_shared_files({{"--trace", opt->trace_path}}, {{"--curves", opt->curves_path}});
            TraceFitSettings settings;
            settings.parameters = parse_fit_parameters(opt->fit);
            if (!opt->channels.empty()) settings.channels = parse_channels(opt->channels, "channels");
            settings.resample_Hz = opt->resample_Hz;
            settings.profile_intervals = opt->profile_intervals;
            const PaperParameters paper = load_paper_parameters();
            const FitRun r = run_fit(opt->trace_path, opt->run, paper, settings, opt->compare_laws, given_options(*sub));
            if (r.fits.empty()) throw std::runtime_error("no damping law could be fitted to the trace");
            report_diagnostics(fit_diagnostics(r, paper));
            create_output_directories(opt->curves_path, opt->mkdir);
            if (!opt->curves_path.empty()) write_fit_curves(r.fits.front(), r.trace, opt->curves_path);
            if (opt->json) std::cout << to_json(r, paper).dump(2) << "\n";
            else print_text(r);
            return r.fits.front().failed ? exit_fit_failed : 0;
          }};
}

}  // namespace hertzdash::cli
