#pragma once
// Damping ratio from the coefficient of restitution, eq. (6) of Hongo et al.

namespace hertzdash {

/// How zeta follows from e.
enum class ZetaForm {
  paper,  ///< eq. (6): zeta = ln(1/e^2) / (2 pi) = ln(1/e)/pi  (small-damping form)
  exact,  ///< linear oscillator half cycle, e = exp(-pi zeta / sqrt(1 - zeta^2)):
          ///< zeta = ln(1/e) / sqrt(pi^2 + ln^2(1/e))
};

/// Damping ratio zeta [-] for a restitution e in (0, 1].
double zeta_from_restitution(double e, ZetaForm form);

const char* to_string(ZetaForm form);

}  // namespace hertzdash
