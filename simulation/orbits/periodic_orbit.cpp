// Shooting for periodic orbits and their Floquet multipliers (simulation/orbits/periodic_orbit.hpp).
#include "hertzdash/simulation/orbits/periodic_orbit.hpp"

#include "hertzdash/simulation/orbits/section_algebra.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace hertzdash {

namespace {

constexpr double stability_margin = 1e-9;
constexpr int max_halvings = 30;

double scaled_norm(const Eigen::VectorXd& g, const Eigen::VectorXd& scale) {
  return g.cwiseQuotient(scale).cwiseAbs().maxCoeff();
}

}  // namespace

std::vector<std::complex<double>> floquet_multipliers(const Eigen::MatrixXd& monodromy) {
  return section::eigenvalues(monodromy);
}

bool is_stable(const std::vector<std::complex<double>>& multipliers) {
  return std::ranges::all_of(multipliers, [](auto l) { return std::abs(l) < 1 - stability_margin; });
}

PeriodicOrbit find_periodic_orbit(const StroboscopicMap& map, const Eigen::VectorXd& guess, const Eigen::VectorXd& scale,
                                  const ShootingOptions& options) {
  PeriodicOrbit orbit;
  Eigen::VectorXd z = guess;
  SectionImage image = map(z);
  if (!image.failure.empty()) {
    orbit.failure = "the guess: " + image.failure;
    return orbit;
  }
  double residual = scaled_norm(image.state - z, scale);
  for (;;) {
    if (residual <= options.tolerance) {
      orbit.converged = true;
      break;
    }
    if (orbit.iterations == options.max_iterations) {
      orbit.failure = fmt::format("no convergence in {} Newton steps (scaled residual {:.3g})", orbit.iterations, residual);
      break;
    }
    const Eigen::MatrixXd J = image.monodromy - Eigen::MatrixXd::Identity(z.size(), z.size());
    if (std::abs(section::det(J)) <= 1e-14 * std::pow(J.norm(), static_cast<double>(z.size()))) {
      orbit.failure = "a multiplier equals 1 (a fold): Newton's matrix M - I is singular";
      break;
    }
    const Eigen::VectorXd step = section::solve(J, z - image.state);
    bool accepted = false;
    for (double lambda = 1; !accepted && lambda >= std::ldexp(1.0, -max_halvings); lambda /= 2) {
      const Eigen::VectorXd trial = z + lambda * step;
      SectionImage next = map(trial);
      if (!next.failure.empty()) continue;
      const double r = scaled_norm(next.state - trial, scale);
      if (!(r < residual) && r > options.tolerance) continue;
      z = trial, image = std::move(next), residual = r, accepted = true;
    }
    ++orbit.iterations;
    if (!accepted) {
      orbit.failure = fmt::format("no Newton step lowers the scaled residual {:.3g}", residual);
      break;
    }
  }
  orbit.state = z;
  orbit.monodromy = image.monodromy;
  orbit.multipliers = floquet_multipliers(image.monodromy);
  orbit.stable = is_stable(orbit.multipliers);
  orbit.residual = residual;
  orbit.impacts = std::move(image.impacts);
  orbit.min_impact_speed_mps = image.min_impact_speed_mps;
  orbit.min_flight_gap_m = image.min_flight_gap_m;
  return orbit;
}

}  // namespace hertzdash
