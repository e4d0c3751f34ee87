// libFuzzer harness: the bounce-recording reader (io/bounce_recording.hpp). Any input must be
// read or refused with a DataError; a recording that was read must hold what the format promises
// (a source, at least one drop, each with a plain label (no comma, quote, '#' or control
// character) of its own, at least one time, every time finite, a "FILE:LINE" per time, a height
// 0 (not given) or finite > 0), and write back to a text that reads again to the same values.
#include "fuzz/input_file.hpp"
#include "hertzdash/io/bounce_recording.hpp"

#include <cmath>
#include <set>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hertzdash;
  const std::optional<BounceRecording> read = fuzz::read_or_refused(read_bounce_recording, data, size);
  if (!read) return 0;
  const BounceRecording& r = *read;
  if (r.drops.empty() || r.source.empty()) __builtin_trap();
  std::set<std::string> labels;
  for (const RecordedDrop& d : r.drops) {
    if (!plain_label(d.label) || !labels.insert(d.label).second) __builtin_trap();
    if (d.impact_time_s.empty() || d.where.size() != d.impact_time_s.size()) __builtin_trap();
    for (double t : d.impact_time_s)
      if (!std::isfinite(t)) __builtin_trap();
    if (!(d.drop_height_m == 0 || (std::isfinite(d.drop_height_m) && d.drop_height_m > 0))) __builtin_trap();
  }
  const std::string text = bounce_recording_text(r, "fuzz", {});
  const BounceRecording again = fuzz::read_again(read_bounce_recording, text);
  if (again.drops.size() != r.drops.size() || again.synthetic != r.synthetic) __builtin_trap();
  for (std::size_t i = 0; i < r.drops.size(); ++i)
    if (again.drops[i].label != r.drops[i].label || again.drops[i].impact_time_s != r.drops[i].impact_time_s ||
        again.drops[i].drop_height_m != r.drops[i].drop_height_m)
      __builtin_trap();
  return 0;
}
