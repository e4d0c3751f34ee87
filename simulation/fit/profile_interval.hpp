#pragma once
// Profile-likelihood intervals of a least-squares fit's parameters: where the quadratic (Wald)
// interval, estimate +- standard error, misdescribes the data (a model far from linear in the
// parameter over its standard error, an estimate near a bound of its range), the set of values
// the data do not reject.
//
// Rule. For parameter j, the profile S_j(t) is the least sum of squared weighted residuals with
// parameter j held at t and every other parameter re-optimised. The 1-sigma profile interval is
//   { t : S_j(t) - S_min <= s^2 },  s^2 = S_min / (n - p),
// the values where the profile rises by one s^2 above the minimum (Bates and Watts 1988,
// "Nonlinear Regression Analysis and Its Applications", Wiley, section 6.1: the profile t
// statistic tau(t) = sign(t - estimate) sqrt(S_j(t) - S_min) / s, here within +-1; Venzon and
// Moolgavkar 1988, Appl. Statist. 37, 87-94, the likelihood-ratio form with sigma known, where
// the rise is chi^2 = 1 and s^2 is replaced by 1). The fits (trace_fit.hpp, restitution_fit.hpp)
// scale their covariance by s^2 whether or not the weights are given, so the threshold is s^2
// in both cases: with weights that describe the noise s^2 is 1 in expectation (Venzon and
// Moolgavkar's rule), and a model linear in its parameters gets exactly its Wald interval,
// S_j(t) = S_min + (t - estimate)^2 / C_jj with C = (J^T J)^-1, so S_j - S_min = s^2 at
// t = estimate +- s sqrt(C_jj) = estimate +- standard error. The interval is invariant under a
// reparametrisation (the Wald interval is not): it is searched in the fit's unbounded variable z.
//
// Search. From the estimate z0, trial points z0 +- se_z 2^k, k = 0, 1, ... (se_z the standard
// error in z) until the profile exceeds the threshold; the crossing is then located by Brent's
// method between the last two trials to 1e-3 se_z. A side the profile does not cross within
// profile_max_doublings (2^12 standard errors in z; in a logit or log variable far enough, for
// any standard error not tiny, to reach the parameter's bound to rounding) is open: the data do not bound the parameter there, and its end is the
// parameter's bound. A side where the profile cannot be evaluated (the model fails, a re-fit
// fails) has no end (NaN) and a reason.
#include <functional>
#include <optional>
#include <string>

namespace hertzdash {

/// A 1-sigma profile-likelihood interval of one parameter [the parameter's unit].
struct ProfileInterval {
  double lower = 0, upper = 0;           ///< NaN: not found (failure says why); the bound where open
  bool lower_open = false, upper_open = false;  ///< the profile never rose by the threshold: the end is the bound
  int evaluations = 0;                   ///< profile evaluations (each a model run or a re-fit)
  std::string failure;                   ///< why a side was not found, else empty
};

/// Most doublings of the trial step (the search's reach: se_z 2^max_doublings).
inline constexpr int profile_max_doublings = 12;

/// The interval of one parameter in its unbounded variable z: `rise(z)` is S_j at the parameter's
/// value p(z) less S_min (nothing where it cannot be evaluated), `threshold` s^2, `z0` the
/// estimate and `se_z` its standard error in z (finite, > 0), `to_parameter` the map z -> p
/// (increasing), applied to the ends found; an open side's end is to_parameter(-+infinity).
ProfileInterval profile_interval(const std::function<std::optional<double>(double z)>& rise, double threshold, double z0,
                                 double se_z, const std::function<double(double z)>& to_parameter);

}  // namespace hertzdash
