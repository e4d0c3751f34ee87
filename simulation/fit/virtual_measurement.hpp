#pragma once
// A virtual experiment: the model's drop test recorded as the paper's instruments would record
// it, in the measured-trace format (data/measurements/README.md), labelled synthetic. The
// instruments read the continuous signals of ImpactHistory::instruments_at (load cell force,
// accelerometer, rod velocity and displacement since onset); each channel then passes
//   1. an anti-alias filter: a second-order Butterworth low-pass, -3 dB at the cut-off f_c
//      (its group delay at low frequency is sqrt(2) / (2 pi f_c), which the fit's onset time
//      absorbs), run on a grid 16 times finer than the sampling and started from rest well
//      before the window;
//   2. sampling at the rate f_s (at most max_virtual_samples samples) over the window [-margin t_c, (1 + margin) t_c] around the contact;
//   3. additive white Gaussian noise of standard deviation noise_fraction * max |channel| over
//      the window (GSL's mt19937 and gsl_ran_gaussian, seeded: the same seed gives the same file).
// Nothing here is a measurement: the trace says `synthetic: true` and names what made it.
#include "hertzdash/io/measured_trace.hpp"
#include "hertzdash/simulation/run/impact_history.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace hertzdash {

/// The instruments' chain: constant for one virtual experiment.
struct MeasurementChain {
  double sample_rate_Hz = 1e6;        ///< f_s [Hz] > 0
  double anti_alias_cutoff_Hz = 0;    ///< f_c [Hz] in (0, f_s / 2], or 0 for no filter
  double noise_fraction = 0;          ///< noise sigma over the channel's largest magnitude, in [0, 1]
  std::uint64_t seed = 1;             ///< of the noise
  double window_margin = 0.1;         ///< the window's margin either side of the contact, in contact times
  std::vector<std::string> channels{"force_N", "accel_mps2", "displacement_m"};  ///< of measured_quantity_columns()
};

/// Most samples of one virtual measurement (a CSV file of about 1 GB).
inline constexpr double max_virtual_samples = 1e7;

/// Throws InvalidParameter naming the option (--sample-rate, --anti-alias, --noise, --channels) and its range.
void validate(const MeasurementChain& chain);

/// The samples of `history` through `chain` (time since contact onset; `source`, `rod` and
/// `height_m` are left for the caller; `synthetic` is true).
MeasuredTrace record_virtual_measurement(const ImpactHistory& history, const MeasurementChain& chain);

/// The channels named in a comma-separated list (measured_quantity_columns()); throws InvalidParameter(option, ...).
std::vector<std::string> parse_channels(const std::string& list, const char* option);

}  // namespace hertzdash
