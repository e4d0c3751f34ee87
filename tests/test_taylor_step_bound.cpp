// The complex singularities of the undamped regularised contact
// (validation/common/regularized_contact_singularities.hpp), which set how far any Taylor step can reach,
// against the series themselves; and the Taylor path's count of series against the least
// count they allow.
#include "hertzdash/integrators/power_series.hpp"
#include "hertzdash/integrators/taylor.hpp"
#include "hertzdash/model/damping/laws/undamped.hpp"
#include "validation/common/regularized_contact_singularities.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

using namespace hertzdash;

TEST_CASE("undamped regularised contact: the nearest singularities lie above the turning point", "[taylor]") {
  // Re s* = |s*| cos(pi/5) equals the half duration S: w_m B(1/5, 3/10) cos(pi/5) / 5 =
  // w_m B(1/5, 1/2) / 5 follows from Gamma(3/10) Gamma(7/10) = pi / sin(3 pi/10) and
  // cos(pi/5) = sin(3 pi/10). Rounding only: 1e-14.
  const UndampedRegularizedContact c = undamped_regularized_contact();
  CHECK(c.singular_distance * std::cos(std::numbers::pi / 5) == Approx(c.half_duration).epsilon(1e-14));
  // Hence Im s* / S = tan(pi/5).
  CHECK(c.singular_height / c.half_duration == Approx(std::tan(std::numbers::pi / 5)).epsilon(1e-14));
  // The series of w'' = -w^4 at the turning point (w = w_m, w' = 0), by the recurrence of
  // power_series.hpp: it is even about that point, so in sigma = s^2 its coefficients
  // a_j = c_{2j} have the singularities s* - S = +-i Im s* at sigma = -(Im s*)^2, and, with
  // w ~ (s - s*)^{-2/3} there, a_j ~ (-(Im s*)^2)^{-j} j^{-1/3} (1 + O(1/j)). The ratios
  // r_j = a_j / a_{j-1} then carry a 1/j term, which the Domb-Sykes extrapolation
  // j r_j - (j - 1) r_{j-1} removes, leaving O(1/j^2): about 1e-4 at j = 16 (the plain ratio
  // test is 1 % off there). So the radius at the turning point is Im s* within 1e-3.
  constexpr int order = series_capacity;
  std::array<std::array<double, series_capacity + 1>, 2> coefficients{};
  coefficients[0][0] = c.w_max;
  const SeriesVariable w{coefficients[0].data()}, v{coefficients[1].data()};
  auto w2 = w * w;
  auto rhs = std::tuple{v, -1.0 * (w2 * w2)};
  SeriesStorage<series_products<decltype(std::get<1>(rhs))>> storage;
  storage.bind(std::get<1>(rhs));
  for (int k = 0; k < order; ++k) {
    std::get<1>(rhs).update(k);
    coefficients[0][k + 1] = std::get<0>(rhs)[k] / (k + 1);
    coefficients[1][k + 1] = std::get<1>(rhs)[k] / (k + 1);
  }
  for (int k = 1; k <= order; k += 2) CHECK(coefficients[0][k] == 0.0);  // even about the turning point
  const auto a = [&](int j) { return coefficients[0][2 * j]; };
  const int j = order / 2;
  const double r = a(j) / a(j - 1), r_previous = a(j - 1) / a(j - 2);
  const double extrapolated = j * r - (j - 1) * r_previous;
  CHECK(extrapolated < 0);  // the singularities are off the real axis, a conjugate pair
  const double radius = 1.0 / std::sqrt(-extrapolated);
  std::printf("turning point: radius from the series %.6f, Im s* %.6f (plain ratio %.6f)\n", radius,
              c.singular_height, 1.0 / std::sqrt(std::abs(r)));
  CHECK(radius == Approx(c.singular_height).epsilon(1e-3));
}

TEST_CASE("taylor-regularized's count of series against the singularities' estimate", "[taylor]") {
  // The undamped contact without gravity at 0.626 m/s, tolerances 1e-6..1e-10: the number of
  // series generated (right-hand-side evaluations / order) is at least the estimate
  // least_taylor_series(tol, p) -- the step rule holds the last term kept, not the first one
  // dropped, to the tolerance, a margin of tol^{-1/p} over tol^{-1/(p+1)} -- and at most twice
  // it (a step rule that wasted more would be a regression).
  const PaperParameters paper = load_paper_parameters();
  DropTestSetup setup = paper_setup(paper, "steel", 0.02);
  setup.gravity_mps2 = 0.0;
  setup.impact_velocity_mps = 0.626;
  validate(setup);
  std::printf("undamped contact: tol, order, series generated, least estimate\n");
  for (double tol : {1e-6, 1e-8, 1e-10}) {
    SolverSettings settings;
    settings.integrator = IntegratorKind::taylor_regularized;
    settings.rtol = tol;
    settings.atol = 1e-4 * tol;
    ImpactSimulator sim(settings);
    const ImpactSummary s = sim.run<Undamped>(setup);
    REQUIRE(s.separated);
    const int p = taylor_order(tol);
    const double series = static_cast<double>(s.work.rhs_evaluations) / p, least = least_taylor_series(tol, p);
    std::printf("%8.0e %3d %6.0f %6.2f\n", tol, p, series, least);
    CHECK(series >= least);
    CHECK(series <= 2 * least);
  }
}
