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

}  // namespace hertzdash
