#pragma once
// Fitting a damping law's own parameters to a restitution table (io/restitution_table.hpp;
// data/measurements/README.md, "Restitution tables"): weighted nonlinear least squares of e
// against the impact speed, by the fit engine (fit_engine.hpp), one model value per row.
//
// Model. At each distinct speed v of the table, the law's effective restitution of one impact
// at approach speed v in the contact in which `hertzdash restitution` defines it
// (calibrate_restitution.hpp: the set-up's bodies against a rigid flat, or against `rod-E` if
// given, gravity off): the run options with --impact-velocity v and the fitted parameters
// replaced, through resolve_setup and ImpactSimulator. The impacts run by gbs8 in the
// regularising variables at rtol = atol = 1e-12 (the integrator table's fall-back where a law
// cannot), so a model value is accurate to about 1e-10 and a smooth function of the parameters
// at the scale of the Jacobian's differences (central, step 1e-6 in the unbounded variables:
// an error of ~1e-10 / 1e-6 = 1e-4 of a derivative of order 1 at worst).
//
// Parameters. By default the law's own: the input e (`restitution`) for the laws that read it,
// the material time constant (`viscous-time-constant`) for a law that has one (kuwabara-kono:
// with A fixed its e falls with the speed; calibrated from e at each run's own speed it would
// not); a law with neither (the undamped `none`) has nothing to fit. Any fittable option by
// FitSettings::parameters instead (`--fit`). Starting values: the option given, else
// for `restitution` the table's mean e, for `viscous-time-constant` the A whose e at the table's
// median speed is the table's mean e (the law's calibration), else the set-up's value
// (fit_parameters.hpp).
//
// Residuals and uncertainty. r_i = (e_i - e_model(v_i)) / sd_i with sd_i the row's e_sd; a table
// without e_sd has one common, unknown sigma: sd_i = 1, and sigma^2 is estimated by
// s^2 = RSS / (n - p). The covariance is s^2 (J^T J)^-1 in both cases, s^2 = chi^2 / (n - p)
// (as the trace fit's), with e_sd at least 1 (the stated e_sd is inflated where the law does not
// explain the table to it, never scaled away: six identical rows), mapped to the parameters by
// the transforms' derivatives.
//
// Criteria. With e_sd: chi^2 = sum r_i^2, reduced chi-square chi^2 / (n - p) (about 1 if the law
// explains the table to its scatter), AIC = chi^2 + 2k, BIC = chi^2 + k ln n (k the fitted
// parameters). Without: the Gaussian likelihood with sigma fitted too, AIC = n ln(RSS / n) +
// 2 (k + 1), BIC = n ln(RSS / n) + (k + 1) ln n, RSS / n at least (1e-9)^2 (the model's accuracy:
// a noise-free synthetic table otherwise gives ln 0); the reduced chi-square is 1 by
// construction and not reported.
//
// Profile intervals and cross-validation are the engine's (fit_engine.hpp); a table's folds are
// its distinct speeds (each left out in turn, its rows predicted: no nuisances), its rows have
// no groups and the unit of a residual is the row's e_sd (1 without).
#include "hertzdash/io/restitution_table.hpp"
#include "hertzdash/simulation/fit/fit_engine.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <vector>

namespace hertzdash {

/// Refuses (InvalidParameter) the options a restitution-table fit cannot use: an elastic rod,
/// `impact-velocity` or `height` (the table gives the speeds), `gravity`, `rod-nu` without
/// `rod-E`, an iterated omega_n.
void check_restitution_fit_options(const RunOptions& o);

/// Fit the table. Validates the options like `restitution` (InvalidParameter: the rod model
/// rigid, no `impact-velocity` or `height` (the table gives the speeds), no `gravity`, a
/// closed-form omega_n variant); throws DataError for a table with no more rows than parameters.
/// The result has a point per row, x the impact speed [m/s].
FitResult fit_restitution_table(const RestitutionTable& table, const RunOptions& base, const PaperParameters& paper,
                                     const FitSettings& settings);

/// Every registered law fitted (fit_engine.hpp's compare_laws), each cross-validated with
/// settings.cross_validate.
LawComparison compare_laws_on_restitution(const RestitutionTable& table, const RunOptions& base,
                                                     const PaperParameters& paper,
                                                     const FitSettings& settings);

}  // namespace hertzdash
