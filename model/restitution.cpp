#include "hertzdash/model/restitution.hpp"

#include <cmath>
#include <numbers>

namespace hertzdash {

double zeta_from_restitution(double e, ZetaForm form) {
  const double L = std::log(1.0 / e);
  switch (form) {
    case ZetaForm::paper: return L / std::numbers::pi;
    case ZetaForm::exact: return L / std::sqrt(std::numbers::pi * std::numbers::pi + L * L);
  }
  return NAN;
}

const char* to_string(ZetaForm form) { return form == ZetaForm::paper ? "paper" : "exact"; }

double clamped_restitution(double zeta) {
  const double s = std::sqrt(1 - zeta * zeta);
  const double theta_F = std::numbers::pi - std::atan2(2 * zeta * s, 1 - 2 * zeta * zeta);
  return std::exp(-zeta / s * theta_F);
}

double zeta_from_clamped_restitution(double e) {
  double lo = 0, hi = 1;  // clamped_restitution(lo) >= e > clamped_restitution(hi)
  while (hi - lo > 1e-16) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    (clamped_restitution(mid) >= e ? lo : hi) = mid;
  }
  return lo;
}

}  // namespace hertzdash
