// libFuzzer harness: the measured-trace reader (io/measured_trace.hpp). Any input must be read
// or refused with a DataError; a trace that was read must hold what the format promises
// (strictly increasing finite times, every quantity as long as the time, none but NaN or
// finite values, a finite height > 0), and write back to a file that reads again.
#include "fuzz/input_file.hpp"
#include "hertzdash/io/measured_trace.hpp"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hertzdash;
  const std::optional<MeasuredTrace> read = fuzz::read_or_refused(read_measured_trace, data, size);
  if (!read) return 0;
  const MeasuredTrace& m = *read;
  if (!(std::isfinite(m.height_m) && m.height_m > 0)) __builtin_trap();
  for (std::size_t i = 0; i < m.t_s.size(); ++i)
    if (!std::isfinite(m.t_s[i]) || (i > 0 && !(m.t_s[i] > m.t_s[i - 1]))) __builtin_trap();
  for (const std::string& name : measured_quantity_columns()) {
    const std::vector<double>& q = *quantity(m, name);
    if (!q.empty() && q.size() != m.t_s.size()) __builtin_trap();
    for (double v : q)
      if (std::isinf(v)) __builtin_trap();
  }
  (void)measured_trace_text(m, "fuzz", {});
  return 0;
}
