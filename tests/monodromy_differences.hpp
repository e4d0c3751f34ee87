#pragma once
// A stroboscopic map's monodromy against central differences of the map itself, for the orbit
// tests (tests/test_orbits.cpp, test_orbit_soft.cpp, test_orbit_damper.cpp): entry (i, j) in the
// state's scales s, d(z_i/s_i)/d(z_j/s_j), with steps 1e-6 of the scales. The differences err by
// O(h^2 P''') plus the map's own error over the step (round-off O(eps/h) for instantaneous impacts;
// the contacts' rtol over h for soft ones): each caller states its tolerance from those.
#include "hertzdash/simulation/orbits/stroboscopic_map.hpp"

#include <catch2/catch.hpp>

#include <cmath>

namespace hertzdash::test {

/// Checks every entry within `tolerance` (1 + |difference|), the neighbours having the image's
/// impacts; returns the image at z.
inline SectionImage require_monodromy_matches_differences(const StroboscopicMap& map, const Eigen::VectorXd& z,
                                                          const Eigen::VectorXd& s, double tolerance) {
  SectionImage image = map(z);
  REQUIRE(image.failure.empty());
  const Eigen::Index n = z.size();
  for (Eigen::Index j = 0; j < n; ++j) {
    Eigen::VectorXd dz = Eigen::VectorXd::Zero(n);
    dz(j) = 1e-6 * s(j);
    const SectionImage plus = map(z + dz), minus = map(z - dz);
    REQUIRE(plus.impacts.size() == image.impacts.size());
    REQUIRE(minus.impacts.size() == image.impacts.size());
    for (Eigen::Index i = 0; i < n; ++i) {
      const double fd = (plus.state(i) - minus.state(i)) / (2 * dz(j)) * s(j) / s(i);
      CHECK(std::abs(image.monodromy(i, j) * s(j) / s(i) - fd) < tolerance * (1 + std::abs(fd)));
    }
  }
  return image;
}

}  // namespace hertzdash::test
