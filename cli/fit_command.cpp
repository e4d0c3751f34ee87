// `hertzdash fit`: identify parameters of the drop test from a measured trace
// (data/measurements/README.md) by weighted least squares (simulation/fit/trace_fit.hpp): the
// estimates, their standard errors and correlation, the residuals per channel, whether the
// trace determines the parameters; --compare-laws fits every registered law and ranks them by
// AIC; --curves writes the trace, the fitted model and the residuals for a figure
// (validation/identification/identification_fit.gp draws two).
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/setup_options.hpp"
#include "hertzdash/simulation/fit/virtual_measurement.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>

namespace hertzdash::cli {

namespace {

struct FitCommandOptions {
  RunOptions run;
  std::string trace_path, fit = "ball-E,restitution", channels, curves_path;
  double resample_Hz = 0;
  bool compare_laws = false, json = false, mkdir = false;
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

void print_fit(const TraceFit& f) {
  std::cout << fmt::format("  {:<24} {:>14} {:>14} {:>14} {:>9}\n", "parameter", "initial", "estimate", "std_error",
                           "rel_%");
  for (const FittedParameter& p : f.parameters)
    std::cout << fmt::format("  {:<24} {:>14.6g} {:>14.8g} {:>14.3g} {:>9}\n", p.name, p.initial, p.estimate,
                             p.standard_error,
                             p.name == "onset-time" ? "-" : fmt::format("{:.3g}", 100 * p.standard_error / std::abs(p.estimate)));
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

}  // namespace

Command add_fit_command(CLI::App& app) {
  auto opt = std::make_shared<FitCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "fit", "Identify parameters (by default the hemisphere's modulus and e) from a measured trace");
  sub->add_option("--trace", opt->trace_path, "Measured trace, CSV (data/measurements/README.md)")->required();
  add_run_options(*sub, opt->run, RunOption::Group::setup);
  sub->add_option("--fit", opt->fit,
                  "Parameters to fit besides the onset time: NAME or NAME:LOWER:UPPER, comma-separated; NAME one of: " +
                      fittable_option_names() + "; the starting values are the run options (or the paper's)")
      ->capture_default_str();
  sub->add_option("--channels", opt->channels, "Channels of the trace to fit (default: all it has)");
  add_number_option(*sub, "--resample", opt->resample_Hz, "Average the trace into bins of 1/RATE first [Hz]; 0 = as sampled");
  sub->add_flag("--compare-laws", opt->compare_laws, "Fit every registered damping law and rank them by AIC");
  add_output_file_option(*sub, "--curves", opt->curves_path, "Write the trace, the fitted model and the residuals to this CSV file");
  sub->add_flag("--json", opt->json, "Print the result as one JSON object");
  add_mkdir_flag(*sub, opt->mkdir);

  return {sub, [opt, sub]() {
            prepare_output_file("--curves", opt->curves_path, opt->mkdir);
            refuse_shared_files({{"--trace", opt->trace_path}}, {{"--curves", opt->curves_path}});
            TraceFitSettings settings;
            settings.parameters = parse_fit_parameters(opt->fit);
            if (!opt->channels.empty()) settings.channels = parse_channels(opt->channels, "channels");
            settings.resample_Hz = opt->resample_Hz;
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
