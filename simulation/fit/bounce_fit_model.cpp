// The model of a bounce-recording fit (simulation/fit/bounce_fit_model.hpp): each drop's impacts
// as run_bounce_sequence follows them; and the options such a fit refuses.
#include "hertzdash/simulation/fit/bounce_fit_model.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/omega_n_variant.hpp"
#include "hertzdash/simulation/fit/bounce_fit.hpp"
#include "hertzdash/simulation/fit/restitution_fit_model.hpp"
#include "hertzdash/simulation/run/bounce_sequence.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace hertzdash {

namespace {

void check_bounce_fit_options(const RunOptions& o) {
  const std::string given = "omitted with `bounce-times` (each drop's first impact speed is fitted)";
  if (o.impact_velocity_mps) throw InvalidParameter("impact-velocity", format_value(*o.impact_velocity_mps), given);
  if (o.height_m) throw InvalidParameter("height", format_value(*o.height_m), given);
  if (o.rod_model != "rigid")
    throw InvalidParameter("rod-model", o.rod_model,
                           "rigid with `bounce-times` (its flights are closed forms; the elastic rod's are integrated, "
                           "too slow to fit)");
  if (o.gravity_mps2 && !(*o.gravity_mps2 > 0))
    throw InvalidParameter("gravity", format_value(*o.gravity_mps2),
                           "> 0 with `bounce-times` (the flights between a recording's impacts fall under gravity; "
                           "without it the body never comes back)");
  refuse_trace_only_options(o, "hertzdash fit --bounce-times");
  if (o.omega_n && is_iterated(parse_omega_n_variant(*o.omega_n)))
    throw InvalidParameter("omega-n", *o.omega_n,
                           "a closed-form variant with `bounce-times`: paper, impact-energy, rebound-energy or "
                           "as-printed (the iterated variants need hertzdash simulate)");
}

}  // namespace

void check_bounce_fit_setup(const RunOptions& o, const PaperParameters& paper) {
  check_bounce_fit_options(o);
  RunOptions probe = o;
  probe.follows_flights = true;  // the model's flights read the air drag
  probe.impact_velocity_mps = 1.0;
  try {
    resolve_setup(probe, paper);
  } catch (const InvalidParameter& e) {
    if (e.key != "impact-velocity") throw;  // the probe's speed: each drop's own is checked (bounce_fit.cpp)
  }
}

}  // namespace hertzdash

namespace hertzdash::bounce_fit_detail {

BounceModel::BounceModel(RunOptions base, const PaperParameters& paper, std::vector<std::string> names)
    : FitModel(std::move(base), paper, std::move(names)) {
  base_.follows_flights = true;  // run_bounce_sequence's flights read the air drag
}

const std::vector<ModelImpact>* BounceModel::impacts(const std::vector<double>& law, double v0, int count) {
  std::vector<double> key = law;
  key.push_back(v0);
  key.push_back(count);
  if (auto it = cache_.find(key); it != cache_.end()) {
    if (!it->second) outside_domain_ = outside_[key];
    return it->second ? &*it->second : nullptr;
  }
  if (cache_.size() > 4096) cache_.clear(), outside_.clear();
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
    } else {
      outside_domain_ = fmt::format("from {:.6g} m/s the model's bounce sequence has {} of the {} impacts ({})", v0,
                                    b.impacts.size(), count, b.end_reason);
    }
  } catch (const InvalidParameter& e) {
    outside_domain_ = e.message(KeySpelling::key);
  } catch (const std::runtime_error& e) {  // a run that failed its checks: outside the model's domain
    outside_domain_ = e.what();
  }
  if (!value) outside_[key] = outside_domain_;
  auto it = cache_.emplace(std::move(key), std::move(value)).first;
  return it->second ? &*it->second : nullptr;
}

}  // namespace hertzdash::bounce_fit_detail
