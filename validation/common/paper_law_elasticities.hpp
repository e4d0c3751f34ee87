#pragma once
// Local sensitivities of the paper's impact to its physical inputs, as elasticities
// d ln y / d ln p, from CVODES forward sensitivities of the contact phase
// (contact_sensitivity.hpp) and the chain rule through the paper's closed forms.
//
// The contact phase depends on p only through q = (K, tau, m, v0):
//   K   = (4 sqrt(R)/3) / ((1 - nu_b^2)/E_b + (1 - nu_r^2)/E_r)          eq. (3)
//   v0  = sqrt(2 g h)                                                      free fall
//   tau = 2 zeta(e) / omega_n,   ln omega_n = 0.4 ln K - 0.4 ln m + 0.2 ln v0 + 0.1 ln(1 + e^2) + const
//                                                                          eqs. (6), (11)
// so d ln q / d ln p is a small table of closed forms:
//   p = E_b:  d ln K = c_b / C (c_b = (1 - nu_b^2)/E_b, C the compliance sum),  d ln tau = -0.4 d ln K
//   p = nu_b: d ln K = (2 nu_b^2 / E_b) / C,                                     d ln tau = -0.4 d ln K
//   p = R:    d ln K = 1/2,                                                      d ln tau = -0.2
//   p = m:    d ln m = 1,                                                        d ln tau = +0.4
//   p = h:    d ln v0 = 1/2,                                                     d ln tau = -0.1
//   p = e:    d ln tau = d ln zeta/d ln e - 0.2 e^2/(1 + e^2), with d ln zeta/d ln e = -1/L
//             (eq. 6, L = ln(1/e)) or -pi^2/(L (pi^2 + L^2)) (exact relation).
// Outputs y: e_effective = v_r / v0, peak force, contact time.
// Only the paper's omega_n assumption (eq. 11), free fall from h, no tension clamp.
#include "hertzdash/model/drop_test_setup.hpp"
#include "validation/common/contact_sensitivity.hpp"

#include <array>
#include <string_view>

namespace hertzdash {

/// The inputs whose elasticities are reported, in this order.
enum ElasticityParameter : int { p_ball_E = 0, p_ball_nu, p_restitution, p_mass, p_height, p_radius };
inline constexpr int elasticity_parameter_count = 6;
/// Column names (letters and underscores), e.g. "ball_E".
std::string_view elasticity_parameter_name(int p);

/// The set-up's value of parameter p (E_b [Pa], nu_b, e, m [kg], h [m], R [m]), to read or perturb.
double& elasticity_parameter(DropTestSetup& s, int p);

using Elasticities = std::array<double, elasticity_parameter_count>;  ///< d ln y / d ln p

struct PaperLawElasticities {
  double e_effective = 0, peak_force_N = 0, contact_time_s = 0;
  Elasticities e_effective_el{}, peak_force_el{}, contact_time_el{};
  long steps = 0;  ///< CVODES steps
};

/// Throws InvalidParameter for a set-up outside the stated scope, std::runtime_error on a
/// solver failure.
PaperLawElasticities paper_law_elasticities(const DropTestSetup& setup, const ContactSensitivityOptions& options = {});

}  // namespace hertzdash
