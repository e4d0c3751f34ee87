#include "validation/common/paper_law_elasticities.hpp"

#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace hertzdash {

std::string_view elasticity_parameter_name(int p) {
  constexpr std::array<std::string_view, elasticity_parameter_count> names{"ball_E", "ball_nu", "restitution",
                                                                          "mass",   "height",  "ball_radius"};
  return names.at(static_cast<std::size_t>(p));
}

double& elasticity_parameter(DropTestSetup& s, int p) {
  switch (p) {
    case p_ball_E: return s.ball.E_Pa;
    case p_ball_nu: return s.ball.nu;
    case p_restitution: return s.restitution;
    case p_mass: return s.mass_kg;
    case p_height: return s.height_m;
    case p_radius: return s.ball_radius_m;
  }
  throw std::out_of_range("elasticity_parameter: no parameter " + std::to_string(p));
}

PaperLawElasticities paper_law_elasticities(const DropTestSetup& s, const ContactSensitivityOptions& options) {
  validate(s);
  if (s.damping.omega_n != OmegaNVariant::paper)
    throw InvalidParameter("omega-n", to_string(s.damping.omega_n), "paper for the elasticities (eq. 11)");
  if (s.impact_velocity_mps) throw InvalidParameter("impact-velocity", "given", "absent: v0 comes from h");
  if (s.no_tension) throw InvalidParameter("no-tension", "set", "absent: the contact ends at x = 0");
  if (!(s.restitution < 1)) throw InvalidParameter("restitution", format_value(s.restitution), "< 1 (zeta > 0)");

  const double K = hertz_stiffness(s);
  const double v0 = approach_speed(s);
  const double e = s.restitution;
  const ImpactConditions c{K, s.mass_kg, v0, e};
  const double tau = HongoPaper(c, s.damping).time_constant_s();
  const ContactPhaseSensitivities r =
      contact_phase_sensitivities({K, tau, s.mass_kg, v0, s.gravity_mps2}, options);

  // d ln q_j / d ln p_k, q = (K, tau, m, v0), p = (E_b, nu_b, e, m, h, R).
  const double cb = compliance(s.ball), cr = compliance(s.rod);
  const double C = cb + cr;
  const double L = std::log(1.0 / e), pi2 = std::numbers::pi * std::numbers::pi;
  const double dlnzeta_dlne = s.damping.zeta_form == ZetaForm::paper ? -1.0 / L : -pi2 / (L * (pi2 + L * L));
  std::array<std::array<double, elasticity_parameter_count>, 4> dlnq{};  // [q][p]
  dlnq[q_K][p_ball_E] = cb / C;
  dlnq[q_K][p_ball_nu] = 2.0 * s.ball.nu * s.ball.nu / s.ball.E_Pa / C;
  dlnq[q_K][p_radius] = 0.5;
  dlnq[q_mass][p_mass] = 1.0;
  dlnq[q_v0][p_height] = 0.5;
  // tau = 2 zeta / omega_n: ln omega_n = 0.4 ln K - 0.4 ln m + 0.2 ln v0 + 0.1 ln(1 + e^2) + const.
  for (int k = 0; k < elasticity_parameter_count; ++k)
    dlnq[q_tau][k] = -(0.4 * dlnq[q_K][k] - 0.4 * dlnq[q_mass][k] + 0.2 * dlnq[q_v0][k]);
  dlnq[q_tau][p_restitution] = dlnzeta_dlne - 0.2 * e * e / (1 + e * e);

  const std::array<double, 4> q{K, tau, s.mass_kg, v0};
  // d ln y / d ln q_j = (q_j / y) dy/dq_j; e_effective = v_r / v0 adds -1 for q = v0.
  auto to_log = [&](const ContactGradient& d, double y) {
    std::array<double, 4> g{};
    for (int j = 0; j < 4; ++j) g[j] = q[j] / y * d[j];
    return g;
  };
  std::array<double, 4> g_e = to_log(r.d_rebound_velocity, r.rebound_velocity_mps);
  g_e[q_v0] -= 1.0;
  const std::array<double, 4> g_P = to_log(r.d_peak_force, r.peak_force_N);
  const std::array<double, 4> g_t = to_log(r.d_contact_time, r.contact_time_s);

  PaperLawElasticities out;
  out.e_effective = r.rebound_velocity_mps / v0;
  out.peak_force_N = r.peak_force_N;
  out.contact_time_s = r.contact_time_s;
  out.steps = r.steps;
  for (int k = 0; k < elasticity_parameter_count; ++k)
    for (int j = 0; j < 4; ++j) {
      out.e_effective_el[k] += g_e[j] * dlnq[j][k];
      out.peak_force_el[k] += g_P[j] * dlnq[j][k];
      out.contact_time_el[k] += g_t[j] * dlnq[j][k];
    }
  return out;
}

}  // namespace hertzdash
