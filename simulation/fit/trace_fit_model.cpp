// The model of a trace fit (simulation/fit/trace_fit_model.hpp): the drop test at the fitted
// parameters' values, from contact onset, by RK4 at a fixed step, its last run kept.
#include "hertzdash/simulation/fit/trace_fit_model.hpp"

#include "hertzdash/model/invalid_parameter.hpp"

namespace hertzdash::trace_fit_detail {

TraceModel::TraceModel(RunOptions base, const PaperParameters& paper, std::vector<std::string> names,
                       int steps_per_contact)
    : FitModel(std::move(base), paper, std::move(names)) {
  const DropTestSetup s = onset_setup(base_);
  time_scale_s_ = undamped_hertz_impact(hertz_stiffness(s), s.mass_kg, approach_speed(s)).contact_time_s;
  solver_.integrator = IntegratorKind::rk4;
  solver_.dt_s = time_scale_s_ / steps_per_contact;
  simulator_.emplace(solver_);
}

const ImpactHistory* TraceModel::history(const std::vector<double>& values) {
  if (values_valid_ && values == values_) return history_ ? &*history_ : nullptr;
  values_ = values;
  values_valid_ = true;
  history_.reset();
  DropTestSetup s;
  try {
    s = onset_setup(options_at(values));
  } catch (const InvalidParameter&) {
    return nullptr;
  }
  if (undamped_hertz_impact(hertz_stiffness(s), s.mass_kg, approach_speed(s)).contact_time_s >
      max_contact_growth * time_scale_s_)
    return nullptr;
  std::vector<TraceSample> trace;
  const ImpactSummary summary = simulator_->run(s, base_.damping, &trace);
  ++runs_;
  steps_ += static_cast<double>(summary.work.steps);
  history_.emplace(std::move(trace), s.gravity_mps2);
  summary_ = summary;
  return &*history_;
}

DropTestSetup TraceModel::onset_setup(const RunOptions& o) const {
  DropTestSetup s = resolve_setup(o, *paper_);
  s.impact_velocity_mps = approach_speed(s);  // start at contact onset: the drop before it is exact
  return s;
}

}  // namespace hertzdash::trace_fit_detail
