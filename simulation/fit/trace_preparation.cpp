// The measured trace as a trace fit uses it (simulation/fit/trace_preparation.hpp): resampling into
// bins, the checks a trace must pass before it is fitted, and each channel's noise from its
// second differences.
#include "hertzdash/simulation/fit/trace_preparation.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace hertzdash::trace_fit_detail {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// The upper median: for an even count the upper of the two middle values; NaN for no values.
// Not sample_quantile(v, 0.5) (simulation/uncertainty/sample_quantile.hpp): that averages the two middle
// values of an even count, which would change the noise levels, and so the weights and the
// estimates of every fit, and it throws for no values, where the checks here take the NaN.
double median(std::vector<double> v) {
  if (v.empty()) return NAN;
  const auto mid = v.begin() + static_cast<long>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// sigma of the channel `name` from the second differences of consecutive samples with values
// (see the header), at least the rounding of a recorder whose step is the smallest change
// between samples (q / sqrt(12)) and 1e-6 of the largest magnitude (a noise-free virtual
// experiment). A channel that never changes carries no information: DataError.
double noise_sigma(const std::vector<double>& y, const std::string& file, const std::string& name) {
  std::vector<double> d2;
  for (std::size_t i = 1; i + 1 < y.size(); ++i)
    if (std::isfinite(y[i - 1]) && std::isfinite(y[i]) && std::isfinite(y[i + 1]))
      d2.push_back(y[i + 1] - 2.0 * y[i] + y[i - 1]);
  const double m = median(d2);
  for (double& d : d2) d = std::abs(d - m);
  double largest = 0, step = inf;
  for (std::size_t i = 0; i < y.size(); ++i) {
    if (!std::isfinite(y[i])) continue;
    largest = std::max(largest, std::abs(y[i]));
    if (i > 0 && std::isfinite(y[i - 1]) && y[i] != y[i - 1]) step = std::min(step, std::abs(y[i] - y[i - 1]));
  }
  if (!std::isfinite(step))
    throw DataError(fmt::format("{}: the {} column never changes: it carries nothing to fit", file, name));
  const double mad = d2.empty() ? 0.0 : 1.4826 * median(d2) / std::sqrt(6.0);
  return std::max({mad, step / std::sqrt(12.0), 1e-6 * largest});
}

std::vector<std::string> channels_to_fit(const MeasuredTrace& trace, const TraceFitSettings& settings) {
  std::vector<std::string> out;
  for (const std::string& c : measured_quantity_columns()) {
    const bool asked = settings.channels.empty() ||
                       std::find(settings.channels.begin(), settings.channels.end(), c) != settings.channels.end();
    if (!asked) continue;
    const std::vector<double>& y = *quantity(trace, c);
    if (y.empty()) {
      if (settings.channels.empty()) continue;
      throw DataError(fmt::format("{}: no {} column to fit (--channels)", trace.path.string(), c));
    }
    if (std::none_of(y.begin(), y.end(), [](double v) { return std::isfinite(v); })) {
      if (settings.channels.empty()) continue;
      throw DataError(fmt::format("{}: the {} column has no values (--channels)", trace.path.string(), c));
    }
    out.push_back(c);
  }
  if (out.empty()) throw DataError(trace.path.string() + ": no channel to fit");
  return out;
}

MeasuredTrace resampled(const MeasuredTrace& in, double rate_Hz) {
  MeasuredTrace out = in;
  out.t_s.clear();
  const double bin = 1.0 / rate_Hz, t0 = in.t_s.front();
  std::vector<std::string> present;
  for (const std::string& c : measured_quantity_columns())
    if (!quantity(in, c)->empty()) present.push_back(c), quantity(out, c)->clear();
  std::size_t i = 0;
  while (i < in.t_s.size()) {
    const auto k = std::floor((in.t_s[i] - t0) / bin);
    std::size_t j = i;
    double t_sum = 0;
    while (j < in.t_s.size() && std::floor((in.t_s[j] - t0) / bin) == k) t_sum += in.t_s[j++];
    out.t_s.push_back(t_sum / static_cast<double>(j - i));
    for (const std::string& c : present) {
      const std::vector<double>& y = *quantity(in, c);
      double sum = 0;
      int count = 0;
      for (std::size_t r = i; r < j; ++r)
        if (std::isfinite(y[r])) sum += y[r], ++count;
      quantity(out, c)->push_back(count ? sum / count : NAN);
    }
    i = j;
  }
  return out;
}

// An isolated sample far outside its channel (a glitch, a corrupted row): its departure from
// the mean of its neighbours, |D2 y_i| / 2 inside the trace, above outlier_ratio times the
// largest magnitude among the samples not next to it (trace_fit.hpp). DataError naming it.
void refuse_outliers(const MeasuredTrace& trace, const std::string& name) {
  const std::vector<double>& y = *quantity(trace, name);
  const std::size_t n = y.size();
  auto magnitude = [&](std::size_t i) { return std::isfinite(y[i]) ? std::abs(y[i]) : 0.0; };
  std::vector<double> before(n + 1, 0.0), after(n + 1, 0.0);  // largest magnitude of y[0, i) and y[i, n)
  for (std::size_t i = 0; i < n; ++i) before[i + 1] = std::max(before[i], magnitude(i));
  for (std::size_t i = n; i-- > 0;) after[i] = std::max(after[i + 1], magnitude(i));
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(y[i])) continue;
    double sum = 0;
    int count = 0;
    if (i > 0 && std::isfinite(y[i - 1])) sum += y[i - 1], ++count;
    if (i + 1 < n && std::isfinite(y[i + 1])) sum += y[i + 1], ++count;
    if (count == 0) continue;
    const double departure = std::abs(y[i] - sum / count);
    const double elsewhere = std::max(i >= 1 ? before[i - 1] : 0.0, i + 2 <= n ? after[i + 2] : 0.0);
    if (!(departure > outlier_ratio * elsewhere)) continue;
    // The outlier's neighbour departs by half as much: name the largest of the three.
    std::size_t k = i;
    for (std::size_t j = i > 0 ? i - 1 : 0; j <= std::min(i + 1, n - 1); ++j)
      if (magnitude(j) > magnitude(k)) k = j;
    throw DataError(fmt::format("{}: sample {} (t = {:.6g} s) of {}, {:.6g}, is an outlier: it departs from its "
                                "neighbours by more than {:g} times the column's largest magnitude elsewhere ({:.3g}); "
                                "correct or remove the row",
                                trace.path.string(), k + 1, trace.t_s[k], name, y[k], outlier_ratio, elsewhere));
  }
}

double median_interval_s(const std::vector<double>& t) {
  std::vector<double> dt;
  for (std::size_t i = 1; i < t.size(); ++i) dt.push_back(t[i] - t[i - 1]);
  return median(dt);
}

}  // namespace

PreparedTrace prepare_trace(const MeasuredTrace& trace, const TraceFitSettings& settings, double contact_time_s,
                            double g) {
  const std::string file = trace.path.string();
  for (const std::string& name : channels_to_fit(trace, settings)) refuse_outliers(trace, name);
  MeasuredTrace t = trace;
  if (settings.resample_Hz != 0) {
    require_positive("resample", settings.resample_Hz, "Hz");
    const double rate = 1.0 / median_interval_s(trace.t_s);
    if (!(settings.resample_Hz < rate))
      throw InvalidParameter("resample", format_value(settings.resample_Hz),
                             fmt::format("below the trace's sampling rate, {:.6g} Hz", rate));
    t = resampled(trace, settings.resample_Hz);
  }
  const double tc = contact_time_s, dt = median_interval_s(t.t_s);
  if (!(tc / dt >= min_samples_per_contact))
    throw DataError(fmt::format("{}: sampled every {:.3g} s ({:.4g} Hz), too coarse: the model's contact lasts {:.3g} s "
                                "and needs at least {:g} samples, a sampling rate of at least {:.4g} Hz",
                                file, dt, 1.0 / dt, tc, min_samples_per_contact, min_samples_per_contact / tc));
  if (!(tc / dt <= max_samples_per_contact))
    throw DataError(fmt::format("{}: sampled every {:.3g} s, {:.3g} samples in the model's contact of {:.3g} s, more than "
                                "{:g}: finer than the model resolves (it steps t_H / 2000). Is the time column in its "
                                "unit (t_s, t_ms, t_us)? A trace sampled this fine is averaged with --resample",
                                file, dt, tc / dt, tc, max_samples_per_contact));

  // A contact must stand out of the noise by ten noise levels in some channel: the force above
  // zero, the deceleration below g, the velocity reversed (a rebound), or the displacement
  // returning from its largest value (the rod coming back up).
  PreparedTrace prepared;
  bool contact = false;
  std::string seen;
  for (const std::string& name : channels_to_fit(t, settings)) {
    const std::vector<double>& y = *quantity(t, name);
    const double sigma = noise_sigma(y, file, name);
    prepared.channels.push_back({name, sigma});
    double signature = 0, last = NAN, peak = -inf;
    for (double v : y) {
      if (!std::isfinite(v)) continue;
      if (name == "force_N") signature = std::max(signature, v);
      else if (name == "accel_mps2") signature = std::max(signature, g - v);
      else if (name == "velocity_mps") signature = std::max(signature, -v);
      else peak = std::max(peak, v), last = v;
    }
    if (name == "displacement_m") signature = peak - last;
    contact = contact || signature > 10.0 * sigma;
    seen += fmt::format("{}{} {:.3g} against a noise of {:.3g}", seen.empty() ? "" : "; ", name, signature, sigma);
  }
  if (!contact)
    throw DataError(fmt::format("{}: no contact in the trace: no channel departs from free fall by ten noise levels "
                                "(force above 0, g minus acceleration, upward velocity, displacement's return: {})",
                                file, seen));
  if (t.t_s.size() <= settings.parameters.size() + 1)
    throw DataError(fmt::format("{}: {} samples cannot determine {} parameters", file, t.t_s.size(), settings.parameters.size() + 1));
  prepared.trace = std::move(t);
  return prepared;
}

}  // namespace hertzdash::trace_fit_detail
