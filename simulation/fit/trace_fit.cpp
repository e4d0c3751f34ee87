// A measured trace as a kind of data for the fit engine (simulation/fit/trace_fit.hpp): the
// prepared trace (trace_preparation.hpp), its observations weighted by their channel's noise,
// the onset time as a nuisance (with its starting guess), the residuals of the model
// (trace_fit_model.hpp), the work bound, and interleaved folds; the fit, its intervals,
// cross-validation and every law compared are the engine's.
#include "hertzdash/simulation/fit/trace_fit.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/fit/fit_parameters.hpp"
#include "hertzdash/simulation/fit/trace_fit_model.hpp"
#include "hertzdash/simulation/fit/trace_preparation.hpp"
#include "hertzdash/simulation/run/impact_history.hpp"

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <optional>

namespace hertzdash {

using namespace trace_fit_detail;

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// Where the contact starts to show: the first time the force exceeds, or the acceleration falls
// below g by, ten noise levels. Empty without such a channel or crossing.
std::optional<double> first_departure(const std::vector<std::string>& names, const std::vector<double>& sigma, double g,
                                      const std::function<double(std::size_t, std::size_t)>& value, std::size_t count,
                                      const std::function<double(std::size_t)>& time) {
  for (std::size_t i = 0; i < count; ++i)
    for (std::size_t c = 0; c < names.size(); ++c) {
      const double v = value(c, i);
      if ((names[c] == "force_N" && v > 10 * sigma[c]) || (names[c] == "accel_mps2" && g - v > 10 * sigma[c]))
        return time(i);
    }
  return std::nullopt;
}

// The onset on the trace's clock that makes the model's departure coincide with the trace's
// (0 when either has none).
double onset_guess_s(const MeasuredTrace& trace, const std::vector<PreparedChannel>& channels, const ImpactHistory& model,
                     double g, double dt_s) {
  std::vector<std::string> names;
  std::vector<double> sigma;
  for (const PreparedChannel& c : channels) names.push_back(c.name), sigma.push_back(c.noise_sigma);
  const auto in_trace = first_departure(
      names, sigma, g,
      [&](std::size_t c, std::size_t i) {
        const double v = (*quantity(trace, names[c]))[i];
        return std::isfinite(v) ? v : (names[c] == "accel_mps2" ? g : 0.0);
      },
      trace.t_s.size(), [&](std::size_t i) { return trace.t_s[i]; });
  const auto steps = static_cast<std::size_t>(model.contact_time_s() / dt_s) + 1;
  const auto in_model = first_departure(
      names, sigma, g,
      [&](std::size_t c, std::size_t i) {
        return instrument_channel(model.instruments_at(static_cast<double>(i) * dt_s), names[c]);
      },
      steps, [&](std::size_t i) { return static_cast<double>(i) * dt_s; });
  return in_trace && in_model ? *in_trace - *in_model : 0.0;
}

// One sample of one channel, with its channel's noise sigma_c and weight 1 / sigma_c.
struct Observation {
  std::size_t channel, sample;  // the sample's row in the (prepared) trace
  double t_s, y, sigma, inv_sigma;
};

// What a trace's data and its folds share.
struct TraceSetup {
  RunOptions base;
  const PaperParameters* paper;
  std::vector<std::string> names;
  int steps_per_contact;
  std::string path;
  std::vector<PreparedChannel> channels;
  std::vector<double> initial;  // the law's starting values
};

class TraceData final : public FitData {
 public:
  TraceData(std::shared_ptr<const TraceSetup> setup, std::vector<Observation> obs, double onset_s)
      : setup_(std::move(setup)), obs_(std::move(obs)), onset_s_(onset_s),
        model_(setup_->base, *setup_->paper, setup_->names, setup_->steps_per_contact) {}

  // The trace prepared for the law and parameters of `base` and `settings`, the onset guessed,
  // the work bound checked (trace_fit.hpp).
  static std::unique_ptr<TraceData> prepare(const MeasuredTrace& trace_in, const RunOptions& base,
                                            const PaperParameters& paper, const TraceFitSettings& settings) {
    if (!(settings.steps_per_contact >= 100))
      throw InvalidParameter("steps per contact", std::to_string(settings.steps_per_contact), ">= 100");
    auto setup = std::make_shared<TraceSetup>();
    setup->base = base;
    setup->paper = &paper;
    for (const FitParameter& p : settings.parameters) setup->names.push_back(p.option);
    setup->steps_per_contact = settings.steps_per_contact;
    setup->initial = fit_detail::initial_values(base, paper, settings.parameters);
    TraceModel model(base, paper, setup->names, settings.steps_per_contact);
    const ImpactHistory* at_start = model.history(setup->initial);
    if (!at_start) throw InvalidParameter("fit", "the starting values", "values inside the model's domain");
    const double g = resolve_setup(base, paper).gravity_mps2;
    PreparedTrace prepared = prepare_trace(trace_in, settings, model.contact_time_s(), g);
    const MeasuredTrace& trace = prepared.trace;
    setup->path = trace.path.string();
    setup->channels = prepared.channels;
    std::vector<Observation> obs;
    for (std::size_t c = 0; c < setup->channels.size(); ++c) {
      const std::vector<double>& y = *quantity(trace, setup->channels[c].name);
      const double sigma = setup->channels[c].noise_sigma;
      for (std::size_t i = 0; i < y.size(); ++i)
        if (std::isfinite(y[i])) obs.push_back({c, i, trace.t_s[i], y[i], sigma, 1.0 / sigma});
    }
    // The onset that fits best at the starting values: first where the trace's contact departs
    // from free fall minus where the model's does (onset_guess_s), then a scan over +-0.3 t_H
    // (in the onset's variable t0 / t_H).
    const double t_H = model.time_scale_s();
    const double guess = onset_guess_s(trace, setup->channels, *at_start, g, model.solver().dt_s) / t_H;
    auto data = std::make_unique<TraceData>(setup, std::move(obs), guess * t_H);
    const std::size_t n = data->rows(), p = settings.parameters.size() + 1;
    if (n <= p) return data;  // the engine says so
    std::vector<double> r(n);
    double best = inf;
    for (int k = -30; k <= 30; ++k) {
      const double z = guess + 0.01 * k;
      if (!data->residuals(setup->initial, {z * t_H}, r.data())) continue;
      double chi2 = 0;
      for (double v : r) chi2 += v * v;
      if (chi2 < best) best = chi2, data->onset_z_ = z;
    }
    // The work bound (trace_fit.hpp, "Work"): refused before iterating if the first iterations
    // alone would exceed it, each model run costing what the one at the starting values did.
    const double run_cost = static_cast<double>(model.summary().work.steps) + static_cast<double>(n);
    if (const double predicted = min_predicted_iterations * static_cast<double>(2 * p + 2) * run_cost;
        predicted > settings.max_work)
      throw DataError(fmt::format("{}: the fit would exceed its work limit: a model run costs {:.3g} ({} RK4 steps and "
                                  "{} observations), {:g} iterations of {} runs {:.3g}, above {:.3g}; average the "
                                  "trace (--resample) or fit fewer channels (--channels)",
                                  setup->path, run_cost, model.summary().work.steps, n, min_predicted_iterations,
                                  2 * p + 2, predicted, settings.max_work));
    return data;
  }

  std::size_t rows() const override { return obs_.size(); }
  FitPoint row(std::size_t i) const override {
    const Observation& o = obs_[i];
    return {o.channel, o.sample, 0, o.t_s, o.y, 0, 0, o.sigma};
  }
  std::vector<std::string> groups() const override {
    std::vector<std::string> names;
    for (const PreparedChannel& c : setup_->channels) names.push_back(c.name);
    return names;
  }
  std::vector<Nuisance> nuisances() const override {
    return {{"onset-time", onset_s_, false, model_.time_scale_s(), std::nullopt, onset_z_}};
  }
  std::vector<double> start(const std::vector<FitParameter>&) override { return setup_->initial; }
  bool residuals(const std::vector<double>& law, const std::vector<double>& nuisances, double* r) override {
    const ImpactHistory* h = model_.history(law);
    if (!h) return false;
    ++evaluations_;
    for (std::size_t i = 0; i < obs_.size(); ++i) {
      const Observation& o = obs_[i];
      r[i] = (o.y - instrument_channel(h->instruments_at(o.t_s - nuisances[0]), setup_->channels[o.channel].name)) *
             o.inv_sigma;
    }
    return true;
  }
  bool sd_known() const override { return true; }
  bool mixed_units() const override { return true; }  // channels in N, m/s^2, m
  double work() const override { return model_.steps() + evaluations_ * static_cast<double>(rows()); }
  std::string too_few(std::size_t n, std::size_t p) const override {
    return fmt::format("{}: {} values cannot determine {} parameters", setup_->path, n, p);
  }
  std::size_t folds() const override { return trace_folds; }
  std::string fold_name(std::size_t k) const override {
    return fmt::format("the samples i with i mod {} = {}", trace_folds, k);
  }
  std::unique_ptr<FitData> part(std::size_t k, bool held, const std::vector<double>& nuisances) const override {
    std::vector<Observation> obs;
    for (const Observation& o : obs_)
      if ((o.sample % trace_folds == k) == held) obs.push_back(o);
    return std::make_unique<TraceData>(setup_, std::move(obs), nuisances[0]);
  }
  void finish(FitResult& fit, const std::vector<double>& law, const std::vector<double>& nuisances) override {
    std::vector<double> r(rows());
    residuals(law, nuisances, r.data());  // the model at the estimate (its impact's diagnostics)
    fit.model_impact = model_.summary();
    fit.model_runs = model_.runs();
    fit.model_solver = model_.solver();
    fit.integrator_used = to_string(model_.solver().integrator);
    fit.fitted_options = model_.options_at(law);
  }
  std::vector<ImpactRestitution> restitution_at(const std::vector<double>& law) override {
    if (!model_.history(law) || !(model_.summary().rebound_velocity_mps > 0)) return {};
    return {{0, model_.summary().impact_velocity_mps, model_.summary().e_effective}};
  }

 private:
  std::shared_ptr<const TraceSetup> setup_;
  std::vector<Observation> obs_;
  double onset_s_;                    // reported as the onset's initial value
  std::optional<double> onset_z_;     // the scanned start in t0 / t_H (a part's: onset_s_ / t_H)
  TraceModel model_;
  double evaluations_ = 0;  // residuals at a point inside the domain
};

}  // namespace

FitResult fit_trace(const MeasuredTrace& trace, const RunOptions& base, const PaperParameters& paper,
                   const TraceFitSettings& settings) {
  const std::unique_ptr<TraceData> data = TraceData::prepare(trace, base, paper, settings);
  return fit(*data, base.damping, settings);
}

LawComparison compare_laws(const MeasuredTrace& trace, const RunOptions& base, const PaperParameters& paper,
                           const TraceFitSettings& settings) {
  fit_detail::initial_values(base, paper, settings.parameters);  // a bad --fit is the user's, not a law's
  return compare_laws(
      [&](const RunOptions& o, const std::vector<FitParameter>& parameters) -> std::unique_ptr<FitData> {
        TraceFitSettings own = settings;
        own.parameters = parameters;
        return TraceData::prepare(trace, o, paper, own);
      },
      base, settings);
}

}  // namespace hertzdash
