// The free-free rod frequencies of model/rod_vibration.hpp (used to check Table 3).
#include "hertzdash/model/rod_vibration.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

using namespace hertzdash;

TEST_CASE("beta1 L is the first non-zero root of the free-free frequency equation", "[rod_vibration]") {
  // Free-free Euler-Bernoulli beam: cos(bL) cosh(bL) = 1. At the root the residual is
  // roundoff of a product of size cosh(4.73) ~ 57: |residual| <= ~57 * 2 eps ~ 3e-14.
  const double b = free_free_beta1_L;
  CHECK(std::abs(std::cos(b) * std::cosh(b) - 1.0) < 1e-12);
  // ... and it is the first one above zero: the residual keeps one sign on (pi, b),
  // the bracket where the first root must lie (cos < 0 there until 3pi/2).
  double largest = -INFINITY;
  for (double x = std::numbers::pi; x < b - 1e-3; x += 1e-3) largest = std::max(largest, std::cos(x) * std::cosh(x) - 1.0);
  CHECK(largest < 0.0);
}

TEST_CASE("flexural frequency matches the textbook formula with I and A written out", "[rod_vibration]") {
  // Independent evaluation: f1 = (bL)^2 / (2 pi L^2) sqrt(E I / (rho A)),
  // I = pi d^4/64, A = pi d^2/4, rho = m/(A L). Same arithmetic up to reordering,
  // so agreement to a few ulps (1e-14 relative).
  const RodGeometry rod{0.025, 0.2, 0.274};
  const double E = 67.4e9;
  const double A = std::numbers::pi * rod.diameter_m * rod.diameter_m / 4.0;
  const double I = std::numbers::pi * std::pow(rod.diameter_m, 4) / 64.0;
  const double rho = rod.mass_kg / (A * rod.length_m);
  const double f_expected = free_free_beta1_L * free_free_beta1_L / (2.0 * std::numbers::pi * rod.length_m * rod.length_m) *
                            std::sqrt(E * I / (rho * A));
  CHECK(flexural_frequency_hz(rod, E) == Approx(f_expected).epsilon(1e-14));
  CHECK(rod_density_kg_per_m3(rod) == Approx(rho).epsilon(1e-15));
}

TEST_CASE("frequency and modulus are inverse maps, with the expected scalings", "[rod_vibration]") {
  const RodGeometry rod{0.025, 0.15, 0.205};
  for (double E : {1e9, 63.2e9, 204e9}) {
    CHECK(modulus_from_flexural_frequency_Pa(rod, flexural_frequency_hz(rod, E)) == Approx(E).epsilon(1e-14));
    CHECK(modulus_from_longitudinal_frequency_Pa(rod, longitudinal_frequency_hz(rod, E)) == Approx(E).epsilon(1e-14));
  }
  // f ~ sqrt(E): four times the modulus doubles both frequencies.
  CHECK(flexural_frequency_hz(rod, 4e10) == Approx(2.0 * flexural_frequency_hz(rod, 1e10)).epsilon(1e-14));
  // Longitudinal: f = c / (2L) with c = sqrt(E/rho); for rho = 2784 kg/m^3 and E = 63.2 GPa,
  // c = 4764.5 m/s, so f = 15.882 kHz at L = 0.15 m (hand arithmetic, 4 digits).
  CHECK(longitudinal_frequency_hz(rod, 63.2e9) == Approx(15882).epsilon(5e-4));
  // Flexural f1 ~ L^{-2} at fixed density: a rod twice as long (and twice as heavy) rings at a quarter.
  const RodGeometry longer{rod.diameter_m, 2 * rod.length_m, 2 * rod.mass_kg};
  CHECK(flexural_frequency_hz(longer, 63.2e9) == Approx(flexural_frequency_hz(rod, 63.2e9) / 4.0).epsilon(1e-14));
}

TEST_CASE("the duralumin rows of Table 3 fit the flexural model, the steel row fits no mode", "[rod_vibration]") {
  // Tables 1 and 3 print three significant figures. E = rho (2 pi f L^2/(bL)^2)^2 * 16/d^2
  // ~ m f^2 L^3 / d^4, so half a unit in the last printed digit of each gives at most
  // 0.36 % (m) + 0.36 % (f, squared) + 1.5 % (L = 0.100, cubed) + 0.8 % (d, fourth power) ~ 3 %.
  struct Row { RodGeometry rod; double f_hz, E_Pa; };
  for (const Row& r : {Row{{0.025, 0.100, 0.137}, 9880, 54.8e9}, Row{{0.025, 0.150, 0.205}, 4710, 63.2e9},
                       Row{{0.025, 0.200, 0.274}, 2740, 67.4e9}}) {
    CHECK(modulus_from_flexural_frequency_Pa(r.rod, r.f_hz) == Approx(r.E_Pa).epsilon(0.03));
  }
  // Steel, 0.778 kg, 200 mm: 112.9 kHz would need more than 1000x its 204 GPa in
  // either mode; 204 GPa itself rings at ~2.8 kHz (flexural) and ~12.7 kHz (longitudinal).
  const RodGeometry steel{0.025, 0.200, 0.778};
  CHECK(modulus_from_flexural_frequency_Pa(steel, 112.9e3) > 1000 * 204e9);
  CHECK(modulus_from_longitudinal_frequency_Pa(steel, 112.9e3) > 50 * 204e9);
  CHECK(flexural_frequency_hz(steel, 204e9) == Approx(2822).epsilon(0.01));
  CHECK(longitudinal_frequency_hz(steel, 204e9) == Approx(12683).epsilon(0.01));
}
