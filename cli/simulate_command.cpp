// `hertzdash simulate`: one drop test of the paper's set-up, any law, any integrator.
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/setup_options.hpp"
#include "cli/trace_file.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/reports/result_output.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"

#include <fmt/format.h>

#include <iostream>
#include <memory>

namespace hertzdash::cli {

namespace {

struct SimulateOptions {
  RunOptions run;
  std::string trace_path;
  std::string trace_format = "model";
  MeasurementChain chain;
  std::string channels = "force_N,accel_mps2,displacement_m";
  bool json = false, mkdir = false;
};

// The options of the measured format, which are errors with the model's.
constexpr const char* measurement_options[] = {"--sample-rate", "--anti-alias", "--noise", "--seed", "--channels"};

void check_trace_options(const CLI::App& sub, SimulateOptions& opt) {
  if (opt.trace_format == "measured") {
    if (opt.trace_path.empty()) throw InvalidParameter("--trace-format", opt.trace_format, "given with --trace FILE");
    opt.chain.channels = parse_channels(opt.channels, "channels");
    validate(opt.chain);
    return;
  }
  if (opt.trace_format != "model") throw InvalidParameter("--trace-format", opt.trace_format, "one of: model, measured");
  for (const char* name : measurement_options)
    if (sub.count(name) > 0)
      throw InvalidParameter(name, sub.get_option(name)->as<std::string>(),
                             "given only with --trace-format measured (it describes the virtual measurement)");
}

void print_text(const SimulateRun& r) {
  const ImpactSummary& s = r.summary;
  const IntegratorKind asked = r.solver.integrator;
  std::cout << fmt::format("hertzdash simulate: damping law '{}', integrator {}{}\n", r.law, to_string(asked),
                           s.integrator_used == asked ? "" : fmt::format(" (ran {})", to_string(s.integrator_used)));
  std::cout << result_text_block(s, r.setup);
}

void write_trace(const SimulateRun& r, const std::string& path) {
  Parameters inputs = r.inputs;
  inputs.emplace_back("integrator_used", to_string(r.summary.integrator_used));
  write_model_trace(path, r.trace, "hertzdash simulate --trace: the contact phase at every integrator step",
                    "hertzdash simulate: contact-phase time series (t_s and displacement_m since contact onset; force "
                    "compressive positive; accel, velocity and displacement of the rod downward positive)",
                    inputs, trace_height_m(r.setup));
}

}  // namespace

Command add_simulate_command(CLI::App& app) {
  auto opt = std::make_shared<SimulateOptions>();
  CLI::App* sub = app.add_subcommand("simulate", "Simulate one drop of a rod onto the nylon hemisphere");
  add_run_options(*sub, opt->run);
  auto o = [](std::string_view key) { return declared_option("simulate", key); };
  add_output_file_option(*sub, o("trace").flag, opt->trace_path, o("trace").help);
  sub->add_option(o("trace-format").flag, opt->trace_format, o("trace-format").help);
  add_number_option(*sub, o("sample-rate").flag, opt->chain.sample_rate_Hz, o("sample-rate").help);
  add_number_option(*sub, o("anti-alias").flag, opt->chain.anti_alias_cutoff_Hz, o("anti-alias").help);
  add_number_option(*sub, o("noise").flag, opt->chain.noise_fraction, o("noise").help);
  add_integer_option(*sub, o("seed").flag, opt->chain.seed, o("seed").help);
  sub->add_option(o("channels").flag, opt->channels, o("channels").help);
  for (const char* flag : measurement_options) sub->get_option(flag)->group("Virtual measurement (--trace-format measured)");
  sub->add_flag(o("json").flag, opt->json, o("json").help);
  add_mkdir_flag(*sub, opt->mkdir);

  return {sub, [opt, sub]() {
            check_trace_options(*sub, *opt);
            prepare_output_file("--trace", opt->trace_path, opt->mkdir);
            const SimulateRun r = run_simulate(opt->run, load_paper_parameters(), !opt->trace_path.empty());
            std::string trace_note;
            if (opt->trace_format == "measured") {
              const MeasuredTrace measurement = virtual_measurement(r, opt->run.rod, opt->chain);
              create_output_directories(opt->trace_path, opt->mkdir);
              write_measured_trace(opt->trace_path, measurement,
                                   "hertzdash simulate: a SYNTHETIC virtual measurement of the model (not a measurement)",
                                   virtual_measurement_parameters(r, opt->chain));
              trace_note = virtual_measurement_note(r, opt->chain);
            } else if (!opt->trace_path.empty()) {
              create_output_directories(opt->trace_path, opt->mkdir);
              write_trace(r, opt->trace_path);
            }
            report_diagnostics(run_diagnostics(r, trace_note));
            if (opt->json) std::cout << to_json(r, trace_note).dump(2) << "\n";
            else print_text(r);
            return 0;
          }};
}

}  // namespace hertzdash::cli
