#include "hertzdash/simulation/fit/virtual_measurement.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/options/run_options.hpp"

#include <fmt/format.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace hertzdash {

namespace {

constexpr int oversampling = 16;  // the filter's grid per sampling interval

// Second-order Butterworth low-pass by the bilinear transform (cut-off pre-warped) at step h.
class ButterworthLowPass {
 public:
  ButterworthLowPass(double cutoff_Hz, double h_s, double initial) {
    const double k = std::tan(std::numbers::pi * cutoff_Hz * h_s), q = std::numbers::sqrt2;
    const double n = 1.0 / (1.0 + q * k + k * k);
    b0_ = k * k * n;
    a1_ = 2.0 * (k * k - 1.0) * n;
    a2_ = (1.0 - q * k + k * k) * n;
    x1_ = x2_ = y1_ = y2_ = initial;  // at rest: the steady state of a constant input
  }
  double operator()(double x) {
    const double y = b0_ * (x + 2.0 * x1_ + x2_) - a1_ * y1_ - a2_ * y2_;
    x2_ = x1_;
    x1_ = x;
    y2_ = y1_;
    y1_ = y;
    return y;
  }

 private:
  double b0_, a1_, a2_, x1_, x2_, y1_, y2_;
};

}  // namespace

std::vector<std::string> parse_channels(const std::string& list, const char* option) {
  const auto& known = measured_quantity_columns();
  std::vector<std::string> out;
  for (const std::string& name : split_option_list(list)) {
    if (std::find(known.begin(), known.end(), name) == known.end() || std::count(out.begin(), out.end(), name))
      throw InvalidParameter(option, list, "a comma-separated list of distinct channels from: force_N, accel_mps2, "
                                           "velocity_mps, displacement_m");
    out.push_back(name);
  }
  return out;
}

void validate(const MeasurementChain& c) {
  require_positive("sample-rate", c.sample_rate_Hz, "Hz");
  if (c.anti_alias_cutoff_Hz != 0 && !(c.anti_alias_cutoff_Hz > 0 && c.anti_alias_cutoff_Hz <= c.sample_rate_Hz / 2))
    throw InvalidParameter("anti-alias", format_value(c.anti_alias_cutoff_Hz),
                           fmt::format("0 (no filter) or a cut-off in (0, {}] Hz, half the sampling rate", c.sample_rate_Hz / 2));
  if (!(c.noise_fraction >= 0 && c.noise_fraction <= 1))
    throw InvalidParameter("noise", format_value(c.noise_fraction),
                           "in [0, 1], a fraction of each channel's largest magnitude");
  if (c.channels.empty()) throw InvalidParameter("channels", "", "at least one channel");
  require_positive("window margin", c.window_margin, "contact times");
}

MeasuredTrace record_virtual_measurement(const ImpactHistory& history, const MeasurementChain& chain) {
  validate(chain);
  const double tc = history.contact_time_s(), dt = 1.0 / chain.sample_rate_Hz;
  const double t_first = -chain.window_margin * tc, t_last = (1.0 + chain.window_margin) * tc;
  const double count = std::floor((t_last - t_first) / dt) + 1;
  if (!(count <= max_virtual_samples))
    throw InvalidParameter("sample-rate", format_value(chain.sample_rate_Hz),
                           fmt::format("at most {:.4g} Hz: {:g} samples over this contact's window of {:.4g} s",
                                       max_virtual_samples / (t_last - t_first), max_virtual_samples, t_last - t_first));
  const auto samples = static_cast<std::size_t>(count);
  MeasuredTrace m;
  m.synthetic = true;
  for (std::size_t i = 0; i < samples; ++i) m.t_s.push_back(t_first + static_cast<double>(i) * dt);

  const std::unique_ptr<gsl_rng, decltype(&gsl_rng_free)> rng(gsl_rng_alloc(gsl_rng_mt19937), &gsl_rng_free);
  if (!rng) throw std::bad_alloc();
  gsl_rng_set(rng.get(), static_cast<unsigned long>(chain.seed));

  for (const std::string& channel : measured_quantity_columns()) {
    if (std::find(chain.channels.begin(), chain.channels.end(), channel) == chain.channels.end()) continue;
    std::vector<double>& out = *quantity(m, channel);
    auto signal = [&](double tau) { return instrument_channel(history.instruments_at(tau), channel); };
    if (chain.anti_alias_cutoff_Hz > 0) {
      // The filter runs on a grid `oversampling` times finer than the sampling, from rest at the
      // signal's value 10 / (2 pi f_c) before the window.
      const double h = dt / oversampling, settle = 10.0 / (2.0 * std::numbers::pi * chain.anti_alias_cutoff_Hz);
      const auto lead = static_cast<long>(std::ceil(settle / h));
      const auto last = static_cast<long>(samples - 1) * oversampling;
      ButterworthLowPass filter(chain.anti_alias_cutoff_Hz, h, signal(t_first - static_cast<double>(lead) * h));
      for (long k = -lead; k <= last; ++k) {
        const double y = filter(signal(t_first + static_cast<double>(k) * h));
        if (k >= 0 && k % oversampling == 0) out.push_back(y);
      }
    } else {
      for (double tau : m.t_s) out.push_back(signal(tau));
    }
    double largest = 0;
    for (double v : out) largest = std::max(largest, std::abs(v));
    const double sigma = chain.noise_fraction * largest;
    if (sigma > 0)
      for (double& v : out) v += gsl_ran_gaussian(rng.get(), sigma);
  }
  return m;
}

}  // namespace hertzdash
