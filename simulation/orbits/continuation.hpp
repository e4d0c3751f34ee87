#pragma once
// Continuation of periodic orbits in a parameter lambda (docs/orbits.md): the fixed points of the
// stroboscopic map P^N(z; lambda) (simulation/orbits/stroboscopic_map.hpp) followed as a curve in
// (z, lambda) by pseudo-arclength, through folds.
//
// Variables, scaled: zeta = z / scale (the rig's scales) and mu = (lambda - from)/(to - from), so
// that the branch runs from mu = 0 towards mu = 1; x = (zeta, mu), F(x) = (P^N(z) - z)/scale.
// The Jacobian [dF/dzeta, dF/dmu]: dF/dzeta = S^-1 (M - I) S from the map's own monodromy M
// (saltation matrices, no differences); dF/dmu by a central difference in mu alone (step 1e-6;
// error ~1e-10; one-sided where a neighbour lies past a grazing), which only steers: points and
// multipliers come from M.
//   - tangent t: the null vector of the n x (n + 1) Jacobian (n the section's dimension: the
//     cross product of its rows for n = 2, the SVD beyond; simulation/orbits/section_algebra.hpp),
//     oriented along the last one;
//   - predictor x + h t; corrector: Newton on [F(x); t.(x - x_pred)] = 0 (bordered), converged
//     where |F| < 1e-10 and the step < 1e-9;
//   - step h from 0.01, times 1.3 after a corrector of at most 3 steps, halved after a failed one
//     or a turn of the tangent by more than 25 degrees, at most 0.03 (so that two events of one
//     kind, whose sign changes would cancel, are unlikely within a step) and at least 1e-7 (below
//     it the branch ends, with a note).
// Events between two points a and b, each located by bisection on the step from a (to 1e-12 in
// arclength), its parameter reported:
//   - fold: det(M - I) changes sign (a multiplier through +1; the branch turns in lambda);
//   - period doubling: det(M + I) changes sign (a multiplier through -1). The branch of period 2N
//     is followed from there too (while 2N <= max_period): at the branch point it leaves along
//     (v, 0), v the eigenvector of M for -1, P^{2N} having a pitchfork there;
//   - Neimark-Sacker: a complex pair crossing the unit circle, the product of |lambda|^2 - 1 over
//     the complex pairs (each by more than 1e-12) changing sign between points with as many
//     pairs (in two dimensions det M - 1: a prescribed box with e < 1 has |lambda|^2 = det M < 1,
//     none; the damper's four can);
//   - grazing: the orbit's impacts per period change on the way (an impact born at zero relative
//     speed, or a flight touching a wall: the map is not smooth there), and the branch ends there.
//     From the side where the orbit has fewer impacts (the new one not yet born) the corrector
//     converges up to it: bisection on the step, taken where the located orbit is within 1e-6 of
//     the rig's scales of grazing (else the corrector had jumped to another branch, and a shorter
//     step follows). From the side of the impact that vanishes the map's Jacobian grows like
//     1/(impact speed) and Newton fails short of it: the steps shrink towards it (to 1e-5), and,
//     where the orbit's closeness to grazing (its slowest impact or closest flight, in the rig's
//     scales) is below 1e-2 and falling, the grazing is its secant to zero through the last two
//     points.
// A branch also ends on leaving [from, to] (the last point corrected onto lambda = to), on an
// impact reaching the section phase (to 1e-3 of a cycle: the map jumps; choose another
// section phase), or after max_points points in all.
#include "hertzdash/simulation/orbits/periodic_orbit.hpp"

#include <complex>
#include <functional>
#include <string>
#include <vector>

namespace hertzdash {

/// The sequence at parameter value lambda (throws InvalidParameter outside its declared range).
using SequenceFamily = std::function<ImpactSequenceSpec(double lambda)>;

struct ContinuationOptions {
  double from = 0, to = 1;      ///< the parameter's range, from the start towards `to`
  int period = 1;               ///< N, drive cycles of the first branch
  double section_phase = 0;     ///< in [0, 1)
  Eigen::VectorXd start;        ///< the orbit at `from` (or near it: Newton corrects it first)
  Eigen::VectorXd scale;        ///< the state's scales
  int max_points = 2000;        ///< points over all branches
  int max_period = 16;          ///< doubled branches followed while their period is at most this
};

/// One point of a branch.
struct BranchPoint {
  int branch = 0;   ///< 0 the first, then each doubled branch in the order found
  int period = 1;   ///< drive cycles
  double parameter = 0;
  Eigen::VectorXd state;                          ///< z at the section
  std::vector<std::complex<double>> multipliers;  ///< largest modulus first
  bool stable = false;
  int impacts = 0;  ///< per period
  std::vector<double> impact_phases;  ///< the drive phase of each, in the order of the period
  double min_impact_speed_mps = 0, min_flight_gap_m = 0;
};

enum class BranchEventType { fold, period_doubling, neimark_sacker, grazing };
/// "fold", "period-doubling", "neimark-sacker", "grazing".
const char* to_string(BranchEventType type);

struct BranchEvent {
  BranchEventType type = BranchEventType::fold;
  double parameter = 0;
  int branch = 0, period = 1;
  Eigen::VectorXd state;
};

struct Continuation {
  std::vector<BranchPoint> points;  ///< branch by branch, each in arclength order
  std::vector<BranchEvent> events;  ///< in the order found
  std::vector<std::string> ends;    ///< per branch, why it ended
};

/// The branches from the orbit near `options.start` at `from` (see above). std::runtime_error if
/// Newton finds no orbit at `from`; std::invalid_argument unless start and scale have 2 entries.
Continuation continue_periodic_orbits(const SequenceFamily& family, const ContinuationOptions& options);

}  // namespace hertzdash
