// Hertz theory holds for a contact small against the ball (a << R). A run whose deformation
// is not small is flagged (issue 19: results that violate the model's own assumptions are
// warnings in the summary and JSON, never silent numbers).
#include "cli_runner.hpp"

#include "hertzdash/model/hertz.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

using hertzdash::test::run_cli;

TEST_CASE("The Hertz profile error is the sphere's departure from the paraboloid to first order", "[hertz][deformation]") {
  // The sphere of radius R at r = a: z = R - sqrt(R^2 - a^2) = a^2/(2R) + a^4/(8R^3) + a^6/(16R^5) + ...
  // Relative to the paraboloid a^2/(2R): 1 + a^2/(4R^2) + a^4/(8R^4) + ..., and with a^2 = R x the
  // departure is x/(4R) + (x/R)^2/8 + ... So the exact departure minus hertz_profile_error is
  // (x/R)^2/8 to leading order: positive and at most (x/R)^2/8 (1 + x/R) for x/R <= 0.2.
  // The exact departure, written without cancellation: with s = sqrt(R^2 - a^2),
  // (R - s) / (a^2 / 2R) - 1 = 2R / (R + s) - 1 = (R - s) / (R + s) = a^2 / (R + s)^2.
  const double R = 0.0127;
  for (double x_over_R : {1e-4, 1e-3, 0.01, 0.04, 0.1, 0.2}) {
    const double x = x_over_R * R, a2 = R * x, s = std::sqrt(R * R - a2);
    const double exact = a2 / ((R + s) * (R + s));
    const double difference = exact - hertzdash::hertz_profile_error(x, R);
    INFO("x/R = " << x_over_R << ": exact " << exact << ", first order " << hertzdash::hertz_profile_error(x, R));
    CHECK(difference > 0);
    CHECK(difference <= x_over_R * x_over_R / 8 * (1 + x_over_R));
  }
  // The limit of 1 % is a/R = 0.2: x/R = 0.04.
  CHECK(hertzdash::hertz_profile_error(0.04 * R, R) == Approx(hertzdash::hertz_profile_error_limit).epsilon(1e-12));
}

namespace {

nlohmann::json simulate_json(const std::string& args, std::string* err = nullptr) {
  const auto r = run_cli("simulate --json " + args);
  INFO("hertzdash simulate --json " << args << "\n  stderr: " << r.err);
  REQUIRE(r.exit_code == 0);
  if (err) *err = r.err;
  return nlohmann::json::parse(r.out);
}

bool has_warning(const nlohmann::json& j, const std::string& code) {
  for (const auto& w : j["warnings"])
    if (w["code"] == code) return true;
  return false;
}

}  // namespace

TEST_CASE("simulate flags a deformation that is not small against the ball radius", "[cli][deformation]") {
  // The steel rod from 20 mm deforms the ball by x = 0.242 mm, x/R = 0.019: profile error 0.48 %,
  // inside the limit. From 0.3 m, x = 0.713 mm, x/R = 0.056: 1.4 %, outside it.
  std::string err;
  const auto low = simulate_json("--height 0.02 --ball-yield-stress inf", &err);
  CHECK(low["hertz_profile_error"].get<double>() ==
        Approx(low["max_deformation_m"].get<double>() / (4 * 0.0127)).epsilon(1e-12));
  CHECK_FALSE(low["exceeds_small_deformation"].get<bool>());
  CHECK(low["warnings"].empty());  // a clean run: no yield check, resolved, separated
  CHECK(err.empty());

  const auto high = simulate_json("--height 0.3 --ball-yield-stress inf", &err);
  CHECK(high["exceeds_small_deformation"].get<bool>());
  CHECK(has_warning(high, "large_deformation"));
  CHECK(err.find("hertzdash: warning: the maximum deformation") != std::string::npos);
  // The yield check reports through the same list when it applies.
  CHECK(has_warning(simulate_json("--height 0.02"), "yield_onset"));
}

TEST_CASE("A rod that never separates is a warning in the JSON, not only a flag", "[cli][deformation]") {
  // With e = 0.01 the paper's law dissipates nearly all of the 20 mm drop's energy; gravity then
  // holds the rod on the ball and it never leaves it within the simulated 20 t_H.
  std::string err;
  const auto j = simulate_json("--restitution 0.01", &err);
  REQUIRE_FALSE(j["separated"].get<bool>());
  CHECK(has_warning(j, "not_separated"));
  CHECK(err.find("did not separate") != std::string::npos);
}
