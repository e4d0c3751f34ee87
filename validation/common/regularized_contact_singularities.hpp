#pragma once
// How far a power series of the undamped contact in the regularising variables can reach:
// the solution's complex singularities in closed form, and from them an estimate of the
// fewest Taylor series any step rule needs for the contact, against which the benchmark
// reads the Taylor path's own count (paper, Section "Performance").
//
// In the variables of model/contact_system.hpp, without damping and gravity, the
// contact is u'' = -(2K/m) u^4 (u = x^{1/2}, ' = d/dtau). Scaled to w'' = -w^4 with
// w(0) = 0, w'(0) = 1, energy gives w'^2 = 1 - (2/5) w^5, so w rises to
// w_m = (5/2)^{1/5} and falls back to 0 after the tau-duration 2 S with
//   S = int_0^{w_m} dw / sqrt(1 - (2/5) w^5) = w_m B(1/5, 1/2) / 5.
// Continued along the complex ray w = r e^{i pi/5}, where 1 - (2/5) w^5 = 1 + (2/5) r^5 > 0,
// the solution reaches w = infinity at the finite
//   s* = e^{i pi/5} int_0^inf dr / sqrt(1 + (2/5) r^5) = e^{i pi/5} w_m B(1/5, 3/10) / 5,
// a singularity (w ~ (s - s*)^{-2/3}); along the negative real ray likewise at -|s*|, and by
// the time reversal about the turning point at 2S + |s*| and 2S - s*. By the reflection formula
// Re s* = S: the nearest singularities sit straight above and below the largest compression, at
// distance Im s* = |s*| sin(pi/5), so the series there converges only out to that radius.
//   A series of order p stepped a distance h from a point whose radius of convergence is rho
// leaves a remainder of about (h/rho)^{p+1} of the solution's size (the coefficients decay
// like rho^{-k} up to a power of k), so a step rule holding that to tol steps no further
// than about rho tol^{1/(p+1)}, and the contact needs about
//   N = tol^{-1/(p+1)} int_0^{2S} ds / rho(s)
// series at least, rho(s) the distance from s to the nearest of the singularities above (at
// least the true radius, so N errs low). An estimate, not a theorem: the decay's prefactor
// is taken as 1. Damping and gravity move the singularities; N is for the undamped contact.
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numbers>

namespace hertzdash {

/// The scaled undamped contact w'' = -w^4, w(0) = 0, w'(0) = 1 (see above).
struct UndampedRegularizedContact {
  double w_max;           ///< largest w, (5/2)^{1/5}
  double half_duration;   ///< S: w returns to 0 at s = 2S
  double singular_distance;  ///< |s*|: nearest singularity from onset
  double singular_height;    ///< Im s*: nearest singularity from the turning point
};

inline UndampedRegularizedContact undamped_regularized_contact() {
  const auto beta = [](double a, double b) { return std::tgamma(a) * std::tgamma(b) / std::tgamma(a + b); };
  const double w_max = std::pow(2.5, 0.2);
  const double S = w_max * beta(0.2, 0.5) / 5, s_abs = w_max * beta(0.2, 0.3) / 5;
  return {w_max, S, s_abs, s_abs * std::sin(std::numbers::pi / 5)};
}

/// int_0^{2S} ds / rho(s) with rho the distance to the nearest of the singularities at
/// S +- i Im s*, -|s*| and 2S + |s*| (midpoint rule, 4000 panels: rho is Lipschitz and
/// bounded below by Im s*, so the sum is accurate to far better than the bound's meaning).
inline double contact_length_in_radii() {
  const UndampedRegularizedContact c = undamped_regularized_contact();
  const std::array<std::complex<double>, 4> singular{{{c.half_duration, c.singular_height},
                                                      {c.half_duration, -c.singular_height},
                                                      {-c.singular_distance, 0.0},
                                                      {2 * c.half_duration + c.singular_distance, 0.0}}};
  constexpr int panels = 4000;
  const double ds = 2 * c.half_duration / panels;
  double sum = 0;
  for (int i = 0; i < panels; ++i) {
    const std::complex<double> s((i + 0.5) * ds, 0.0);
    double rho = INFINITY;
    for (const auto& z : singular) rho = std::min(rho, std::abs(s - z));
    sum += ds / rho;
  }
  return sum;
}

/// The least number of series of order p that any step rule holding the remainder to tol
/// needs for the undamped contact (see above).
inline double least_taylor_series(double tol, int p) {
  return contact_length_in_radii() * std::pow(tol, -1.0 / (p + 1));
}

}  // namespace hertzdash
