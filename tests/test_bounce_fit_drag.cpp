// Air drag in the bounce-recording fit (issue 33): a SYNTHETIC recording of a light ball made
// with drag is fitted with and without it. With the drag it was made with, the fit gives back
// its e; without, it mistakes the drag for a lower e, by the amount the closed-form flights
// predict. No measured recording ships.
#include "bounce_recording_synthetic.hpp"

#include "hertzdash/model/air_drag.hpp"
#include "hertzdash/simulation/fit/bounce_fit.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

using namespace hertzdash;
using namespace hertzdash::test;

namespace {

/// A 2.7 g ball of 20 mm radius on a steel plate in air (docs/balls.md), Kelvin-Voigt's law at
/// e = 0.9 (calibrated at each impact: its velocity ratio is e at every speed).
RunOptions light_ball(bool drag) {
  RunOptions o;
  o.damping = "kelvin-voigt";
  o.restitution = 0.9;
  o.mass_kg = 2.7e-3;
  o.ball_radius_m = 0.02;
  o.ball_E_Pa = 2.4e9;
  o.ball_nu = 0.35;
  o.ball_yield_stress_Pa = INFINITY;
  o.rod_E_Pa = 200e9;
  o.rod_nu = 0.3;
  if (drag) o.air_density_kg_per_m3 = 1.204;
  return o;
}

FitResult fit(const BounceRecording& r, RunOptions o) {
  o.restitution.reset();  // the fit's parameter: its starting value is not the truth
  const CheckedRecording c = check_bounce_recording(r);
  return fit_bounce_recording(c, r.path.string(), o, load_paper_parameters(), FitSettings{});
}

}  // namespace

TEST_CASE("bounce recording: drag changes the fitted e of a light ball, as the flights predict", "[bounce_fit]") {
  // Three drops at 2, 2.5 and 3 m/s, six impacts each, noise-free.
  const std::vector<SyntheticDrop> drops{{"a", 2.0, 0.0}, {"b", 2.5, 10.0}, {"c", 3.0, 20.0}};
  const BounceRecording r = synthetic_recording(light_ball(true), drops, 6);

  // With the drag it was made with, the fit returns e = 0.9 to the fit's accuracy: 1e-8 in
  // tests/test_bounce_recording_fit.cpp for the steel rod's 8 impacts; here 6 impacts of d e /
  // d t ~ 1 / (k t_k) ten times weaker at these shorter flights (0.1-0.5 s), so 1e-7.
  const FitResult with = fit(r, light_ball(true));
  REQUIRE_FALSE(with.failed);
  CHECK(with.parameter("restitution").estimate == Approx(0.9).margin(1e-7));

  // Without it, the model's flights are 2 v / g. With drag a flight from v is
  // T(v) = (2 v / g)(1 - d / 4 + O(d^2)) and the next rebound e v (1 - d / 2), d = (v / v_t)^2
  // (tests/test_air_drag.cpp): each interval ratio reads e (1 - (1 + e^2) d / 4). A vacuum
  // model fits one e' to ratios whose d spans the recording's flights, so
  //   e (1 - (1 + e^2) d_max / 4) - O(d_max^2) <= e' <= e (1 - (1 + e^2) d_min / 4) + O(d_max^2),
  // d_max and d_min the largest and smallest (v_r / v_t)^2 of the flights the fit sees.
  const FitResult without = fit(r, light_ball(false));
  REQUIRE_FALSE(without.failed);
  const double e = 0.9, e_fitted = without.parameter("restitution").estimate;
  const double v_t = terminal_speed_mps({.air_density_kg_per_m3 = 1.204}, 2.7e-3, 0.02, 9.80665);
  const double v_r_max = e * 3.0, v_r_min = e * 2.0 * std::pow(e, 4);  // the last flight of the slowest drop
  const double d_max = (v_r_max / v_t) * (v_r_max / v_t), d_min = (v_r_min / v_t) * (v_r_min / v_t);
  INFO("fitted without drag " << e_fitted << ", d in [" << d_min << ", " << d_max << "]");
  CHECK(e_fitted < e * (1 - (1 + e * e) * d_min / 4) + d_max * d_max);
  CHECK(e_fitted > e * (1 - (1 + e * e) * d_max / 4) - d_max * d_max);
  CHECK(e - e_fitted > d_max * d_max);  // the shift is beyond the bounds' second-order slack
  // And the vacuum model cannot follow the drag's flights: its timing residuals are far above the
  // drag model's (noise-free: rounding and the integrators' ~1e-12 s).
  CHECK(without.sigma > 1e3 * std::max(with.sigma, 1e-12));
}
