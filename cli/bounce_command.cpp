// `hertzdash bounce`: a drop from --height and the impacts that follow it, with any law,
// integrator and rod model; per impact the onset, separation and contact times, approach and
// rebound speeds and peak force, and the restitution the paper's method would measure from the
// intervals between impacts beside the true velocity ratios (simulation/run/bounce_sequence.hpp).
// With --target-interval-restitution it first finds the input e whose first interval ratio is
// the target: the e the paper should have put into its dashpot.
#include "cli/command.hpp"
#include "cli/number_options.hpp"
#include "cli/output_files.hpp"
#include "cli/setup_options.hpp"
#include "cli/trace_file.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "hertzdash/simulation/run/bounce_trace.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"

#include <fmt/format.h>

#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>

namespace hertzdash::cli {

namespace {

/// A progress line on stderr for a sequence that runs long (the elastic rod: seconds per impact):
/// after 2 s, redrawn on a terminal at most 5 times a second, else a line every 10 s.
class ProgressLine {
 public:
  explicit ProgressLine(int impacts) : impacts_(impacts) {}
  void operator()(std::size_t done) {
    const auto now = std::chrono::steady_clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    if (elapsed < 2.0 || std::chrono::duration<double>(now - last_).count() < (terminal_ ? 0.2 : 10.0)) return;
    last_ = now;
    drawn_ = true;
    std::cerr << fmt::format("{}hertzdash bounce: impact {} of at most {} after {:.0f} s{}", terminal_ ? "\r" : "",
                             done, impacts_, elapsed, terminal_ ? "" : "\n")
              << std::flush;
  }
  /// Ends a redrawn line, so that what follows (the result, or an error) starts on a line of its own.
  ~ProgressLine() {
    if (drawn_ && terminal_) std::cerr << "\n";
  }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

 private:
  int impacts_;
  bool terminal_ = isatty(STDERR_FILENO) != 0;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now(), last_ = start_;
};

struct BounceCommandOptions {
  RunOptions run;
  BounceOptions bounce;
  double bounces = BounceOptions{}.impacts;  // read as a number, so that 2.5 gets the range in its message
  std::optional<double> interval_target;
  std::string trace_path;
  bool json = false, mkdir = false;
};

void print_text(const BounceRun& r) {
  const BounceSequence& b = r.sequence;
  std::cout << fmt::format("hertzdash bounce: damping law '{}', integrator {}, flights {}\n", r.law,
                           to_string(b.integrator_used), b.flights_integrated ? "integrated" : "in closed form");
  if (r.calibration)
    std::cout << fmt::format("  input e {:.6g} gives the first interval ratio {:.6g} (target {:.6g})\n",
                             r.calibration->e_input, r.calibration->e_effective, *r.interval_target);
  if (b.viscous_time_constant_s) std::cout << fmt::format("  viscous_time_constant_s {:.6g}\n", *b.viscous_time_constant_s);
  std::cout << fmt::format("  {:>3} {:>14} {:>14} {:>12} {:>12} {:>12} {:>12} {:>10} {:>10}\n", "n", "onset_time_s",
                           "separation_s", "contact_s", "approach_mps", "rebound_mps", "peak_force_N", "e_velocity",
                           "e_interval");
  for (std::size_t n = 0; n < b.impacts.size(); ++n) {
    const BounceImpact& i = b.impacts[n];
    const std::string ev = i.separated ? fmt::format("{:.6f}", i.rebound_speed_mps / i.approach_speed_mps) : "-";
    const std::string ei = n < b.e_from_intervals.size() ? fmt::format("{:.6f}", b.e_from_intervals[n]) : "-";
    std::cout << fmt::format("  {:>3} {:>14.9f} {:>14.9f} {:>12.6g} {:>12.6g} {:>12.6g} {:>12.6g} {:>10} {:>10}\n", n,
                             i.onset_time_s, i.separation_time_s, i.contact_time_s, i.approach_speed_mps,
                             i.rebound_speed_mps, i.peak_force_N, ev, ei);
  }
  std::cout << fmt::format("  ended: {}; {} steps, {} rhs evaluations\n", b.end_reason, b.work.steps,
                           b.work.rhs_evaluations);
}

}  // namespace

Command add_bounce_command(CLI::App& app) {
  auto opt = std::make_shared<BounceCommandOptions>();
  CLI::App* sub = app.add_subcommand(
      "bounce", "A drop and the bounces after it: the paper's restitution from impact intervals beside velocity ratios");
  add_run_options(*sub, opt->run);
  auto o = [](std::string_view key) { return declared_option("bounce", key); };
  add_number_option(*sub, o("bounces").flag, opt->bounces, o("bounces").help)->type_name("INT");
  add_number_option(*sub, o("min-rebound-velocity").flag, opt->bounce.min_rebound_velocity_mps,
                    o("min-rebound-velocity").help);
  add_number_option(*sub, o("target-interval-restitution").flag, opt->interval_target,
                    o("target-interval-restitution").help);
  sub->add_flag(o("json").flag, opt->json, o("json").help);
  add_output_file_option(*sub, o("trace").flag, opt->trace_path, o("trace").help);
  add_mkdir_flag(*sub, opt->mkdir);

  return {sub, [opt]() {
            opt->bounce.impacts = parse_bounces(opt->bounces);
            prepare_output_file("--trace", opt->trace_path, opt->mkdir);
            if (!opt->trace_path.empty() && opt->run.rod_model == "elastic")
              throw InvalidParameter("rod-model", "elastic",
                                     "rigid with `trace` (the elastic rod's flights are integrated with the rod "
                                     "ringing; its sequence records no time series)");
            std::optional<BounceRun> r;
            {
              ProgressLine progress(opt->bounce.impacts);  // its line ends before the result or an error
              opt->bounce.on_impact = [&progress](std::size_t done) { progress(done); };
              r = run_bounce(opt->run, load_paper_parameters(), opt->bounce, opt->interval_target);
              opt->bounce.on_impact = nullptr;
            }
            if (!opt->trace_path.empty()) {
              Parameters inputs = r->inputs;
              inputs.emplace_back("integrator_used", to_string(r->sequence.integrator_used));
              create_output_directories(opt->trace_path, opt->mkdir);
              write_model_trace(opt->trace_path, bounce_trace(r->sequence, r->setup, r->law, r->solver),
                                "hertzdash bounce --trace: each contact at the integrator's steps, each flight in "
                                "closed form",
                                "hertzdash bounce: the sequence's time series (t_s and displacement_m since the first "
                                "contact onset; x_m < 0 in flight, the gap; force compressive positive; accel, velocity "
                                "and displacement of the rod downward positive)",
                                inputs, trace_height_m(r->setup));
            }
            report_diagnostics(run_diagnostics(*r));
            if (opt->json) std::cout << to_json(*r).dump(2) << "\n";
            else print_text(*r);
            return 0;
          }};
}

}  // namespace hertzdash::cli
