// A `simulate` run recorded as a virtual experiment (simulation/reports/run_reports.hpp): the measured
// trace with its provenance, the note on interpolated samples, and the file's header parameters.
#include "hertzdash/simulation/reports/run_reports.hpp"
#include "hertzdash/simulation/run/impact_history.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace hertzdash {

MeasuredTrace virtual_measurement(const SimulateRun& run, const std::string& rod, const MeasurementChain& chain) {
  MeasuredTrace m = record_virtual_measurement(ImpactHistory(run.trace, run.setup.gravity_mps2), chain);
  m.source = "SYNTHETIC: a virtual experiment made by hertzdash simulate --trace-format measured (the model through "
             "a simulated measurement chain; not a measurement)";
  m.rod = rod;
  m.height_m = trace_height_m(run.setup);
  return m;
}

double trace_height_m(const DropTestSetup& setup) {
  const double g = setup.gravity_mps2;
  if (!setup.impact_velocity_mps) return setup.height_m;
  return g > 0 ? *setup.impact_velocity_mps * *setup.impact_velocity_mps / (2 * g) : 0.0;
}

std::string virtual_measurement_note(const SimulateRun& run, const MeasurementChain& chain) {
  double longest = 0;
  for (std::size_t i = 1; i < run.trace.size(); ++i) longest = std::max(longest, run.trace[i].t_s - run.trace[i - 1].t_s);
  if (!(longest > 1.0 / chain.sample_rate_Hz)) return {};
  return fmt::format("{} took steps up to {:.3g} s, longer than the sampling interval {:.3g} s: the samples between its "
                     "steps are linear interpolations (bound the step with `max-step`, or use a fixed `dt`, for a "
                     "faithful virtual experiment)",
                     to_string(run.summary.integrator_used), longest, 1.0 / chain.sample_rate_Hz);
}

Parameters virtual_measurement_parameters(const SimulateRun& run, const MeasurementChain& chain) {
  Parameters p = run.inputs;
  p.emplace_back("integrator_used", to_string(run.summary.integrator_used));
  p.emplace_back("sample_rate_Hz", fmt::format("{}", chain.sample_rate_Hz));
  p.emplace_back("anti_alias_cutoff_Hz", fmt::format("{}", chain.anti_alias_cutoff_Hz));
  p.emplace_back("noise_fraction", fmt::format("{}", chain.noise_fraction));
  p.emplace_back("noise_seed", std::to_string(chain.seed));
  return p;
}

}  // namespace hertzdash
