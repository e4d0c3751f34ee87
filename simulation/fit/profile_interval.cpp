// Profile-likelihood intervals (simulation/fit/profile_interval.hpp): the outward search from the
// estimate and Brent's method on the profile's crossing of the threshold.
#include "hertzdash/simulation/fit/profile_interval.hpp"

#include "hertzdash/simulation/run/gsl_root.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace hertzdash {

namespace {

struct Side {
  double z = NAN;
  bool open = false;
  std::string failure;
};

// One side (direction +1 or -1): the crossing of rise(z) = threshold.
Side search(const std::function<std::optional<double>(double)>& rise, double threshold, double z0, double se_z,
            double direction, int& evaluations) {
  auto excess = [&](double z) -> std::optional<double> {
    ++evaluations;
    const std::optional<double> r = rise(z);
    if (!r || !std::isfinite(*r)) return std::nullopt;
    return *r - threshold;
  };
  double inside = z0;  // the excess is negative here: the estimate is the minimum
  for (int k = 0; k <= profile_max_doublings; ++k) {
    const double z = z0 + direction * se_z * std::ldexp(1.0, k);
    const std::optional<double> e = excess(z);
    if (!e)
      return {NAN, false,
              fmt::format("the profile could not be evaluated {:g} standard errors {} the estimate", std::ldexp(1.0, k),
                          direction > 0 ? "above" : "below")};
    if (*e < 0) {
      inside = z;
      continue;
    }
    try {
      const double lo = std::min(inside, z), hi = std::max(inside, z);
      const double root = brent_root(
          [&](double zz) {
            const std::optional<double> x = excess(zz);
            if (!x) throw std::runtime_error("the profile could not be evaluated inside the bracket");
            return *x;
          },
          lo, hi, 1e-3 * se_z, 0.0, "profile interval");
      return {root, false, {}};
    } catch (const std::runtime_error& err) {
      return {NAN, false, err.what()};
    }
  }
  return {direction * std::numeric_limits<double>::infinity(), true, {}};
}

}  // namespace

ProfileInterval profile_interval(const std::function<std::optional<double>(double z)>& rise, double threshold, double z0,
                                 double se_z, const std::function<double(double z)>& to_parameter) {
  ProfileInterval out;
  if (!(std::isfinite(se_z) && se_z > 0 && std::isfinite(threshold) && threshold > 0)) {
    out.lower = out.upper = NAN;
    out.failure = "no finite standard error or scatter to start the search from";
    return out;
  }
  const Side lower = search(rise, threshold, z0, se_z, -1.0, out.evaluations);
  const Side upper = search(rise, threshold, z0, se_z, +1.0, out.evaluations);
  out.lower = std::isnan(lower.z) ? NAN : to_parameter(lower.z);
  out.upper = std::isnan(upper.z) ? NAN : to_parameter(upper.z);
  out.lower_open = lower.open;
  out.upper_open = upper.open;
  out.failure = lower.failure.empty() ? upper.failure
                : upper.failure.empty() ? lower.failure
                                        : lower.failure + "; " + upper.failure;
  return out;
}

}  // namespace hertzdash
