#pragma once
// The iterated omega_n variants of the paper's law (OmegaNVariant): omega_n taken
// from the simulated impact itself, found as a fixed point omega = G(omega) where
// G simulates the impact with omega_n = omega and returns
//   self-consistent:  G = sqrt((4K/(5m)) X_max^{1/2})   (eq. 9 at the simulated peak deformation)
//   contact-time:     G = pi / t_c                      (half a period of the equivalent oscillator)
// Plain (Picard) iteration from the paper's eq. (11) value. It converges where G
// varies slowly with omega: omega enters only through the damping c_e ~ 1/omega,
// which changes X_max and t_c little at moderate damping; the observed contraction
// factor |G(w_k) - G(w_{k-1})| / |w_k - w_{k-1}| is reported so this can be checked.
// A fixed point need not exist: for the contact-time variant at small e, G(w) < w
// for every w at which the rod still separates (strong damping lengthens the
// contact without bound: the tensile dashpot force holds the rod), so the iterates
// drift into impacts without separation and the iteration reports failure.
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <string>
#include <vector>

namespace hertzdash {

struct OmegaNFixedPointOptions {
  double rtol = 1e-9;     ///< stop when |w_{k+1} - w_k| <= rtol w_{k+1}; keep above the solver's noise
  int max_iterations = 200;
};

/// The iteration's outcome (OmegaNIteration: iterations, converged, ...) and what it found.
struct OmegaNFixedPoint : OmegaNIteration {
  ImpactSummary summary;          ///< the impact simulated with the final omega_n
  double omega_n_rad_per_s = 0;   ///< the fixed point (last iterate)
  std::vector<double> history;    ///< w_0 (eq. 11) ... w_k
};

/// G(w) of the variant for an impact simulated with omega_n = w (summary of that run).
/// Throws std::runtime_error if the rod did not separate (no contact time).
double implied_omega_n(OmegaNVariant variant, double K, double mass_kg, const ImpactSummary& s);

/// Iterates omega_n to its fixed point for setup.damping.omega_n (an iterated variant) with
/// the paper's law; setup.damping.omega_n_rad_per_s is ignored on input. Does not throw on
/// non-convergence, an impact without separation or a solver failure: check `converged`.
OmegaNFixedPoint solve_omega_n_fixed_point(ImpactSimulator& simulator, DropTestSetup setup,
                                           const OmegaNFixedPointOptions& options = {});

/// Runs the paper's law with any omega_n variant: the closed forms directly, the iterated ones
/// through solve_omega_n_fixed_point (whose outcome is returned; for a closed form
/// iterations = 1, converged = true). ImpactSimulator::run(setup, "hongo") calls this.
OmegaNFixedPoint run_paper_law(ImpactSimulator& simulator, const DropTestSetup& setup,
                               const OmegaNFixedPointOptions& options = {},
                               std::vector<TraceSample>* trace = nullptr);

}  // namespace hertzdash
