#pragma once
// Internal to the fits (not installed, cmake/install.cmake): the starting values of the fitted
// parameters. Parsing a --fit list (parse_fit_parameters) is public, in fit_engine.hpp.
#include "hertzdash/simulation/fit/fit_engine.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

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

double mean(const std::vector<double>& v);
double median(std::vector<double> v);

}  // namespace hertzdash::fit_detail
