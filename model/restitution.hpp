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

/// The restitution of the linear oscillator m x'' + c x' + k x = 0 whose force is clamped at zero
/// (no attraction: contact ends where k x + c x' first vanishes), zeta = c / (2 sqrt(k m)) in
/// [0, 1): with s = sqrt(1 - zeta^2), e = exp(-(zeta/s) theta_F), theta_F = pi - atan2(2 zeta s,
/// 1 - 2 zeta^2) (derived in tests/test_damping_law_restitution.cpp). tsuji-dem's x^{1/4} dashpot
/// runs the same phase curve, so this is its clamped e too. Decreasing from 1 (zeta = 0) towards
/// e^{-2} (zeta -> 1).
double clamped_restitution(double zeta);
/// The zeta in [0, 1) whose clamped_restitution is e, e in (e^{-2}, 1] (bisection to round-off).
double zeta_from_clamped_restitution(double e);

}  // namespace hertzdash
