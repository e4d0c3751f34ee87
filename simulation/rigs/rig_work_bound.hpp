#pragma once
// The work bound of a rig on the impact-sequence driver (simulation/shaker/impact_sequence.hpp),
// checked from its inputs before it runs (docs/reliability.md, "Work bounds").
// The driver's flights are closed forms, but it samples them (64 points per drive cycle, 16 per
// natural period for the energy account) and searches them for impacts in spans of 100 drive
// cycles and 4 natural periods; a soft contact's integrator resolves the drive inside the contact.
// So an impact costs about a fixed c (the search, the contact, the bookkeeping) and L / S such
// steps, L the longest of the run's time scales (the drive period, the natural periods, a flight,
// a contact) and S the shortest of those the run resolves (the drive period, the natural periods,
// the fall across a gap), and a run of N impacts (transient and kept) about W = N (c + L / S).
// Measured on the development machine (one core), 101,000 impacts of each rig's default run took
// 9 to 62 us each, and the impact damper with instantaneous impacts at L / S = 1e4 and 1e5 (1,100
// impacts) 1.4 s and 12.7 s: one unit of W is about 1.2e-7 s, and c = 500 units (60 us) bounds
// the measured impacts.
#include "hertzdash/model/drop_test_setup.hpp"

#include <span>
#include <string>
#include <string_view>

namespace hertzdash {

/// A time scale of a rig's run and the input that sets it.
struct RigTimeScale {
  std::string what;          ///< "the drive period 1/f"
  double seconds = 0;        ///< [s]
  std::string_view key;      ///< the input that sets it ("frequency")
  double value = 0;          ///< that input's value
  bool given = false;        ///< the user gave it
  bool resolved = true;      ///< a scale the run resolves (S above); false: a duration only (a contact, a flight)
};

/// The drive period 1/f, set by `frequency` (resolved).
RigTimeScale drive_period_scale(double frequency_Hz, bool given);
/// A natural period 2 pi sqrt(mass / stiffness) of `what` ("the primary's"), set by the input
/// `key` of value `value` (resolved).
RigTimeScale natural_period_scale(std::string_view what, double mass_kg, double stiffness_N_per_m, std::string_view key,
                                  double value, bool given);

/// The soft contact's time scale: the undamped Hertz contact time (model/hertz.hpp) of the set-up's
/// body at `speed_mps`, set by `mass` (a duration: not resolved).
RigTimeScale hertz_contact_time_scale(const DropTestSetup& setup, double speed_mps, bool mass_given);

/// The fixed cost c of an impact, in units of W (see above).
inline constexpr double rig_work_per_impact = 500;
/// The most work W = N (c + L / S) of one run: about a minute on one core of the development machine.
inline constexpr double max_rig_work = 5e8;

/// Refuses a run whose predicted work N (c + L / S) (see above) exceeds max_rig_work, with an
/// InvalidParameter naming the input that sets the shortest resolved scale S if the user gave
/// it, else the one that sets the longest L, else `impacts`.
void require_bounded_rig_work(std::span<const RigTimeScale> scales, int impacts, int transient, bool impacts_given);

}  // namespace hertzdash
