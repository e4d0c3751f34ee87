#pragma once
// Dirty bounce recordings, found in the open (issue 33): before a recording
// (io/bounce_recording.hpp) is fitted, each drop's detected impact times are checked, and every
// time the fit will not use is flagged with its drop, its index (0-based, the drop's rows in the
// file's order), its kind and the reason, never silently fitted nor silently dropped.
//
// The physics the check relies on: a body bouncing on a flat with restitution e < 1 has flights
// that shrink geometrically, dt_{k+1} = r dt_k with r about e (the paper's interval ratio;
// bounce_sequence.hpp), r changing slowly if e depends on the speed or air drag acts.
//
// 1. Non-monotonic: a time not after the one before it cannot be a later impact. The drop keeps
//    a longest strictly increasing subsequence of its times (the earliest rows where several
//    are equally long); every other time is flagged `non_monotonic` and left out.
// 2. Doubled and missed detections, on the increasing times with their impact numbers n_i (n_0
//    = 0; a missed impact makes a gap). An interval from impact n spanning g impacts is expected
//    to be C r^n S_g(r), S_g = 1 + r + ... + r^{g-1}; its one-impact value s = dt / S_g(r). At
//    each interior time, the local ratio of the two intervals beside it, l = (s_b / s_a)^(1 /
//    (n_b - n_a)), should be r: its deviation d = |ln l - ln r|, r the median of the drop's
//    local ratios (robust while glitches touch fewer than half of them). A clean drop has d of
//    order the timing jitter over the interval plus the slow change of e (about 0.01-0.05); a
//    missed impact gives an interval r (1 + r) times its predecessor instead of r, d = ln(1 +
//    r) (0.41 for r = 0.5, 0.59 for r = 0.8); a doubled detection splitting an interval in two
//    halves gives d = ln 2 at the times before and after the split, more the shorter a part. The
//    threshold sits halfway in the logarithm between clean and missed, d > ln(1 + r) / 2 (a
//    factor 1.22 for r = 0.5, 1.34 for r = 0.8). While some d exceeds it, the single repair
//    that most lowers the largest d (then the sum of d^2) is made: leave out one time (the
//    extra time of a doubled detection: `doubled`), or add one missed impact in one interval
//    (every later impact renumbered: `missed`, flagged at the time that follows it, whose
//    number the fit then uses; nothing is left out, so a missed impact costs no data). The
//    check stops when no repair lowers the largest d, or after a quarter of the drop's times
//    have been repaired (a drop that dirty is the detector's problem, not noise to clean).
//    A drop needs five times for this check (three local ratios, whose median then resists one
//    glitch); with fewer, its glitches cannot be told from its restitution: it is checked for
//    monotonic times only, and a note says so.
// 3. A flight that does not shrink: after the repairs, a flight (an interval over its span,
//    dt / S_g(r)) as long as the one before it, a ratio near 1 or above it, means the body lost
//    no energy at an impact, which a dissipative bounce cannot: a doubled detection the local check could not
//    place (an interval ratio near 1 where r is near 1 deviates too little from r), or a shifted
//    or mistyped time. Which time is wrong cannot be told, and every later time carries the
//    error: the drop is cut before the later end of the first such flight, each time from there
//    on flagged `not_shrinking` and left out. "Near 1" is above 1 - (1 - r) / 10: a ratio that
//    kept nine tenths of the drop's typical shrink, (1 - r), is not. Timing jitter sigma moves a
//    ratio by sigma sqrt(6) / dt: a clean drop whose flights shrink by (1 - r) dt less than about
//    twice that (r = 0.9, dt = 0.2 s: sigma above 4 ms) can be cut by noise alone, losing data
//    but fitting nothing wrong; its flags say so with their ratios. A drop of fewer than five
//    times is not cut: without the repairs, an echo in it could cut the true impact after it.
// 4. Too few: a drop fits its own first impact speed and clock offset (bounce_fit.hpp), so it
//    tells the law's parameters something only with at least three usable times; a drop with
//    fewer is flagged `too_few` (index: none) and left out whole.
// A drop of more than max_bounces rows is refused (DataError): the model follows at most that
// many impacts.
#include "hertzdash/io/bounce_recording.hpp"

#include <optional>
#include <string>
#include <vector>

namespace hertzdash {

/// The fewest usable times a drop needs to be fitted (two nuisances plus one datum).
inline constexpr std::size_t min_bounce_times = 3;
/// The fewest times a drop needs for the doubled and missed checks (three local ratios).
inline constexpr std::size_t min_checked_bounce_times = 5;

/// One time the fit does not use as given.
struct BounceFlag {
  std::string drop;                  ///< the drop's label
  std::optional<std::size_t> index;  ///< the time's index in the drop (file order); none for a whole drop
  std::string kind;                  ///< non_monotonic, doubled, missed, not_shrinking, too_few
  std::string reason;                ///< why, with the numbers and the row's FILE:LINE
};

/// A drop as the fit uses it.
struct CheckedDrop {
  std::string label;
  std::vector<double> impact_time_s;  ///< the usable times, increasing
  std::vector<int> impact_number;     ///< each time's impact number from the drop's first (gaps: missed impacts)
  std::vector<std::size_t> index;     ///< each time's index in the drop's rows (file order)
  double drop_height_m = 0;           ///< as recorded (0: not given)
  double interval_ratio = 0;          ///< r, the median local ratio of its usable times
};

struct CheckedRecording {
  std::vector<CheckedDrop> drops;     ///< the drops fitted, in the file's order
  std::vector<BounceFlag> flagged;    ///< in the file's order of drops, then by index
  std::vector<std::string> notes;     ///< drops too short for the glitch check
  /// The detector's timing precision, 1 sigma [s] (`fit --timing-sd`); 0: unknown, one common
  /// scatter is fitted. Known, it weighs the times and the fit is judged against it (poor_fit).
  double timing_sd_s = 0;

  std::size_t times() const;          ///< usable times over every drop
};

/// Check every drop (see the header comment). Throws DataError naming the file when no drop is
/// usable, or a drop has more than max_bounces rows.
CheckedRecording check_bounce_recording(const BounceRecording& recording);

}  // namespace hertzdash
