#pragma once
// SYNTHETIC bounce recordings for the tests (tests/test_bounce_recording_*.cpp): each drop's
// impact times are the onset times of `hertzdash bounce --impact-velocity v0` (run_bounce,
// CVODE at rtol 1e-12: another integrator than the fit's gbs8) on a clock of the drop's own,
// with Gaussian timing jitter from a seeded RNG. No measured recording ships.
#include "hertzdash/io/bounce_recording.hpp"
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <random>
#include <string>
#include <vector>

namespace hertzdash::test {

/// The truth of most tests: the paper's law at input e = 0.80, the steel rod's set-up.
inline RunOptions hongo_truth() {
  RunOptions o;
  o.restitution = 0.80;
  return o;
}

/// The sequence of `impacts` impacts of `truth` from first approach speed v0, onsets from 0.
inline BounceSequence bounce_truth(RunOptions truth, double v0, int impacts) {
  truth.impact_velocity_mps = v0;
  truth.rtol = 1e-12;
  BounceOptions b;
  b.impacts = impacts;
  b.min_rebound_velocity_mps = 0;
  return run_bounce(truth, load_paper_parameters(), b).sequence;
}

struct SyntheticDrop {
  std::string label;
  double v0_mps, clock_offset_s;
};

/// The truth's e_effective over a recording of `drops` of `impacts` impacts each: the mean of
/// rebound / approach speed over every impact of every drop, as the recording's runs made them.
inline double true_e_effective(const RunOptions& truth, const std::vector<SyntheticDrop>& drops, int impacts) {
  double sum = 0;
  int n = 0;
  for (const SyntheticDrop& d : drops)
    for (const BounceImpact& i : bounce_truth(truth, d.v0_mps, impacts).impacts)
      sum += i.rebound_speed_mps / i.approach_speed_mps, ++n;
  return sum / n;
}

/// Three drops (0.4, 0.6, 0.8 m/s; clock offsets 1.25 s, -3 s, 100.5 s) of `impacts` impacts.
inline std::vector<SyntheticDrop> three_drops() {
  return {{"a", 0.4, 1.25}, {"b", 0.6, -3.0}, {"c", 0.8, 100.5}};
}

/// A recording of `drops` of `truth`, jitter sigma_s [s] (0: none) drawn with `seed`.
inline BounceRecording synthetic_recording(const RunOptions& truth, const std::vector<SyntheticDrop>& drops,
                                           int impacts, double sigma_s = 0, unsigned seed = 0) {
  BounceRecording r;
  r.path = "synthetic.csv";
  r.source = "SYNTHETIC: written by the tests (tests/bounce_recording_synthetic.hpp), law " + truth.damping;
  r.synthetic = true;
  std::mt19937 rng(seed);
  std::normal_distribution<double> jitter(0.0, sigma_s > 0 ? sigma_s : 1.0);
  for (const SyntheticDrop& d : drops) {
    RecordedDrop rd{d.label, {}, {}, 0.0};
    for (double t : bounce_truth(truth, d.v0_mps, impacts).onset_times_s) {
      rd.impact_time_s.push_back(d.clock_offset_s + t + (sigma_s > 0 ? jitter(rng) : 0.0));
      rd.where.push_back("synthetic.csv:" + std::to_string(rd.where.size() + 1));
    }
    r.drops.push_back(rd);
  }
  return r;
}

/// Insert time `t` into drop `drop` at row `index` (a doubled or out-of-order detection).
inline void insert_time(BounceRecording& r, std::size_t drop, std::size_t index, double t) {
  RecordedDrop& d = r.drops[drop];
  d.impact_time_s.insert(d.impact_time_s.begin() + static_cast<std::ptrdiff_t>(index), t);
  d.where.insert(d.where.begin() + static_cast<std::ptrdiff_t>(index), "synthetic.csv:inserted");
}

/// Remove row `index` of drop `drop` (a missed detection).
inline void remove_time(BounceRecording& r, std::size_t drop, std::size_t index) {
  RecordedDrop& d = r.drops[drop];
  d.impact_time_s.erase(d.impact_time_s.begin() + static_cast<std::ptrdiff_t>(index));
  d.where.erase(d.where.begin() + static_cast<std::ptrdiff_t>(index));
}

}  // namespace hertzdash::test
