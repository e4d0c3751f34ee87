#pragma once
// Internal to the fits (not installed, cmake/install.cmake): the starting values of the fitted
// parameters, and what every kind's model keeps (FitModel). Parsing a --fit list
// (parse_fit_parameters) is public, in fit_engine.hpp.
#include "hertzdash/simulation/fit/fit_engine.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <string>
#include <utility>
#include <vector>

namespace hertzdash::fit_detail {

/// The starting value of each parameter: its value in the set-up `base` resolves to. Throws
/// InvalidParameter("fit", ...) for a parameter unset with no default, or outside its bounds.
std::vector<double> initial_values(const RunOptions& base, const PaperParameters& paper,
                                   const std::vector<FitParameter>& parameters);

/// The starting values of a law's parameters fitted to impacts (a table, a recording): the
/// option given, else `restitution` at `e`, `viscous-time-constant` the law's calibration to `e`
/// at `speed_mps` (one contact: no gravity, no drag), else initial_values. Throws like it.
std::vector<double> law_starting_values(const RunOptions& base, const PaperParameters& paper,
                                        const std::vector<FitParameter>& parameters, double e, double speed_mps);

/// What every kind's model keeps: the run options, the paper, the fitted options' names, its runs
/// so far and the integrator that ran them.
class FitModel {
 public:
  FitModel(RunOptions base, const PaperParameters& paper, std::vector<std::string> names)
      : base_(std::move(base)), paper_(&paper), names_(std::move(names)) {}

  /// The run options with the fitted options (`names`) at `values`.
  RunOptions options_at(const std::vector<double>& values) const;
  int runs() const { return runs_; }
  const std::string& integrator_used() const { return integrator_used_; }

 protected:
  RunOptions base_;
  const PaperParameters* paper_;
  std::vector<std::string> names_;
  int runs_ = 0;
  std::string integrator_used_;
};

double mean(const std::vector<double>& v);
double median(std::vector<double> v);

}  // namespace hertzdash::fit_detail
