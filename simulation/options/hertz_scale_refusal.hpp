#pragma once
// The refusal of a set-up outside the Hertz model's scale, worded for a user who typed some of
// its inputs: the model (model/drop_test_setup.hpp, validate_hertz_scale) finds that the
// undamped Hertz deformation X = (5 m v0^2 / (4 K))^{2/5} breaks a bound and gives the numbers;
// this names an input the user gave, with the bound on it where one input alone sets it.
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/options/run_options.hpp"

namespace hertzdash {

/// Throws InvalidParameter naming the first of these inputs that `given` holds, with the bound
/// on it: `impact-velocity` (v0 = sqrt(4 K X^{5/2} / (5 m)) at X on the bound), `height`
/// (v0^2 / 2g), `gravity` (v0^2 / 2h), `mass` (4 K X^{5/2} / (5 v0^2)); then `ball-radius`,
/// `ball-E`, `rod-E`, `ball-nu`, `rod-nu` (which enter through K and R); the height, marked a
/// default, when the user gave none of them. A speed a front end set (RunOptions::
/// impact_velocity_origin) is never blamed before an input the user gave, and is named by its
/// origin, with the bound on it, when the user gave none. The message lists the inputs that together give X,
/// "(default)" after each the user did not give.
[[noreturn]] void refuse_hertz_scale(const DropTestSetup& s, const HertzScale& scale, const RunOptions& given);

}  // namespace hertzdash
