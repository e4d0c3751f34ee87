// The model of a bounce-recording fit (simulation/fit/bounce_fit_model.hpp): each drop's impacts
// as run_bounce_sequence follows them, the starting values; and the options such a fit refuses.
#include "hertzdash/simulation/fit/bounce_fit_model.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/omega_n_variant.hpp"
#include "hertzdash/simulation/fit/bounce_fit.hpp"
#include "hertzdash/simulation/fit/fit_parameters.hpp"
#include "hertzdash/simulation/fit/restitution_fit_model.hpp"
#include "hertzdash/simulation/run/bounce_sequence.hpp"
#include "hertzdash/simulation/run/law_runs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace hertzdash {

void check_bounce_fit_options(const RunOptions& o) {
  const std::string given = "omitted with `bounce-times` (each drop's first impact speed is fitted)";
  if (o.impact_velocity_mps) throw InvalidParameter("impact-velocity", format_value(*o.impact_velocity_mps), given);
  if (o.height_m) throw InvalidParameter("height", format_value(*o.height_m), given);
  if (o.rod_model != "rigid")
    throw InvalidParameter("rod-model", o.rod_model,
                           "rigid with `bounce-times` (its flights are closed forms; the elastic rod's are integrated, "
                           "too slow to fit)");
  refuse_trace_only_options(o, "hertzdash fit --bounce-times");
  if (o.omega_n && is_iterated(parse_omega_n_variant(*o.omega_n)))
    throw InvalidParameter("omega-n", *o.omega_n,
                           "a closed-form variant with `bounce-times`: paper, impact-energy, rebound-energy or "
                           "as-printed (the iterated variants need hertzdash simulate)");
}

}  // namespace hertzdash

namespace hertzdash::bounce_fit_detail {

namespace {

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// S_g(r) = 1 + r + ... + r^{g-1}.
double span(int g, double r) {
  double s = 0, q = 1;
  for (int k = 0; k < g; ++k) s += q, q *= r;
  return s;
}

// The A of a material-time-constant law whose e at `speed` is `e` (the simulator's calibration).
double calibrated_time_constant(const RunOptions& base, const PaperParameters& paper, double speed, double e) {
  RunOptions o = base;
  o.restitution = e;
  o.viscous_time_constant_s.reset();
  o.air_density_kg_per_m3.reset();  // one contact: no flight, no drag
  o.drag_coefficient.reset();
  const DropTestSetup s = restitution_fit_detail::restitution_contact(o, paper, speed);
  const LawRuns& runs = law_runs(base.damping);
  return runs.calibrated_time_constant ? *runs.calibrated_time_constant(s).damping.viscous_time_constant_s : 0.0;
}

}  // namespace

BounceModel::BounceModel(RunOptions base, const PaperParameters& paper, std::vector<std::string> names)
    : base_(std::move(base)), paper_(&paper), names_(std::move(names)) {
  base_.follows_flights = true;  // run_bounce_sequence's flights read the air drag
}

RunOptions BounceModel::options_at(const std::vector<double>& law) const {
  RunOptions o = base_;
  for (std::size_t j = 0; j < names_.size(); ++j) set_number(o, *find_run_option(names_[j]), law[j]);
  return o;
}

const std::vector<ModelImpact>* BounceModel::impacts(const std::vector<double>& law, double v0, int count) {
  std::vector<double> key = law;
  key.push_back(v0);
  key.push_back(count);
  if (auto it = cache_.find(key); it != cache_.end()) return it->second ? &*it->second : nullptr;
  if (cache_.size() > 4096) cache_.clear();
  std::optional<std::vector<ModelImpact>> value;
  try {
    RunOptions o = options_at(law);
    o.impact_velocity_mps = v0;
    const DropTestSetup s = resolve_setup(o, *paper_);
    const BounceSequence b = run_bounce_sequence(s, base_.damping, restitution_fit_detail::restitution_model_solver(),
                                                 {.impacts = count, .min_rebound_velocity_mps = 0.0});
    ++runs_;
    integrator_used_ = to_string(b.integrator_used);
    if (static_cast<int>(b.impacts.size()) == count) {
      value.emplace();
      for (const BounceImpact& i : b.impacts) value->push_back({i.onset_time_s, i.approach_speed_mps, i.rebound_speed_mps});
    }
  } catch (const InvalidParameter&) {
  } catch (const std::runtime_error&) {  // a run that failed its checks: outside the model's domain
  }
  auto it = cache_.emplace(std::move(key), std::move(value)).first;
  return it->second ? &*it->second : nullptr;
}

std::vector<double> starting_values(const CheckedRecording& data, const RunOptions& base, const PaperParameters& paper,
                                    const std::vector<FitParameter>& parameters) {
  std::vector<double> ratios;
  for (const CheckedDrop& d : data.drops)
    if (d.interval_ratio > 0 && d.interval_ratio < 1) ratios.push_back(d.interval_ratio);
  const double r = std::clamp(ratios.empty() ? 0.8 : median(ratios), 0.01, 0.99);
  const double g = resolve_setup([&] {
                     RunOptions o = base;
                     o.follows_flights = true;
                     o.impact_velocity_mps = 1.0;
                     return o;
                   }(), paper).gravity_mps2;
  std::vector<double> speeds;
  for (const CheckedDrop& d : data.drops) {
    const double dr = d.interval_ratio > 0 && d.interval_ratio < 1 ? d.interval_ratio : r;
    speeds.push_back(d.drop_height_m > 0
                         ? std::sqrt(2.0 * g * d.drop_height_m)
                         : g * (d.impact_time_s[1] - d.impact_time_s[0]) / (2.0 * dr * span(d.impact_number[1], dr)));
  }
  std::vector<double> v;
  for (const FitParameter& p : parameters) {
    require_read(base, *find_run_option(p.option), "(fitted)");
    double x;
    if (p.option == "restitution" && !base.restitution) x = r;
    else if (p.option == "viscous-time-constant" && !base.viscous_time_constant_s)
      x = calibrated_time_constant(base, paper, median(speeds), r);
    else x = trace_fit_detail::initial_values(base, paper, {p}).front();
    if (!(x > p.lower && x < p.upper))
      throw InvalidParameter("fit", fmt::format("{}:{}:{}", p.option, format_value(p.lower), format_value(p.upper)),
                             fmt::format("bounds around the starting value {} {} (set it inside them)",
                                         key_reference(p.option), format_value(x)));
    v.push_back(x);
  }
  for (std::size_t d = 0; d < data.drops.size(); ++d) v.push_back(speeds[d]), v.push_back(data.drops[d].impact_time_s[0]);
  return v;
}

}  // namespace hertzdash::bounce_fit_detail
