// The dirty-data check of a bounce recording (simulation/fit/bounce_recording_check.hpp):
// monotonic times, then doubled and missed detections by the local interval ratios, then drops
// of too few times.
#include "hertzdash/simulation/fit/bounce_recording_check.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/simulation/run/bounce_sequence.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

namespace hertzdash {

namespace {

// One usable time: its value, its impact number, its index in the drop's rows.
struct Time {
  double t;
  int number;
  std::size_t row;
};

// The longest strictly increasing subsequence of t, the earliest rows where several are equally
// long: L[i] the longest starting at i, then from the left the first row that continues one of
// the longest. O(m^2), m <= max_bounces.
std::vector<std::size_t> longest_increasing(const std::vector<double>& t) {
  const std::size_t m = t.size();
  std::vector<std::size_t> L(m, 1);
  for (std::size_t i = m; i-- > 0;)
    for (std::size_t j = i + 1; j < m; ++j)
      if (t[j] > t[i]) L[i] = std::max(L[i], L[j] + 1);
  std::vector<std::size_t> keep;
  std::size_t want = *std::max_element(L.begin(), L.end());
  for (std::size_t i = 0; i < m && want > 0; ++i)
    if (L[i] == want && (keep.empty() || t[i] > t[keep.back()])) keep.push_back(i), --want;
  return keep;
}

// S_g(r) = 1 + r + ... + r^{g-1}: a span of g flights in units of its first.
double span(int g, double r) {
  double s = 0, p = 1;
  for (int k = 0; k < g; ++k) s += p, p *= r;
  return s;
}

// The local ratio at each interior time (see the header), with r = `r` for the spans.
std::vector<double> local_ratios(const std::vector<Time>& s, double r) {
  std::vector<double> l;
  for (std::size_t i = 1; i + 1 < s.size(); ++i) {
    const double sa = (s[i].t - s[i - 1].t) / span(s[i].number - s[i - 1].number, r);
    const double sb = (s[i + 1].t - s[i].t) / span(s[i + 1].number - s[i].number, r);
    l.push_back(std::pow(sb / sa, 1.0 / (s[i].number - s[i - 1].number)));
  }
  return l;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// The drop's interval ratio: the median of its local ratios, spans taken at the median of the
// plain interval ratios first (gaps change them little: S_g enters only where there are gaps).
double interval_ratio(const std::vector<Time>& s) {
  std::vector<double> plain;
  for (std::size_t i = 1; i + 1 < s.size(); ++i) plain.push_back((s[i + 1].t - s[i].t) / (s[i].t - s[i - 1].t));
  double r = median(plain);
  if (!(r > 0 && r < 1)) return r;
  return median(local_ratios(s, r));
}

struct Score {
  std::size_t above = 0;  // interior times whose deviation exceeds the threshold
  double largest = 0, sum_squares = 0;
};

Score score(const std::vector<Time>& s, double r, double threshold) {
  Score sc;
  for (double l : local_ratios(s, r)) {
    const double d = std::abs(std::log(l / r));
    sc.above += d > threshold;
    sc.largest = std::max(sc.largest, std::isfinite(d) ? d : std::numeric_limits<double>::infinity());
    sc.sum_squares += d * d;
  }
  return sc;
}

struct Repair {
  bool missed;        // else: leave out a doubled detection
  std::size_t where;  // missed: the interval's end (position in the sequence); doubled: the time's position
};

// The sequence after a repair: a missed impact renumbers every later time one up; a time left
// out was counted as an impact, so every later one goes one down (and the first stays 0).
std::vector<Time> repaired(std::vector<Time> s, const Repair& r) {
  if (r.missed) {
    for (std::size_t i = r.where; i < s.size(); ++i) ++s[i].number;
    return s;
  }
  for (std::size_t i = r.where + 1; i < s.size(); ++i) --s[i].number;
  s.erase(s.begin() + static_cast<std::ptrdiff_t>(r.where));
  const int first = s.empty() ? 0 : s.front().number;
  for (Time& t : s) t.number -= first;
  return s;
}

// Doubled and missed detections (the header's step 2), flags appended to `flagged`.
void repair_glitches(const RecordedDrop& d, std::vector<Time>& s, std::vector<BounceFlag>& flagged,
                     std::vector<std::string>& notes) {
  const std::size_t budget = std::max<std::size_t>(1, s.size() / 4);
  for (std::size_t repairs = 0; repairs < budget; ++repairs) {
    const double r = interval_ratio(s);
    if (!(r > 0 && r < 1)) {
      notes.push_back(fmt::format("drop '{}': its intervals do not shrink (median interval ratio {:.3g}): not checked "
                                  "for doubled or missed detections",
                                  d.label, r));
      return;
    }
    const double threshold = 0.5 * std::log1p(r);
    const Score now = score(s, r, threshold);
    if (now.above == 0) return;
    // Candidates: a missed impact in each interval, each time left out; ranked by the deviations
    // left above the threshold, then a missed impact before a time left out (keep the data
    // where both explain it), then the sum of squared deviations.
    std::optional<Repair> best;
    Score best_score;
    auto key = [](const Score& sc, const Repair& c) { return std::tuple(sc.above, !c.missed, sc.sum_squares); };
    for (std::size_t k = 1; k < 2 * s.size(); ++k) {
      const Repair c = k < s.size() ? Repair{true, k} : Repair{false, k - s.size()};
      const std::vector<Time> t = repaired(s, c);
      if (t.size() < min_bounce_times) continue;
      const Score sc = score(t, r, threshold);
      if (!best || key(sc, c) < key(best_score, *best)) best = c, best_score = sc;
    }
    if (!best || !(best_score.above < now.above || (best_score.above == now.above && best_score.largest < now.largest)))
      break;
    const std::size_t p = best->where, row = s[p].row;
    if (best->missed)
      flagged.push_back({d.label, row, "missed",
                         fmt::format("{}: the interval of {:.6g} s before this impact is too long for the drop's "
                                     "interval ratio r = {:.4g} (deviation up to a factor {:.3g}, threshold {:.3g}); "
                                     "with one impact not detected in it (a flight of 1 + r = {:.3g} times the "
                                     "expected) it fits: impact numbered {} from here on",
                                     d.where[row], s[p].t - s[p - 1].t, r, std::exp(now.largest), std::exp(threshold),
                                     1 + r, s[p].number + 1)});
    else
      flagged.push_back({d.label, row, "doubled",
                         fmt::format("{}: time {:.9g} s splits a flight (the intervals beside it deviate from the "
                                     "drop's interval ratio r = {:.4g} by up to a factor {:.3g}, threshold {:.3g}): "
                                     "a doubled detection, left out",
                                     d.where[row], s[p].t, r, std::exp(now.largest), std::exp(threshold))});
    s = repaired(s, *best);
  }
  const double r = interval_ratio(s);
  if (r > 0 && r < 1) {
    const Score left = score(s, r, 0.5 * std::log1p(r));
    if (left.above > 0)
      notes.push_back(fmt::format("drop '{}': {} of its intervals deviate from its interval ratio r = {:.4g} by more "
                                  "than a factor {:.3g} that no repair (at most a quarter of its times) explains: "
                                  "fitted as they are",
                                  d.label, left.above, r, std::exp(0.5 * std::log1p(r))));
  }
}

// A flight that does not shrink (the header's step 3), on the repaired times: the drop is cut
// before the later end of the first such interval, each time from there on flagged.
void cut_at_growing_flight(const RecordedDrop& d, std::vector<Time>& s, std::vector<BounceFlag>& flagged) {
  const double median_ratio = s.size() >= 3 ? interval_ratio(s) : 0.0;
  const double r = median_ratio > 0 && median_ratio < 1 ? median_ratio : 1.0;  // spans of g flights, S_g(r)
  auto flight = [&](std::size_t i) { return (s[i + 1].t - s[i].t) / span(s[i + 1].number - s[i].number, r); };
  const double limit = 1 - (1 - r) / 10;  // "near 1": within a tenth of the drop's own loss (the header)
  for (std::size_t k = 1; k + 1 < s.size(); ++k) {
    const double ratio = flight(k) / flight(k - 1);
    if (ratio < limit) continue;
    const std::size_t first_row = s[k + 1].row;
    for (std::size_t i = k + 1; i < s.size(); ++i)
      flagged.push_back(
          {d.label, s[i].row, "not_shrinking",
           i == k + 1 ? fmt::format("{}: the flight ending at time {:.9g} s is not shorter than the one before it "
                                    "(ratio {:.4g}; the drop's r = {:.4g}, so above 1 - (1 - r) / 10 = {:.4g} is no "
                                    "shrink): a bounce that lost no energy, so a doubled, shifted or mistyped "
                                    "detection; the drop is cut here, this time and the {} after it left out",
                                    d.where[s[i].row], s[i].t, ratio, r, limit, s.size() - k - 2)
                      : fmt::format("{}: after the flight that did not shrink (row index {}): left out",
                                    d.where[s[i].row], first_row)});
    s.resize(k + 1);
    return;
  }
}

}  // namespace

std::size_t CheckedRecording::times() const {
  std::size_t n = 0;
  for (const CheckedDrop& d : drops) n += d.impact_time_s.size();
  return n;
}

CheckedRecording check_bounce_recording(const BounceRecording& recording) {
  CheckedRecording out;
  for (const RecordedDrop& d : recording.drops) {
    if (d.impact_time_s.size() > static_cast<std::size_t>(max_bounces))
      throw DataError(fmt::format("{}: drop '{}' has {} impacts; a bounce sequence follows at most {}",
                                  recording.path.string(), d.label, d.impact_time_s.size(), max_bounces));
    std::vector<BounceFlag> flags;
    const std::vector<std::size_t> keep = longest_increasing(d.impact_time_s);
    std::vector<Time> s;
    for (std::size_t i = 0, k = 0; i < d.impact_time_s.size(); ++i) {
      if (k < keep.size() && keep[k] == i) {
        s.push_back({d.impact_time_s[i], static_cast<int>(s.size()), i});
        ++k;
        continue;
      }
      flags.push_back({d.label, i, "non_monotonic",
                       fmt::format("{}: time {:.9g} s is out of order (the drop's longest increasing run of times "
                                   "leaves it out): left out",
                                   d.where[i], d.impact_time_s[i])});
    }
    if (s.size() >= min_checked_bounce_times) repair_glitches(d, s, flags, out.notes);
    else if (s.size() >= min_bounce_times)
      out.notes.push_back(fmt::format("drop '{}' has {} increasing times, fewer than {}: not checked for doubled or "
                                      "missed detections (too few intervals to tell a glitch from its restitution)",
                                      d.label, s.size(), min_checked_bounce_times));
    if (s.size() >= min_checked_bounce_times) cut_at_growing_flight(d, s, flags);
    if (s.size() < min_bounce_times) {
      flags.push_back({d.label, std::nullopt, "too_few",
                       fmt::format("{}: drop '{}' has {} usable times, fewer than {} (its first impact speed and "
                                   "clock offset take two): left out",
                                   d.where.front(), d.label, s.size(), min_bounce_times)});
    } else {
      CheckedDrop c{d.label, {}, {}, {}, d.drop_height_m, 0.0};
      for (const Time& t : s) c.impact_time_s.push_back(t.t), c.impact_number.push_back(t.number), c.index.push_back(t.row);
      c.interval_ratio = interval_ratio(s);
      out.drops.push_back(std::move(c));
    }
    std::stable_sort(flags.begin(), flags.end(), [](const BounceFlag& a, const BounceFlag& b) {
      return a.index.value_or(std::numeric_limits<std::size_t>::max()) <
             b.index.value_or(std::numeric_limits<std::size_t>::max());
    });
    out.flagged.insert(out.flagged.end(), flags.begin(), flags.end());
  }
  if (out.drops.empty()) {  // the reasons, not only their count: the first ten, then how many more
    std::string reasons;
    for (std::size_t i = 0; i < std::min<std::size_t>(out.flagged.size(), 10); ++i)
      reasons += fmt::format("\n  {}: {}", out.flagged[i].kind, out.flagged[i].reason);
    if (out.flagged.size() > 10) reasons += fmt::format("\n  and {} more", out.flagged.size() - 10);
    throw DataError(fmt::format("{}: nothing usable: no drop has {} increasing impact times ({} flagged):{}",
                                recording.path.string(), min_bounce_times, out.flagged.size(), reasons));
  }
  return out;
}

}  // namespace hertzdash
