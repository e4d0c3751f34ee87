#pragma once
// Restitution of a law in the rigid-wall contact phase, and its calibration.
//
// The effective restitution of a law is measured on the contact phase alone: the
// rod meets a rigid flat (rod E = inf) at the approach speed v0 with gravity off,
// so e_effective = rebound speed / v0 is a property of the contact law, not of
// the flight. Laws whose e_effective differs from their input e can be compared
// at equal ACTUAL restitution by calibration: solve e_effective(e_input) = target
// for e_input with GSL's Brent root finder (simulation/run/gsl_root.hpp) on (0, 1].
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <functional>
#include <string>
#include <string_view>

namespace hertzdash {

/// The contact phase of `s`: same bodies, mass, input e and tension rule, but a rigid
/// flat, no gravity, and the approach speed given as the impact velocity.
DropTestSetup contact_phase_setup(const DropTestSetup& s);

struct RestitutionCalibration {
  double e_input;      ///< the input restitution found
  double e_effective;  ///< the law's effective restitution at e_input
  int iterations;      ///< Brent iterations
};

/// Smallest input e the calibration searches; below it most laws do not separate at all.
inline constexpr double calibration_e_min = 1e-3;

/// A target this close to e_effective at an end of [calibration_e_min, 1] is met there:
/// a single run's e_effective is accurate to ~1e-7 at the default CVODE tolerances.
inline constexpr double calibration_end_tolerance = 1e-6;

/// Solve observable(e_input) = target for e_input in [calibration_e_min, 1], `observable`
/// increasing in e_input (an effective restitution, an interval ratio). A target within
/// calibration_end_tolerance of the observable at an end is met there; converged when the
/// bracket is narrower than 1e-10 in e_input. Throws InvalidParameter(option, ...) when the
/// target is outside (0, 1], outside the observable's range, or in a gap where the observable
/// jumps (`what` names the observable).
RestitutionCalibration calibrate_input_restitution(const std::function<double(double)>& observable, double target,
                                                   const std::string& option, std::string_view what);

/// Solve e_effective(e_input) = target for e_input in [calibration_e_min, 1], contact phase
/// of `s`. Converged when the bracket is narrower than 1e-10 in e_input. Throws
/// InvalidParameter("target-restitution", ...) when the target is outside (0, 1] or
/// outside the range [e_effective(e_min), e_effective(1)] the law can reach.
RestitutionCalibration calibrate_restitution(ImpactSimulator& simulator, const DropTestSetup& s, std::string_view law,
                                             double target);

}  // namespace hertzdash
