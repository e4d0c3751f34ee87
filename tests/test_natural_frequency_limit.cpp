// The undamped limit of the paper's natural frequency, eqs. (7)-(11) as corrected.
//
// With e = 1, eq. (10) reads (1/2) m v0^2 = (2/5) K X^{5/2}: Xmax is the exact peak
// deformation X of the undamped Hertz impact (model/hertz.hpp). The corrected
// eq. (9), w = sqrt((4K/(5m)) X^{1/2}), then satisfies
//   (w X)^2 = (4K/(5m)) X^{5/2} = v0^2,   i.e.   w = v0 / X   exactly,
// the identity the article's errata argument rests on (paper/sections/differences.tex).
// The printed eq. (9), sqrt(4K/(5m)) X^{1/2}, differs from it by the factor X^{1/4},
// which is not dimensionless: its value changes with the unit of length.
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/hertz.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace hertzdash;

TEST_CASE("corrected eq. (9) at e = 1 gives w = v0 / X, X the undamped Hertz peak deformation",
          "[model][natural-frequency]") {
  // The steel rod on nylon (K ~ 3.5e8 N/m^1.5, m = 0.778 kg) and a soft, light case,
  // over two decades of approach speed.
  const double K = GENERATE(3.54e8, 2.0e6);
  const double m = GENERATE(0.778, 0.01);
  const double v0 = GENERATE(0.1, 0.626, 10.0);
  const double X_eq10 = paper_peak_deformation(K, m, v0, 1.0);
  const double X_hertz = undamped_hertz_impact(K, m, v0).max_deformation_m;
  const double w = hertz_natural_frequency(K, m, X_eq10);
  INFO("K = " << K << ", m = " << m << ", v0 = " << v0);
  // Both are (5 m v0^2 / (4K))^{2/5}, by two spellings of the same pow: a few ulps.
  CHECK(X_eq10 == Approx(X_hertz).epsilon(1e-14));
  // w X / v0 = 1: a sqrt, a pow and four products, each within half an ulp, so the
  // relative error is below ~1e-15; 1e-13 leaves room for the pow's own rounding.
  CHECK(w * X_eq10 / v0 == Approx(1.0).epsilon(1e-13));
}

TEST_CASE("the printed eq. (9) differs from the corrected one by X^{1/4}, which depends on the unit",
          "[model][natural-frequency][erratum]") {
  // Expected values, from the two formulas:
  //   as printed / corrected = sqrt(4K/(5m)) X^{1/2} / sqrt((4K/(5m)) X^{1/2})
  //                          = X^{1/2} / X^{1/4} = X^{1/4};
  // in the millimetre-kilogram-second system (force in kg mm/s^2 = 1e-3 N) the numbers
  // become K_mm = 1e3 (1e-3)^{3/2} K = 10^{-3/2} K and X_mm = 1e3 X, so
  //   corrected_mm / corrected_SI = (10^{-3/2} (1e3)^{1/2})^{1/2} = 1   (a frequency),
  //   printed_mm / printed_SI     = (10^{-3/2})^{1/2} (1e3)^{1/2} = 10^{3/4} = (1e3)^{1/4}.
  const double K = 3.54e8, m = 0.778, v0 = 0.626;  // steel rod, h = 20 mm
  const double X = paper_peak_deformation(K, m, v0, 1.0);
  const double w_corrected = hertz_natural_frequency(K, m, X);
  const double w_printed_SI = as_printed_natural_frequency(K, m, X);
  const double K_mm = K * 1e3 * std::pow(1e-3, 1.5), X_mm = 1e3 * X;
  const double w_corrected_mm = hertz_natural_frequency(K_mm, m, X_mm);
  const double w_printed_mm = as_printed_natural_frequency(K_mm, m, X_mm);
  // Each side is a few sqrt, pow and products (relative error ~1e-15); 1e-13 leaves room
  // for the pow's own rounding, and is far below any misplaced exponent (X^{1/4} ~ 0.1).
  CHECK(w_printed_SI / w_corrected == Approx(std::pow(X, 0.25)).epsilon(1e-13));
  // The erratum the article's Table II states: the corrected w does not depend on the
  // unit of length, the printed one changes by (1e3)^{1/4}.
  CHECK(w_corrected_mm == Approx(w_corrected).epsilon(1e-13));
  CHECK(w_printed_mm / w_printed_SI == Approx(std::pow(1e3, 0.25)).epsilon(1e-13));
}
