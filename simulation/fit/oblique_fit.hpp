#pragma once
// Fitting an oblique impact's tangential parameters to measured rebound angles (the angle of
// the contact point's velocity after the impact against the incident angle, as Kharaz, Gorham and
// Salman (2001) measured it; data/external/chung-ooi-2011/README.md), by the fit engine
// (fit_engine.hpp): weighted nonlinear least squares of the rebound angle, one oblique impact
// (simulation/run/oblique_impact.hpp) per row.
//
// Model. At each row's incident angle, the rebound angle of `base` (its sphere, flat, normal law,
// tangential model, speed and spin) with the fitted parameters replaced: Coulomb's mu (`friction`),
// the sphere's Poisson ratio (`ball-nu`: Mindlin's ratio of tangential to normal compliance
// 2 (1 - nu)/(2 - nu), and E* a little), and, for the linear spring, its stiffness
// (`tangential-stiffness` [N/m]). The rebound angle of
// a sticking contact oscillates with k_t (through cos(Omega t_c), Omega^2 = k_t/m_t), so the least
// squares in (mu, k_t) have many minima: on a virtual experiment (mu = 0.2, k_t = 2e6 N/m, four
// angles, the test-4 sphere) the sum of squares is 0 at the truth, 3.4 deg^2 at mu = 0.3, but 1245
// at k_t = 6e6 and 168 at (0.036, 2e8), where a joint fit from the default start stopped (and from
// the best of a five-point scan in k_t). A joint fit therefore starts from a fine scan: mu alone
// fitted at k_t0 10^(i/20), i = -30..30 (k_t0 the given stiffness, else Mindlin's 8 G* a of the
// head-on impact), the best point starting the joint fit. The runs use Dormand-Prince at rtol
// 1e-10, atol 1e-12 of the state's scales: a rebound angle to about 1e-8 degrees, smooth at the
// scale of the engine's difference step (1e-6 in the unbounded variables).
//
// Parameters. `friction`, by default in [1e-3, 2] (a logit), started at 0.1. Residuals: measured
// minus model in degrees, one common sigma estimated (the rows carry no scatter of their own).
// Folds: each row (leave-one-out), no nuisances. A tangential model comparison is one fit per
// model: same parameters, so AIC orders them by their residual sum of squares.
#include "hertzdash/simulation/fit/fit_engine.hpp"
#include "hertzdash/simulation/run/oblique_impact.hpp"

#include <string>
#include <vector>

namespace hertzdash {

/// Measured rebound angles: where they come from, and the incident and rebound angles [degrees].
struct ReboundAngleTable {
  std::string source;
  std::vector<double> incidence_angle_deg, rebound_angle_deg;
};

/// Fit `table` with the oblique impacts of `base` (its incidence angle replaced by each row's);
/// settings.parameters empty: `friction` in [1e-3, 2]. Throws InvalidParameter("fit", ...) for a
/// parameter other than `friction`, `ball-nu` and `tangential-stiffness` (the last with
/// linear-spring only),
/// and DataError for a table with no more rows than parameters, or rows of different lengths.
FitResult fit_rebound_angles(const ReboundAngleTable& table, const ObliqueImpactSpec& base, const FitSettings& settings);

/// The solver of the fit's runs: rtol 1e-10, atol 1e-12.
SolverSettings oblique_fit_solver();

}  // namespace hertzdash
