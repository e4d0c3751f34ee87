#pragma once
// How the paper's law picks the natural frequency omega_n of the Hertz contact,
// eqs. (7)-(11) of Hongo et al. The paper's choice (eq. 11) is one modelling
// assumption among several; the sensitivity study compares them.
#include "hertzdash/model/invalid_parameter.hpp"

#include <array>
#include <string>
#include <string_view>

namespace hertzdash {

/// omega_n = sqrt((4K/(5m)) X^{1/2}) (eq. 9, corrected) at an amplitude X taken from:
enum class OmegaNVariant {
  paper,            ///< eq. (10)-(11): strain energy = mean of the kinetic energies before and after impact
  impact_energy,    ///< strain energy = impact energy (1/2) m v0^2 (e = 1 in eq. 10)
  rebound_energy,   ///< strain energy = rebound energy (1/2) m (e v0)^2
  self_consistent,  ///< X = the simulated maximum deformation of the impact itself (fixed point)
  contact_time,     ///< not from X: omega_n = pi / t_c, t_c the simulated contact time (fixed point)
  as_printed,       ///< the erratum: eq. (9) as transcribed, sqrt(4K/(5m)) X^{1/2}, X from eq. (10);
                    ///< dimensionally wrong (1/s * m^{1/4}), evaluated numerically in SI units
};

inline constexpr std::array<OmegaNVariant, 6> all_omega_n_variants{
    OmegaNVariant::paper,           OmegaNVariant::impact_energy, OmegaNVariant::rebound_energy,
    OmegaNVariant::self_consistent, OmegaNVariant::contact_time,  OmegaNVariant::as_printed};

/// CLI spelling, e.g. "self-consistent".
inline const char* to_string(OmegaNVariant v) {
  switch (v) {
    case OmegaNVariant::paper: return "paper";
    case OmegaNVariant::impact_energy: return "impact-energy";
    case OmegaNVariant::rebound_energy: return "rebound-energy";
    case OmegaNVariant::self_consistent: return "self-consistent";
    case OmegaNVariant::contact_time: return "contact-time";
    case OmegaNVariant::as_printed: return "as-printed";
  }
  return "?";
}

/// The variants whose omega_n depends on the simulated impact: they take an explicit
/// omega_n (DampingSettings::omega_n_rad_per_s) found by a fixed-point iteration.
inline bool is_iterated(OmegaNVariant v) {
  return v == OmegaNVariant::self_consistent || v == OmegaNVariant::contact_time;
}

/// Parses the CLI spelling; throws InvalidParameter(option, ...) listing the valid names.
inline OmegaNVariant parse_omega_n_variant(std::string_view text, const std::string& option = "omega-n") {
  std::string names;
  for (OmegaNVariant v : all_omega_n_variants) {
    if (text == to_string(v)) return v;
    names += (names.empty() ? "" : ", ") + std::string(to_string(v));
  }
  throw InvalidParameter(option, std::string(text), "one of: " + names);
}

}  // namespace hertzdash
