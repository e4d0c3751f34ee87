#pragma once
// A trace as a file or an array holds it: each time once. A run given its impact velocity records
// its onset twice (where the run begins, and as the start of its first step), and a time series
// whose time does not increase strictly is refused by the trace reader (io/measured_trace.hpp).
#include "hertzdash/simulation/run/impact_summary.hpp"

#include <vector>

namespace hertzdash {

/// The samples of `trace` whose time exceeds the previous sample's kept (the first of equal times).
inline std::vector<TraceSample> distinct_time_samples(const std::vector<TraceSample>& trace) {
  std::vector<TraceSample> out;
  out.reserve(trace.size());
  for (const TraceSample& s : trace)
    if (out.empty() || s.t_s > out.back().t_s) out.push_back(s);
  return out;
}

}  // namespace hertzdash
