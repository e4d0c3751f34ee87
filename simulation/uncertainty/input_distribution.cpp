#include "hertzdash/simulation/uncertainty/input_distribution.hpp"

#include "hertzdash/model/invalid_parameter.hpp"

#include <gsl/gsl_cdf.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace hertzdash {

namespace {

// The standard normal quantile of the probability between F(a) and F(b) at fraction u, for
// standardised bounds a < b. Where both bounds lie in the upper tail the complementary CDF keeps
// the digits that 1 - F would lose (a bound 8 sd above the mean has F = 1 - 6e-16).
double truncated_standard_normal_quantile(double u, double a, double b) {
  if (a > 0) {
    const double qa = gsl_cdf_ugaussian_Q(a), qb = gsl_cdf_ugaussian_Q(b);
    return gsl_cdf_ugaussian_Qinv(qa - u * (qa - qb));
  }
  const double pa = gsl_cdf_ugaussian_P(a), pb = gsl_cdf_ugaussian_P(b);
  return gsl_cdf_ugaussian_Pinv(pa + u * (pb - pa));
}

}  // namespace

double InputDistribution::quantile(double u) const {
  switch (kind) {
    case DistributionKind::uniform: return p1 + u * (p2 - p1);
    case DistributionKind::normal:
      return std::clamp(p1 + p2 * truncated_standard_normal_quantile(u, (lower - p1) / p2, (upper - p1) / p2), lower,
                        upper);
    case DistributionKind::lognormal: {
      const double a = lower > 0 ? (std::log(lower) - p1) / p2 : -INFINITY;
      const double b = (std::log(upper) - p1) / p2;
      return std::clamp(std::exp(p1 + p2 * truncated_standard_normal_quantile(u, a, b)), lower, upper);
    }
  }
  return NAN;
}

InputDistribution uniform_distribution(double min, double max) {
  return {.kind = DistributionKind::uniform, .p1 = min, .p2 = max, .lower = min, .upper = max};
}

InputDistribution normal_distribution(double mean, double sd, double lower, double upper) {
  return {.kind = DistributionKind::normal, .p1 = mean, .p2 = sd, .lower = lower, .upper = upper};
}

InputDistribution lognormal_distribution(double log_mean, double log_sd, double lower, double upper) {
  return {.kind = DistributionKind::lognormal, .p1 = log_mean, .p2 = log_sd, .lower = lower, .upper = upper};
}

DistributionKind parse_distribution_kind(std::string_view kind, const std::string& name) {
  for (DistributionKind k : {DistributionKind::uniform, DistributionKind::normal, DistributionKind::lognormal})
    if (kind == to_string(k)) return k;
  throw InvalidParameter(name + ".distribution", std::string(kind), "one of: uniform, normal, lognormal");
}

std::string to_string(DistributionKind kind) {
  switch (kind) {
    case DistributionKind::uniform: return "uniform";
    case DistributionKind::normal: return "normal";
    case DistributionKind::lognormal: return "lognormal";
  }
  return "?";
}

void validate(const InputDistribution& d, const std::string& name) {
  auto require_finite = [&](const char* what, double v) {
    if (!std::isfinite(v)) throw InvalidParameter(name + "." + what, format_value(v), "a finite number");
  };
  switch (d.kind) {
    case DistributionKind::uniform:
      require_finite("min", d.p1);
      require_finite("max", d.p2);
      if (!(d.p1 < d.p2)) throw InvalidParameter(name + ".max", format_value(d.p2), "greater than min = " + format_value(d.p1));
      return;
    case DistributionKind::normal:
      require_finite("mean", d.p1);
      require_positive(name + ".sd", d.p2, "the parameter's unit");
      break;
    case DistributionKind::lognormal:
      require_finite("log_mean", d.p1);
      require_positive(name + ".log_sd", d.p2, "of ln X");
      if (!(d.lower >= 0)) throw InvalidParameter(name + ".min", format_value(d.lower), ">= 0 (a lognormal value is positive)");
      break;
  }
  if (std::isnan(d.lower) || std::isnan(d.upper) || !(d.lower < d.upper))
    throw InvalidParameter(name + ".max", format_value(d.upper), "greater than min = " + format_value(d.lower));
  // The truncation must keep some probability (a normal truncated 40 sd from its mean keeps none
  // that a double can hold).
  const double a = d.kind == DistributionKind::normal ? (d.lower - d.p1) / d.p2
                   : d.lower > 0                      ? (std::log(d.lower) - d.p1) / d.p2
                                                      : -INFINITY;
  const double b = ((d.kind == DistributionKind::normal ? d.upper : std::log(d.upper)) - d.p1) / d.p2;
  const double mass = a > 0 ? gsl_cdf_ugaussian_Q(a) - gsl_cdf_ugaussian_Q(b) : gsl_cdf_ugaussian_P(b) - gsl_cdf_ugaussian_P(a);
  if (!(mass > 0))
    throw InvalidParameter(name + ".min", format_value(d.lower),
                           "a truncation [min, max] with probability > 0 under the distribution");
}

std::string describe(const InputDistribution& d) {
  std::string s;
  switch (d.kind) {
    case DistributionKind::uniform: return fmt::format("uniform(min = {:g}, max = {:g})", d.p1, d.p2);
    case DistributionKind::normal: s = fmt::format("normal(mean = {:g}, sd = {:g})", d.p1, d.p2); break;
    case DistributionKind::lognormal: s = fmt::format("lognormal(log_mean = {:g}, log_sd = {:g})", d.p1, d.p2); break;
  }
  const bool lower = d.kind == DistributionKind::lognormal ? d.lower > 0 : std::isfinite(d.lower);
  if (lower || std::isfinite(d.upper)) s += fmt::format(" truncated to [{:g}, {:g}]", d.lower, d.upper);
  return s;
}

}  // namespace hertzdash
