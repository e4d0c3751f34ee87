#pragma once
// Relative errors of an undamped Hertz impact against its closed forms (model/hertz.hpp),
// shared by the integrator tests that check them.
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hertzdash::testing {

/// |e - 1| and the relative errors of peak deformation, peak force and contact time.
struct UndampedHertzErrors {
  double e, X, F, contact_time;
  double largest() const { return std::max({e, X, F, contact_time}); }
};

/// The errors of `s` against the closed forms `exact`.
inline UndampedHertzErrors undamped_hertz_errors(const ImpactSummary& s, const UndampedHertzImpact& exact) {
  return {std::abs(s.e_effective - 1), std::abs(s.max_deformation_m / exact.max_deformation_m - 1),
          std::abs(s.peak_force_N / exact.peak_force_N - 1), std::abs(s.contact_time_s / exact.contact_time_s - 1)};
}

/// The same, printed as one table row after the tolerance.
inline UndampedHertzErrors undamped_hertz_errors(double tol, const ImpactSummary& s, const UndampedHertzImpact& exact) {
  const UndampedHertzErrors r = undamped_hertz_errors(s, exact);
  std::printf("  %.0e  %.3e  %.3e  %.3e  %.3e  %ld\n", tol, r.e, r.X, r.F, r.contact_time, s.work.rhs_evaluations);
  return r;
}

}  // namespace hertzdash::testing
