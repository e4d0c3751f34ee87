#pragma once
// A fitted parameter's profile-likelihood interval where the model is nearly linear over one
// standard error (simulation/fit/profile_interval.hpp): found on both sides, closed, and its ends
// the Wald ends estimate +- standard error to within `share` of the standard error.
#include "hertzdash/simulation/fit/fit_engine.hpp"

#include <catch2/catch.hpp>

namespace hertzdash::test {

inline void check_nearly_wald_interval(const FittedParameter& p, double share) {
  CAPTURE(p.name, p.estimate, p.standard_error);
  REQUIRE(p.profile);
  CHECK(p.profile->failure.empty());
  CHECK_FALSE(p.profile->lower_open);
  CHECK_FALSE(p.profile->upper_open);
  CHECK(p.profile->lower == Approx(p.estimate - p.standard_error).margin(share * p.standard_error));
  CHECK(p.profile->upper == Approx(p.estimate + p.standard_error).margin(share * p.standard_error));
}

}  // namespace hertzdash::test
