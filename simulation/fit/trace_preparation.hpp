#pragma once
// Internal to the trace fit (simulation/fit/trace_fit.cpp; not installed, cmake/install.cmake): the
// measured trace as the fit uses it: resampled if asked, checked (a channel to fit, no outlier,
// a sampling fine enough for the model's contact and not absurdly finer, a contact above the
// noise, enough samples), and each
// channel's noise sigma_c estimated from the data (simulation/fit/trace_fit.hpp, "Residuals").
#include "hertzdash/io/measured_trace.hpp"
#include "hertzdash/simulation/fit/trace_fit.hpp"

#include <string>
#include <vector>

namespace hertzdash::trace_fit_detail {

/// A channel to fit and its noise sigma_c [the channel's unit].
struct PreparedChannel {
  std::string name;
  double noise_sigma = 0;
};

/// The trace as fitted, and its channels with their noise.
struct PreparedTrace {
  MeasuredTrace trace;
  std::vector<PreparedChannel> channels;
};

/// Resample if asked, and check the trace: a channel to fit, no outlier (outlier_ratio, in the
/// trace as read, so the message's sample number is the file's), a sampling interval that
/// resolves the model's contact at the starting values (`contact_time_s`:
/// min_samples_per_contact samples; the message says the least rate) and is no finer than
/// max_samples_per_contact, a contact the noise does not hide, enough samples. Throws
/// DataError naming the file (InvalidParameter for a resampling rate that is not below the trace's).
PreparedTrace prepare_trace(const MeasuredTrace& trace, const TraceFitSettings& settings, double contact_time_s,
                            double g);

}  // namespace hertzdash::trace_fit_detail
