#include "hertzdash/simulation/run/omega_n_fixed_point.hpp"

#include "hertzdash/model/damping/laws/hongo_paper.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace hertzdash {

double implied_omega_n(OmegaNVariant variant, double K, double mass_kg, const ImpactSummary& s) {
  if (!s.separated) throw std::runtime_error("omega_n fixed point: the rod did not separate (no contact time)");
  switch (variant) {
    case OmegaNVariant::self_consistent: return hertz_natural_frequency(K, mass_kg, s.max_deformation_m);
    case OmegaNVariant::contact_time: return std::numbers::pi / s.contact_time_s;
    default: throw std::invalid_argument(std::string("implied_omega_n: not an iterated variant: ") + to_string(variant));
  }
}

OmegaNFixedPoint solve_omega_n_fixed_point(ImpactSimulator& simulator, DropTestSetup setup,
                                           const OmegaNFixedPointOptions& options) {
  const OmegaNVariant variant = setup.damping.omega_n;
  if (!is_iterated(variant))
    throw std::invalid_argument(std::string("solve_omega_n_fixed_point: not an iterated variant: ") +
                                to_string(variant));
  const double K = hertz_stiffness(setup);
  const double v0 = approach_speed(setup);
  OmegaNFixedPoint r;
  double w = hertz_natural_frequency(K, setup.mass_kg, paper_peak_deformation(K, setup.mass_kg, v0, setup.restitution));
  r.history.push_back(w);
  double previous_step = NAN;
  while (r.iterations < options.max_iterations) {
    setup.damping.omega_n_rad_per_s = w;
    ++r.iterations;
    double next = NAN;
    try {
      r.summary = simulator.run<HongoPaper>(setup);
      next = implied_omega_n(variant, K, setup.mass_kg, r.summary);
    } catch (const std::runtime_error& e) {
      r.omega_n_rad_per_s = w;
      r.failure = std::string("at omega_n = ") + std::to_string(w) + " rad/s: " + e.what();
      return r;
    }
    const double step = next - w;
    if (std::isfinite(previous_step) && previous_step != 0) r.contraction = std::abs(step / previous_step);
    previous_step = step;
    r.relative_change = std::abs(step) / next;
    r.history.push_back(next);
    if (r.relative_change <= options.rtol) {
      // The last run used w; next differs from it by at most rtol relative.
      r.converged = true;
      r.omega_n_rad_per_s = w;
      return r;
    }
    w = next;
  }
  r.omega_n_rad_per_s = w;
  r.failure = "no convergence in " + std::to_string(options.max_iterations) + " iterations";
  return r;
}

OmegaNFixedPoint run_paper_law(ImpactSimulator& simulator, const DropTestSetup& setup,
                               const OmegaNFixedPointOptions& options, std::vector<TraceSample>* trace) {
  if (is_iterated(setup.damping.omega_n)) {
    OmegaNFixedPoint r = solve_omega_n_fixed_point(simulator, setup, options);
    if (trace && r.converged) {
      DropTestSetup final_setup = setup;
      final_setup.damping.omega_n_rad_per_s = r.omega_n_rad_per_s;
      simulator.run<HongoPaper>(final_setup, trace);
    }
    return r;
  }
  OmegaNFixedPoint r;
  r.summary = simulator.run<HongoPaper>(setup, trace);
  r.iterations = 1;
  r.converged = true;
  const ImpactConditions c{hertz_stiffness(setup), setup.mass_kg, approach_speed(setup), setup.restitution};
  r.omega_n_rad_per_s = paper_law_natural_frequency(c, setup.damping);
  r.history = {r.omega_n_rad_per_s};
  return r;
}

}  // namespace hertzdash
