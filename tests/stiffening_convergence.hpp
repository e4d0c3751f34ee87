#pragma once
// The soft orbit's multipliers against the rigid (instantaneous) orbit's as the contact stiffens,
// for tests/test_orbit_soft.cpp (the shaker) and tests/test_orbit_damper.cpp (the damper). The
// soft contact lasts t_c ~ K^{-2/5}, and everything it changes (the other body moving, forces
// acting during it) is O(t_c/T), so the largest multiplier's error is first order in t_c/T: a
// tenfold stiffness divides it by 10^{0.4} = 2.51. Prints k, t_c/T, |dlambda| and the observed
// order log(error ratio)/log(t_c ratio); asserts the order within 0.15 of 1 (the O((t_c/T)^2) rest
// moves it by t_c/T ~ 1e-3 here) and the error below 3 t_c/T.
#include "hertzdash/simulation/orbits/periodic_orbit.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

namespace hertzdash::test {

/// `soft_orbit(k)`: the soft orbit with the contact's moduli times k (1, 10, 100), `impacts` a
/// period, f [Hz] the drive's; the largest multipliers a complex pair in both (their upper halves compared).
template <class SoftOrbit>
void check_stiffening_convergence(const PeriodicOrbit& rigid, double f_Hz, std::size_t impacts, SoftOrbit&& soft_orbit) {
  REQUIRE(rigid.converged);
  auto upper = [](const PeriodicOrbit& o) { return o.multipliers[0].imag() >= 0 ? o.multipliers[0] : o.multipliers[1]; };
  std::printf("instantaneous multiplier %.9f %+.9fi\n%8s %12s %12s %8s\n", upper(rigid).real(), upper(rigid).imag(), "k",
              "t_c/T", "|dlambda|", "order");
  double last_error = 0, last_tc = 0;
  for (const double k : {1.0, 10.0, 100.0}) {
    const PeriodicOrbit soft = soft_orbit(k);
    INFO(soft.failure);
    REQUIRE(soft.converged);
    REQUIRE(soft.impacts.size() == impacts);
    const double tc = soft.impacts[0].contact_time_s * f_Hz;
    const double error = std::abs(upper(soft) - upper(rigid));
    const double order = last_error > 0 ? std::log(error / last_error) / std::log(tc / last_tc) : 0;
    std::printf("%8g %12.4e %12.4e %8.3f\n", k, tc, error, order);
    CHECK(error < 3 * tc);
    if (last_error > 0) CHECK(order == Approx(1.0).margin(0.15));
    last_error = error, last_tc = tc;
  }
}

}  // namespace hertzdash::test
