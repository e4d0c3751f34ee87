// The set-up a measured trace states, merged with the options (simulation/fit/trace_setup.hpp).
#include "hertzdash/simulation/fit/trace_setup.hpp"

#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace hertzdash {

RunOptions trace_setup_options(const MeasuredTrace& trace, const RunOptions& base, const PaperParameters& paper,
                               const std::vector<std::string>& given) {
  const std::string file = trace.path.string();
  auto was_given = [&](const char* name) {
    return is_given(base, *find_run_option(name)) || std::find(given.begin(), given.end(), name) != given.end();
  };
  RunOptions o = base;
  if (!was_given("rod")) o.rod = trace.rod;
  else if (base.rod != trace.rod)
    throw InvalidParameter("rod", base.rod,
                           fmt::format("the trace's rod, {} (its header line 'rod:', {}), or omitted: the trace says "
                                       "which rod it measured",
                                       trace.rod, file));
  if (!base.impact_velocity_mps) {  // a given approach speed replaces the height (trace_setup.hpp)
    if (!base.height_m) o.height_m = trace.height_m;
    else if (!(std::abs(*base.height_m - trace.height_m) <= height_match_tolerance_m))
      throw InvalidParameter("height", format_value(*base.height_m),
                             fmt::format("within {:g} m of the trace's height_m, {} m (its header line 'height_m:', "
                                         "{}), or omitted: the trace says from where the rod fell",
                                         height_match_tolerance_m, format_value(trace.height_m), file));
  }
  // The options alone were valid (run_fit resolves them before reading the trace): a refusal
  // now is of the trace's header values.
  try {
    resolve_setup(o, paper);
  } catch (const InvalidParameter& e) {
    throw InvalidParameter(e.key, e.value,
                           fmt::format("{}; the value is the trace's header (rod: {}, height_m: {}; {})", e.valid_range,
                                       trace.rod, format_value(trace.height_m), file));
  }
  return o;
}

}  // namespace hertzdash
