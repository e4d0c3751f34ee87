#pragma once
// The worked example of model/README.md ("Adding a damping law"): a Hunt-Crossley
// type law whose damping factor is chosen so that it returns its input restitution
// EXACTLY. It lives in tests/ so that the guide's code is compiled and run through
// the same standard checks as every registered law (tests/test_damping_law_standard.cpp)
// without adding a law to the CLI (tests/example_law_runs.cpp compiles its runs); to register
// it, move it to model/damping/laws/ and add its line to model/damping/registered_laws.cmake.
#include "hertzdash/model/damping/hertz_proportional_dashpot.hpp"

#include <cmath>

namespace hertzdash {

/// F = K x^{3/2} (1 + chi xdot),  chi = a(e) / v0, where a = chi v0 is the root in
/// (0, 1/e) of
///   g(a) = ln(1 + a) - ln(1 - e a) - (1 + e) a = 0,
/// the exact restitution relation of the Hunt-Crossley form (derived in
/// tests/test_damping_law_restitution.cpp: with b = e a the rebound's chi v_r,
/// a - ln(1 + a) = -b - ln(1 - b)). g(0) = 0, g < 0 just above 0 for e < 1
/// (g ~ -(1 - e^2) a^2 / 2) and g -> +inf as a -> 1/e, so bisection on (0, 1/e)
/// finds the one nontrivial root.
class ExactHertzDashpot : public HertzProportionalDashpot<ExactHertzDashpot> {
 public:
  static constexpr LawInfo info{
      "exact-hertz-dashpot",
      "hertzdash worked example (model/README.md): the Hunt-Crossley form with the exact damping factor.",
      "F = K x^{3/2} (1 + chi xdot)",
      "chi v0 = root a of ln(1+a) - ln(1-e a) = (1+e) a; independent of K and m",
      "any e in (0, 1]; returns its input e exactly (tension never arises)",
      true};

  /// chi v0 [-] for the input restitution e in (0, 1]: 200 bisection steps of (0, 1/e),
  /// far more than the 53 that exhaust double precision (the loop stops when the
  /// midpoint no longer moves).
  static double chi_v0(double e) {
    if (e >= 1.0) return 0.0;
    auto g = [e](double a) { return std::log1p(a) - std::log1p(-e * a) - (1.0 + e) * a; };
    double lo = 0.0, hi = 1.0 / e;
    for (int i = 0; i < 200; ++i) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      (g(mid) < 0.0 ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
  }

  using HertzProportionalDashpot::HertzProportionalDashpot;
};

}  // namespace hertzdash
