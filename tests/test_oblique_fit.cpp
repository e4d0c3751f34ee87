// Fitting friction to rebound angles (simulation/fit/oblique_fit.hpp) on virtual experiments:
// rebound angles computed by the model itself at a known friction coefficient (synthetic data,
// no measurement), which the fit must find again.
//
// The set-up: Chung and Ooi's test-4 alumina sphere at 3.9 m/s, tsuji-dem at e = 0.98
// (validation/common/chung_ooi_test4.hpp), at four or six incident angles across sticking,
// reversing and sliding contacts.
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/fit/oblique_fit.hpp"
#include "validation/common/chung_ooi_test4.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

using namespace hertzdash;

namespace {

const std::vector<double> six_angles{5, 15, 25, 35, 50, 70}, four_angles{5, 20, 35, 60};

/// The model's own rebound angles at `mu` (and a linear spring's k_t, and the sphere's Poisson
/// ratio nu) at `angles`, plus `noise` degrees with alternating signs.
ReboundAngleTable virtual_experiment(const std::string& model, double mu, const std::vector<double>& angles, double noise = 0,
                                     std::optional<double> k_t = {}, std::optional<double> nu = {}) {
  ReboundAngleTable t{"virtual experiment", angles, {}};
  for (std::size_t i = 0; i < angles.size(); ++i) {
    ObliqueImpactSpec s = chung_ooi_test4("tsuji-dem", model, angles[i], mu);
    s.solver = oblique_fit_solver();
    s.linear_stiffness_N_per_m = k_t;
    if (nu) s.setup.ball.nu = *nu;
    t.rebound_angle_deg.push_back(run_oblique_impact(s).rebound_angle_deg + (i % 2 ? noise : -noise));
  }
  return t;
}

}  // namespace

TEST_CASE("oblique fit: the friction coefficient of a noise-free virtual experiment is found again", "[fit][oblique]") {
  // The data are the model at mu = 0.15 to ~1e-8 degrees; the rebound angle moves by tens of
  // degrees per unit of mu at these angles, so the fit's mu is 0.15 to ~1e-9; 1e-6 asserted.
  // Started at 0.1 (the kind's start). With sigma estimated and RSS/n at its floor, the standard
  // error is tiny but finite.
  for (const char* model : {"mindlin-no-slip", "mindlin-deresiewicz"}) {
    CAPTURE(model);
    const FitResult r = fit_rebound_angles(virtual_experiment(model, 0.15, six_angles), chung_ooi_test4("tsuji-dem", model, 0), {});
    REQUIRE_FALSE(r.failed);
    CHECK(r.converged);
    CHECK(r.parameter("friction").estimate == Approx(0.15).margin(1e-6));
    CHECK(r.parameter("friction").initial == 0.1);
    CHECK(r.points.size() == six_angles.size());
  }
}

TEST_CASE("oblique fit: with scatter the estimate lies within its standard errors, and leave-one-out predicts to the scatter",
          "[fit][oblique]") {
  // +-0.5 degrees alternating on the model at mu = 0.15 at four angles: the residuals are about 0.5 degrees,
  // sigma about 0.5 sqrt(n/(n - 1)), and the estimate within 3 standard errors of 0.15. Leaving
  // out each angle in turn and predicting it gives an error of the scatter's order: ratio in
  // (0.5, 2).
  FitSettings settings;
  settings.cross_validate = true;
  const FitResult r =
      fit_rebound_angles(virtual_experiment("mindlin-no-slip", 0.15, four_angles, 0.5), chung_ooi_test4("tsuji-dem", "mindlin-no-slip", 0), settings);
  REQUIRE_FALSE(r.failed);
  const FittedParameter& mu = r.parameter("friction");
  CAPTURE(mu.estimate, mu.standard_error, r.sigma);
  CHECK(std::abs(mu.estimate - 0.15) < 3 * mu.standard_error);
  CHECK(r.sigma == Approx(0.5).epsilon(0.3));
  REQUIRE(r.cross_validation);
  CHECK(r.cross_validation->folds == four_angles.size());
  CHECK(r.cross_validation->ratio > 0.5);
  CHECK(r.cross_validation->ratio < 2);
}

TEST_CASE("oblique fit: the linear spring's stiffness and the friction together", "[fit][oblique]") {
  // Generated at mu = 0.2 and k_t = 2e6 N/m at four angles. The least squares have many minima in
  // k_t (simulation/fit/oblique_fit.hpp); from the scan's best point the joint fit finds both again
  // to 1e-5 relative, k_t in a log variable (no upper bound). Checked from two given starting
  // stiffnesses, a decade apart.
  FitSettings settings;
  settings.parameters = {{"friction", 1e-3, 2}, {"tangential-stiffness", 0, std::numeric_limits<double>::infinity()}};
  for (const double k_start : {1e6, 1e7}) {
    CAPTURE(k_start);
    ObliqueImpactSpec base = chung_ooi_test4("tsuji-dem", "linear-spring", 0);
    base.linear_stiffness_N_per_m = k_start;
    const FitResult r = fit_rebound_angles(virtual_experiment("linear-spring", 0.2, four_angles, 0, 2e6), base, settings);
    REQUIRE_FALSE(r.failed);
    CHECK(r.parameter("friction").estimate == Approx(0.2).epsilon(1e-5));
    CHECK(r.parameter("tangential-stiffness").estimate == Approx(2e6).epsilon(1e-5));
  }
}

TEST_CASE("oblique fit: the sphere's Poisson ratio and the friction together", "[fit][oblique]") {
  // nu sets Mindlin's ratio of tangential to normal compliance, 2 (1 - nu)/(2 - nu), so the rebound
  // angles where the contact sticks; the sliding angles set mu. Generated with Mindlin's no-slip
  // spring at mu = 0.15 and nu = 0.35 (the set-up's own alumina has 0.23, the start) at six angles,
  // noise-free: both found again to 1e-5 relative, the runs being accurate to ~1e-8 degrees.
  FitSettings settings;
  settings.parameters = {{"friction", 1e-3, 2}, {"ball-nu", -0.9, 0.499}};
  const FitResult r = fit_rebound_angles(virtual_experiment("mindlin-no-slip", 0.15, six_angles, 0, {}, 0.35),
                                         chung_ooi_test4("tsuji-dem", "mindlin-no-slip", 0), settings);
  REQUIRE_FALSE(r.failed);
  CHECK(r.parameter("ball-nu").initial == 0.23);
  CHECK(r.parameter("friction").estimate == Approx(0.15).epsilon(1e-5));
  CHECK(r.parameter("ball-nu").estimate == Approx(0.35).epsilon(1e-5));
}

TEST_CASE("oblique fit: what it cannot fit is refused by name", "[fit][oblique]") {
  const ObliqueImpactSpec mindlin = chung_ooi_test4("tsuji-dem", "mindlin-no-slip", 0);
  const ReboundAngleTable table{"t.csv", {10, 20, 30}, {1, 2, 3}};
  FitSettings stiffness;
  stiffness.parameters = {{"tangential-stiffness", 1e4, 1e9}};
  CHECK_THROWS_WITH(fit_rebound_angles(table, mindlin, stiffness), Catch::Contains("fit") && Catch::Contains("linear-spring"));
  FitSettings mass;
  mass.parameters = {{"mass", 1e-6, 1}};
  CHECK_THROWS_WITH(fit_rebound_angles(table, mindlin, mass), Catch::Contains("friction"));
  CHECK_THROWS_AS(fit_rebound_angles({"t.csv", {10, 20}, {1}}, mindlin, {}), DataError);
  CHECK_THROWS_AS(fit_rebound_angles({"t.csv", {10}, {1}}, mindlin, {}), DataError);
}
