// libFuzzer harness: the restitution-table reader (io/restitution_table.hpp). Any input must be
// read or refused with a DataError; a table that was read must hold what the format promises
// (at least two rows, every speed finite and > 0, every e in (0, 1], e_sd empty or one finite
// value > 0 per row, contact times empty or one per row, NaN or finite > 0), and write back to a
// text that reads again to the same values.
#include "fuzz/input_file.hpp"
#include "hertzdash/io/restitution_table.hpp"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hertzdash;
  const std::optional<RestitutionTable> read = fuzz::read_or_refused(read_restitution_table, data, size);
  if (!read) return 0;
  const RestitutionTable& t = *read;
  const std::size_t n = t.rows();
  if (n < 2 || t.impact_speed_mps.size() != n || (!t.e_sd.empty() && t.e_sd.size() != n) ||
      (!t.contact_time_s.empty() && t.contact_time_s.size() != n) || t.source.empty())
    __builtin_trap();
  for (std::size_t i = 0; i < n; ++i) {
    if (!(std::isfinite(t.impact_speed_mps[i]) && t.impact_speed_mps[i] > 0)) __builtin_trap();
    if (!(t.e[i] > 0 && t.e[i] <= 1)) __builtin_trap();
    if (t.has_sd() && !(std::isfinite(t.e_sd[i]) && t.e_sd[i] > 0)) __builtin_trap();
    if (!t.contact_time_s.empty() && !std::isnan(t.contact_time_s[i]) &&
        !(std::isfinite(t.contact_time_s[i]) && t.contact_time_s[i] > 0))
      __builtin_trap();
  }
  const std::string text = restitution_table_text(t, "fuzz", {});
  const RestitutionTable again = fuzz::read_again(read_restitution_table, text);
  if (again.e != t.e || again.impact_speed_mps != t.impact_speed_mps || again.e_sd != t.e_sd ||
      again.synthetic != t.synthetic)
    __builtin_trap();
  return 0;
}
