#pragma once
// Internal to the trace fit (simulation/fit/trace_fit.cpp; not installed, cmake/install.cmake): the
// model a trace is fitted with (simulation/fit/trace_fit.hpp, "Model"): the run options with the
// fitted values, from contact onset, by RK4 at a fixed step t_H / steps_per_contact.
#include "hertzdash/simulation/fit/fit_parameters.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_history.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <optional>
#include <string>
#include <vector>

namespace hertzdash::trace_fit_detail {

class TraceModel : public fit_detail::FitModel {
 public:
  TraceModel(RunOptions base, const PaperParameters& paper, std::vector<std::string> names, int steps_per_contact);

  /// t_H at the initial parameters [s]: the unit of the onset variable and of the step.
  double time_scale_s() const { return time_scale_s_; }
  /// RK4 steps of all runs so far (the model's share of the fit's work, trace_fit.hpp "Work").
  double steps() const { return steps_; }
  const SolverSettings& solver() const { return solver_; }

  /// The impact at these parameter values (the last one is kept), or nullptr where they leave
  /// the model's domain: values the set-up rejects, or an undamped Hertz contact longer than
  /// max_contact_growth times the starting one (the fixed step would take that many more steps).
  const ImpactHistory* history(const std::vector<double>& values);
  double contact_time_s() const { return summary_.contact_time_s; }
  const ImpactSummary& summary() const { return summary_; }

 private:
  DropTestSetup onset_setup(const RunOptions& o) const;

  double time_scale_s_ = 0;
  SolverSettings solver_;
  std::optional<ImpactSimulator> simulator_;
  static constexpr double max_contact_growth = 50;
  std::vector<double> values_;
  bool values_valid_ = false;
  std::optional<ImpactHistory> history_;
  ImpactSummary summary_;  // of the last run
  double steps_ = 0;
};

}  // namespace hertzdash::trace_fit_detail
