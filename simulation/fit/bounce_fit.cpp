// A bounce recording as a kind of data for the fit engine (simulation/fit/bounce_fit.hpp): its
// usable impact times, each drop's first impact speed and clock offset as nuisances, the
// residuals of the model's onsets (bounce_fit_model.hpp), its folds (the drops); the fit, its
// intervals, cross-validation and every law compared are the engine's.
#include "hertzdash/simulation/fit/bounce_fit.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/fit/bounce_fit_model.hpp"
#include "hertzdash/simulation/fit/fit_parameters.hpp"
#include "hertzdash/simulation/fit/restitution_fit_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace hertzdash {

using namespace bounce_fit_detail;
using namespace fit_detail;

namespace {

// S_g(r) = 1 + r + ... + r^{g-1}.
double span(int g, double r) {
  double s = 0, q = 1;
  for (int k = 0; k < g; ++k) s += q, q *= r;
  return s;
}

// Where a drop's first speed comes from without a height, with a hint where the interval is
// longer than any bounce's (times in ms written in the column of seconds).
std::string first_interval_words(double interval_s) {
  return fmt::format("from its first interval, {:.6g} s{}", interval_s,
                     interval_s > 10 ? "; an interval that long is times in ms in the column impact_time_s? name it "
                                       "impact_time_ms"
                                     : "");
}

RunOptions flying(RunOptions o) {
  o.follows_flights = true;  // the model's flights read the air drag
  return o;
}

class RecordingData final : public FitData {
 public:
  // `nuisances`: each drop's v0 and t0 to start from; empty: from the data (bounce_fit.hpp, "Parameters").
  RecordingData(CheckedRecording data, std::string path, const RunOptions& base, const PaperParameters& paper,
                std::vector<std::string> names, std::vector<double> nuisances = {})
      : data_(std::move(data)), path_(std::move(path)), base_(base), paper_(&paper), names_(names),
        model_(base, paper, std::move(names)), start_(std::move(nuisances)) {
    std::vector<double> ratios;
    for (const CheckedDrop& d : data_.drops) {
      for (std::size_t k = 0; k < d.impact_time_s.size(); ++k) rows_.push_back({static_cast<std::size_t>(&d - data_.drops.data()), k});
      if (d.interval_ratio > 0 && d.interval_ratio < 1) ratios.push_back(d.interval_ratio);
    }
    ratio_ = std::clamp(ratios.empty() ? 0.8 : median(ratios), 0.01, 0.99);
    if (!start_.empty()) return;
    const double g = base_.gravity_mps2.value_or(paper.gravity_mps2);
    for (const CheckedDrop& d : data_.drops) {
      const double r = d.interval_ratio > 0 && d.interval_ratio < 1 ? d.interval_ratio : ratio_;
      const bool height = d.drop_height_m > 0;
      const double v0 = height ? std::sqrt(2.0 * g * d.drop_height_m)
                               : g * (d.impact_time_s[1] - d.impact_time_s[0]) / (2.0 * r * span(d.impact_number[1], r));
      // The set-up at the drop's own speed: a speed outside the Hertz contact is the drop's, named
      // with where it comes from, unless an option the user gave sets the bound (hertz_scale_refusal.hpp).
      RunOptions o = base_;
      o.impact_velocity_mps = v0;
      o.impact_velocity_origin =
          fmt::format("the first impact speed of drop '{}' of {} ({})", d.label, path_,
                      height ? fmt::format("from its drop_height_m {:g}", d.drop_height_m)
                             : first_interval_words(d.impact_time_s[1] - d.impact_time_s[0]));
      resolve_setup(o, paper);
      start_.insert(start_.end(), {v0, d.impact_time_s[0]});
    }
  }

  std::size_t rows() const override { return rows_.size(); }
  FitPoint row(std::size_t i) const override {
    const auto [d, k] = rows_[i];
    const CheckedDrop& drop = data_.drops[d];
    return {d, drop.index[k], drop.impact_number[k], NAN, drop.impact_time_s[k], 0, 0, sd_known() ? data_.timing_sd_s : 1.0};
  }
  std::vector<std::string> groups() const override {
    std::vector<std::string> labels;
    for (const CheckedDrop& d : data_.drops) labels.push_back(d.label);
    return labels;
  }
  std::vector<Nuisance> nuisances() const override {
    std::vector<Nuisance> u;
    for (std::size_t d = 0; d < data_.drops.size(); ++d) {
      u.push_back({"first_impact_speed_mps", start_[2 * d], true, 1, d});
      u.push_back({"clock_offset_s", start_[2 * d + 1], false, 1, d});
    }
    return u;
  }
  std::vector<double> start(const std::vector<FitParameter>& parameters) override {
    std::vector<double> speeds;
    for (std::size_t d = 0; d < data_.drops.size(); ++d) speeds.push_back(start_[2 * d]);
    std::vector<double> v = law_starting_values(base_, *paper_, parameters, ratio_, median(speeds));
    (void)restitution_fit_detail::restitution_contact(model_.options_at(v), *paper_, speeds.front());
    return v;
  }
  bool residuals(const std::vector<double>& law, const std::vector<double>& nuisances, double* r) override {
    const double unit = sd_known() ? data_.timing_sd_s : 1.0;
    for (std::size_t d = 0, row = 0; d < data_.drops.size(); ++d) {
      const CheckedDrop& drop = data_.drops[d];
      const auto* m = model_.impacts(law, nuisances[2 * d], drop.impact_number.back() + 1);
      if (!m) {
        outside_ = fmt::format("drop '{}' of {}: {}", drop.label, path_, model_.outside_domain());
        return false;
      }
      for (std::size_t k = 0; k < drop.impact_time_s.size(); ++k, ++row)
        r[row] = (drop.impact_time_s[k] - (nuisances[2 * d + 1] + (*m)[static_cast<std::size_t>(drop.impact_number[k])].onset_s)) /
                 unit;
    }
    return true;
  }
  std::string outside_domain() const override { return outside_; }
  // The dense least squares over every drop's two nuisances costs about 0.024 n P^2 units per fit
  // (n times, P = p + 2 drops; GSL's QR and the covariance's SVD), and the model runs about
  // (3 + 2 p) per drop and iteration, each about 10 units an impact, over about 10 iterations
  // (measured: 100 and 200 drops of 8 times, p = 1: 1.07 s and 6.3 s).
  FitWork predicted_work(std::size_t p) const override {
    const double n = static_cast<double>(rows()), P = static_cast<double>(p + 2 * data_.drops.size());
    return {0.024 * n * P * P + 10.0 * (3.0 + 2.0 * static_cast<double>(p)) * n * 10.0,
            fmt::format("{}: {} drops, {} times, {} parameters (the law's {} and two per drop)", path_,
                        data_.drops.size(), rows(), p + 2 * data_.drops.size(), p)};
  }
  bool sd_known() const override { return data_.timing_sd_s > 0; }
  double least_variance() const override { return 1e-10 * 1e-10; }  // the model's accuracy in time [s^2]
  std::string too_few(std::size_t n, std::size_t p) const override {
    return fmt::format("{}: {} usable impact times cannot determine {} parameters (the law's {} and two per drop)",
                       path_, n, p, p - 2 * data_.drops.size());
  }
  std::size_t folds() const override {
    if (data_.drops.size() < 2)
      throw DataError(fmt::format("{}: cross-validation leaves out each drop in turn and needs at least two usable "
                                  "drops (the recording has {})",
                                  path_, data_.drops.size()));
    return data_.drops.size();
  }
  std::string fold_name(std::size_t k) const override { return fmt::format("drop '{}'", data_.drops[k].label); }
  std::unique_ptr<FitData> part(std::size_t k, bool held, const std::vector<double>& nuisances) const override {
    CheckedRecording part;
    part.timing_sd_s = data_.timing_sd_s;
    std::vector<double> start;
    for (std::size_t d = 0; d < data_.drops.size(); ++d)
      if ((d == k) == held) {
        part.drops.push_back(data_.drops[d]);
        start.insert(start.end(), {nuisances[2 * d], nuisances[2 * d + 1]});
      }
    return std::make_unique<RecordingData>(std::move(part), path_, base_, *paper_, names_, std::move(start));
  }
  void finish(FitResult& fit, const std::vector<double>& law, const std::vector<double>& nuisances) override {
    estimate_nuisances_ = nuisances;
    for (std::size_t i = 0; i < rows(); ++i)
      if (const ModelImpact* mi = model_impact(law, i)) fit.points[i].x = mi->approach_mps;
    fit.model_runs = model_.runs();
    fit.integrator_used = model_.integrator_used();
    fit.model_solver = restitution_fit_detail::restitution_model_solver();
    fit.fitted_options = model_.options_at(law);
  }
  std::vector<ImpactRestitution> restitution_at(const std::vector<double>& law) override {
    std::vector<ImpactRestitution> at;
    for (std::size_t i = 0; i < rows(); ++i)
      if (const ModelImpact* mi = model_impact(law, i); mi && mi->rebound_mps > 0)
        at.push_back({i, mi->approach_mps, mi->rebound_mps / mi->approach_mps});
    return at;
  }

 private:
  // The model's impact of row i at the law's values and the estimate's nuisances; nullptr outside its domain.
  const ModelImpact* model_impact(const std::vector<double>& law, std::size_t i) {
    const auto [d, k] = rows_[i];
    const CheckedDrop& drop = data_.drops[d];
    const auto* m = model_.impacts(law, estimate_nuisances_[2 * d], drop.impact_number.back() + 1);
    return m ? &(*m)[static_cast<std::size_t>(drop.impact_number[k])] : nullptr;
  }

  CheckedRecording data_;
  std::string path_;
  RunOptions base_;
  const PaperParameters* paper_;
  std::vector<std::string> names_;
  BounceModel model_;
  std::vector<double> start_;  // v0 and t0 of each drop
  std::vector<std::pair<std::size_t, std::size_t>> rows_;  // drop, time in it
  double ratio_ = 0.8;         // the drops' median interval ratio
  std::string outside_;        // the drop and the model's reason, the last time it could not run
  std::vector<double> estimate_nuisances_;  // finish()'s
};

std::vector<std::string> names_of(const std::vector<FitParameter>& parameters) {
  std::vector<std::string> names;
  for (const FitParameter& p : parameters) names.push_back(p.option);
  return names;
}

// The options checked and flying, the settings with the law's own parameters where none are given.
std::pair<RunOptions, FitSettings> prepared(const RunOptions& given, const PaperParameters& paper,
                                                  FitSettings settings) {
  check_bounce_fit_setup(given, paper);
  const RunOptions base = flying(given);
  for (const FitParameter& p : settings.parameters)
    if (p.option == "height" || p.option == "impact-velocity")
      throw InvalidParameter("fit", p.option,
                             "names of the law's parameters or the set-up's, not `height` or `impact-velocity` with "
                             "`bounce-times` (each drop's first impact speed is fitted already, from its "
                             "`drop_height_m` where the recording gives it)");
  if (settings.parameters.empty()) settings.parameters = law_fit_parameters(base);
  if (settings.parameters.empty())
    throw InvalidParameter("damping", base.damping,
                           "a law with a parameter to fit for `bounce-times` (this one reads neither `restitution` nor a "
                           "time constant: its e is fixed), or parameters given with `fit`");
  return {base, settings};
}

}  // namespace

FitResult fit_bounce_recording(const CheckedRecording& data, const std::string& path, const RunOptions& given,
                               const PaperParameters& paper, const FitSettings& settings) {
  const auto [base, own] = prepared(given, paper, settings);
  RecordingData d(data, path, base, paper, names_of(own.parameters));
  return fit(d, base.damping, own);
}

LawComparison compare_laws_on_bounces(const CheckedRecording& data, const std::string& path,
                                            const RunOptions& base, const PaperParameters& paper,
                                            const FitSettings& settings) {
  check_bounce_fit_setup(base, paper);
  return compare_laws(
      [&](const RunOptions& o, const std::vector<FitParameter>& parameters) {
        return std::make_unique<RecordingData>(data, path, o, paper, names_of(parameters));
      },
      flying(base), settings);
}

}  // namespace hertzdash
