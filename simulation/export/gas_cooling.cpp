// A granular gas's cooling predicted from e(g) (simulation/export/gas_cooling.hpp).
#include "hertzdash/simulation/export/gas_cooling.hpp"

#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hertzdash {

RestitutionCurve::RestitutionCurve(const EngineContact& contact, double g_min_mps, double g_max_mps, int points) {
  if (points < 2 || !(g_min_mps > 0 && g_max_mps > g_min_mps)) throw std::invalid_argument("RestitutionCurve: bad speed range");
  SolverSettings accurate;
  accurate.integrator = IntegratorKind::gbs8_regularized;
  accurate.rtol = 1e-10;
  accurate.atol = 1e-10;
  ImpactSimulator simulator(accurate);
  EngineContact at = contact;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < points; ++i) {
    at.speed_mps = g_min_mps * std::pow(g_max_mps / g_min_mps, static_cast<double>(i) / (points - 1));
    const double e = simulator.run(engine_impact_setup(at, EngineImpactKind::sphere_sphere), contact.law).e_effective;
    log_g_.push_back(std::log(at.speed_mps));
    log_one_minus_e_.push_back(std::log(std::max(1 - e, 1e-300)));
  }
  seconds_per_impact_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / points;
  elastic_ = std::all_of(log_one_minus_e_.begin(), log_one_minus_e_.end(), [](double l) { return l < -600; });
}

double RestitutionCurve::operator()(double g_mps) const {
  if (elastic_) return 1.0;
  const double x = std::log(g_mps);
  const std::size_t n = log_g_.size();
  std::size_t i = std::upper_bound(log_g_.begin(), log_g_.end(), x) - log_g_.begin();
  i = std::clamp<std::size_t>(i, 1, n - 1);  // the segment [i-1, i], the end ones extended
  const double w = (x - log_g_[i - 1]) / (log_g_[i] - log_g_[i - 1]);
  return 1 - std::exp(log_one_minus_e_[i - 1] + w * (log_one_minus_e_[i] - log_one_minus_e_[i - 1]));
}

double cooling_rate_J_per_s(double T_J, double mass_kg, double diameter_m, double number_density_per_m3, double chi,
                            const RestitutionCurve& e) {
  // int_0^inf p(g) g^3 (1 - e^2) dg = s^3 int_0^inf phi(u) u^3 (1 - e(s u)^2) du, phi the standard
  // normal density; Simpson on [0, 10] (the Gaussian tail beyond weighs below 1e-20).
  const double s = std::sqrt(2 * T_J / mass_kg);
  constexpr int intervals = 400;
  constexpr double u_max = 10, h = u_max / intervals;
  double sum = 0;
  for (int i = 0; i <= intervals; ++i) {
    const double u = i * h, eu = u == 0 ? 1.0 : e(s * u);
    const double f = std::exp(-u * u / 2) / std::sqrt(2 * std::numbers::pi) * u * u * u * (1 - eu * eu);
    sum += f * (i == 0 || i == intervals ? 1 : i % 2 ? 4 : 2);
  }
  const double integral = s * s * s * sum * h / 3;
  const double n = number_density_per_m3;
  const double loss = std::numbers::pi / 2 * mass_kg * n * n * diameter_m * diameter_m * chi * integral;
  return -2 * loss / (3 * n);
}

std::vector<CoolingSample> predicted_cooling(double T0_J, double t0_s, double t1_s, int samples, double mass_kg,
                                             double diameter_m, double number_density_per_m3, double chi,
                                             const RestitutionCurve& e) {
  // y = T^{-1/2}: dy/dt = -(1/2) T^{-3/2} dT/dt.
  const auto dy = [&](double y) {
    const double T = 1 / (y * y);
    return -0.5 * std::pow(T, -1.5) * cooling_rate_J_per_s(T, mass_kg, diameter_m, number_density_per_m3, chi, e);
  };
  constexpr int substeps = 20;
  std::vector<CoolingSample> out{{t0_s, T0_J}};
  double y = 1 / std::sqrt(T0_J);
  const double dt = (t1_s - t0_s) / (samples - 1) / substeps;
  for (int k = 1; k < samples; ++k) {
    for (int j = 0; j < substeps; ++j) {
      const double k1 = dy(y), k2 = dy(y + dt / 2 * k1), k3 = dy(y + dt / 2 * k2), k4 = dy(y + dt * k3);
      y += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    out.push_back({t0_s + (t1_s - t0_s) * k / (samples - 1), 1 / (y * y)});
  }
  return out;
}

}  // namespace hertzdash
