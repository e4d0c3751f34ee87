#pragma once
// The --trace file of `simulate` and `bounce`: the measured-trace format (data/measurements/README.md:
// t_s, force_N, accel_mps2, velocity_mps, displacement_m, the header lines source, rod, height_m,
// synthetic) with the model's own columns besides (x_m, xdot_mps, contact_force_N, rod_accel_mps2),
// labelled synthetic, so that `hertzdash fit --trace` reads what `simulate --trace` writes.
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/simulation/run/impact_summary.hpp"

#include <string>
#include <vector>

namespace hertzdash::cli {

/// Write `samples` atomically to `path`, time and rod displacement counted from the first sample
/// (contact onset): `source` says what made them (the file adds "SYNTHETIC"), `contents` what the
/// columns hold, `inputs` the run's description (it names the rod), `height_m` the header's drop
/// height (trace_height_m: for a run given its impact velocity, v0^2 / (2 g)).
void write_model_trace(const std::string& path, const std::vector<TraceSample>& samples, const std::string& source,
                       const std::string& contents, const Parameters& inputs, double height_m);

}  // namespace hertzdash::cli
