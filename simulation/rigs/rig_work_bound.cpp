// The work bound of a rig (simulation/rigs/rig_work_bound.hpp).
#include "hertzdash/simulation/rigs/rig_work_bound.hpp"

#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hertzdash {

RigTimeScale drive_period_scale(double frequency_Hz, bool given) {
  return {.what = "the drive period 1/f", .seconds = 1 / frequency_Hz, .key = "frequency", .value = frequency_Hz,
          .given = given};
}

RigTimeScale natural_period_scale(std::string_view what, double mass_kg, double stiffness_N_per_m, std::string_view key,
                                  double value, bool given) {
  return {.what = fmt::format("{} natural period 2 pi sqrt(mass/stiffness)", what),
          .seconds = 2 * std::numbers::pi * std::sqrt(mass_kg / stiffness_N_per_m), .key = key, .value = value,
          .given = given};
}

RigTimeScale hertz_contact_time_scale(const DropTestSetup& setup, double speed_mps, bool mass_given) {
  return {.what = fmt::format("the Hertz contact time at {:.3g} m/s", speed_mps),
          .seconds = undamped_hertz_impact(hertz_stiffness(setup), setup.mass_kg, speed_mps).contact_time_s,
          .key = "mass", .value = setup.mass_kg, .given = mass_given, .resolved = false};
}

void require_bounded_rig_work(std::span<const RigTimeScale> scales, int impacts, int transient, bool impacts_given) {
  const RigTimeScale* shortest = nullptr;
  const RigTimeScale* longest = nullptr;
  for (const RigTimeScale& s : scales) {
    if (s.resolved && (!shortest || !(s.seconds >= shortest->seconds))) shortest = &s;
    if (!longest || !(s.seconds <= longest->seconds)) longest = &s;
  }
  if (!shortest || !longest) return;
  const double n = static_cast<double>(impacts) + transient, ratio = std::max(longest->seconds / shortest->seconds, 1.0);
  const double work = n * (rig_work_per_impact + ratio);
  if (work <= max_rig_work) return;  // NaN (a scale 0 or infinite) is refused below
  const RigTimeScale* blamed = shortest->given || !longest->given ? shortest : longest;
  const std::string scales_text =
      shortest == longest
          ? fmt::format("its one time scale, {}, is {:.3g} s", shortest->what, shortest->seconds)
          : fmt::format("{} is {:.3g} s and {} is {:.3g} s, a ratio of {:.3g}", shortest->what, shortest->seconds,
                        longest->what, longest->seconds, longest->seconds / shortest->seconds);
  const std::string why = fmt::format(
      "such that the run's work is bounded: {}; {:.0f} impacts (transient and kept) would take about {:.3g} steps "
      "({:.0f} per impact plus the ratio), above the {:.3g} (about a minute) a run may take (docs/reliability.md, "
      "\"Work bounds\")",
      scales_text, n, work, rig_work_per_impact, max_rig_work);
  if (!blamed->given && impacts_given) throw InvalidParameter("impacts", format_value(impacts), why);
  throw InvalidParameter(std::string(blamed->key), format_value(blamed->value) + (blamed->given ? "" : " (default)"), why);
}

}  // namespace hertzdash
