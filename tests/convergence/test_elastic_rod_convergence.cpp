// Convergence of the elastic rod in its number of elements N (ctest label `convergence`).
//
// The lumped-mass bar's free-free frequencies are known in closed form,
//   w_k(N) = (2 c / h) sin(k pi / (2 N)),  h = L / N,
// and expand as w_k(N) = (k pi c / L) (1 - (k pi / N)^2 / 24 + O(N^-4)): second order in
// 1/N towards the continuous rod's k c / (2L). The test first checks that the bar the
// system integrates (ElasticBar::internal_force and its node masses) has exactly those
// eigenvalues, then prints the error / ratio / order table and asserts order 2 +- 0.05
// (the O(N^-4) term moves the successive orders by (k pi / N)^2 / 40 < 0.02 from N = 8 on).
//
// e_effective of the paper's drop test converges in N at the same order: linear elements
// reproduce the bar's static compliance under nodal loads exactly, so what converges is the
// inertia, whose lumped-mass error is the frequencies' O(h^2). Successive differences fall by 4 per
// doubling: order 2 +- 0.2 (the differences, 1e-6 and below, sit within a decade of the
// integration error floor ~1e-10 only beyond N = 160, which the sweep stops short of).
#include "tests/elastic_rod_support.hpp"

#include <Eigen/Eigenvalues>
#include <catch2/catch.hpp>
#include <fmt/format.h>

#include <cmath>
#include <iostream>
#include <numbers>

using namespace hertzdash;
using namespace hertzdash::test;

namespace {

/// The steel rod of Table 1 / Table 3 as an N-element bar, undamped.
ElasticBar steel_bar(int N) {
  const RodData& rod = paper().rod("steel");
  return ElasticBar(rod.length_m, std::numbers::pi * rod.diameter_m * rod.diameter_m / 4, rod.mass_kg, rod.E_Pa, N, 0.0);
}

/// The bar's free-free angular frequencies, from its assembled stiffness (the internal force
/// of unit displacements) and node masses: the generalised eigenproblem K phi = w^2 M phi.
Eigen::VectorXd assembled_frequencies(const ElasticBar& bar) {
  const int n = bar.nodes();
  Eigen::MatrixXd K(n, n), M = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd u(n), zero = Eigen::VectorXd::Zero(n), f(n);
  for (int j = 0; j < n; ++j) {
    u.setZero();
    u[j] = 1.0;
    bar.internal_force([&](int i) { return u[i]; }, [&](int i) { return zero[i]; }, [&](int i) -> double& { return f[i]; });
    K.col(j) = -f;
    M(j, j) = bar.node_mass_kg(j);
  }
  Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M);
  REQUIRE(solver.info() == Eigen::Success);
  return solver.eigenvalues().cwiseMax(0.0).cwiseSqrt();
}

}  // namespace

TEST_CASE("Elastic rod: the assembled bar has the closed-form lumped-mass frequencies", "[convergence][elastic]") {
  // Eigenvalues of a symmetric 33x33 problem to ~1e-13 relative (LAPACK-grade, Eigen's
  // tridiagonal QR): bound 1e-9 relative to w_N. The rigid-body mode is w_0 = 0.
  const ElasticBar bar = steel_bar(32);
  const Eigen::VectorXd w = assembled_frequencies(bar);
  CHECK(w[0] < 1e-6 * bar.frequency_rad_per_s(32));
  for (int k = 1; k <= 32; ++k) CHECK(std::abs(w[k] - bar.frequency_rad_per_s(k)) < 1e-9 * bar.frequency_rad_per_s(32));
  // Rayleigh damping from the first mode's ratio: zeta_k = beta w_k / 2, zeta_1 as asked.
  const RodData& rod = paper().rod("steel");
  const ElasticBar damped(rod.length_m, std::numbers::pi * rod.diameter_m * rod.diameter_m / 4, rod.mass_kg, rod.E_Pa, 32,
                          0.01);
  CHECK(damped.damping_beta_s() * damped.frequency_rad_per_s(1) / 2 == Approx(0.01).epsilon(1e-14));
}

TEST_CASE("Elastic rod: the first free-free frequencies converge to k c / (2L) at second order", "[convergence][elastic]") {
  for (int k = 1; k <= 3; ++k) {
    std::cout << fmt::format("free-free longitudinal mode {} of the steel rod, exact {:.6g} Hz\n", k,
                             steel_bar(8).continuum_frequency_hz(k))
              << fmt::format("  {:>5} {:>14} {:>12} {:>8} {:>6}\n", "N", "f_k(N) [Hz]", "rel. error", "ratio", "order");
    double previous = 0;
    for (int N = 8; N <= 128; N *= 2) {
      const ElasticBar bar = steel_bar(N);
      const double f = assembled_frequencies(bar)[k] / (2 * std::numbers::pi);
      const double error = std::abs(f / bar.continuum_frequency_hz(k) - 1);
      if (previous > 0) {
        const double order = std::log2(previous / error);
        std::cout << fmt::format("  {:>5} {:>14.8g} {:>12.4e} {:>8.4f} {:>6.3f}\n", N, f, error, previous / error, order);
        CHECK(order == Approx(2).margin(0.05));
      } else {
        std::cout << fmt::format("  {:>5} {:>14.8g} {:>12.4e}\n", N, f, error);
      }
      previous = error;
    }
  }
}

TEST_CASE("Elastic rod: e_effective converges in the number of elements at second order", "[convergence][elastic]") {
  const std::vector<int> N{5, 10, 20, 40, 80, 160};
  std::vector<double> e;
  for (int n : N) e.push_back(run(elastic_options("steel", 0.02, n), tight_dopri5()).e_effective);
  std::cout << "e_effective of the steel rod (h = 20 mm, the rig's defaults) against the elements N\n"
            << fmt::format("  {:>5} {:>18} {:>12} {:>8} {:>6}\n", "N", "e_effective", "|e(N)-e(N/2)|", "ratio", "order");
  std::cout << fmt::format("  {:>5} {:>18.15f}\n", N[0], e[0]);
  double previous = 0;
  for (std::size_t i = 1; i < N.size(); ++i) {
    const double difference = std::abs(e[i] - e[i - 1]);
    if (previous > 0) {
      const double order = std::log2(previous / difference);
      std::cout << fmt::format("  {:>5} {:>18.15f} {:>12.4e} {:>8.4f} {:>6.3f}\n", N[i], e[i], difference,
                               previous / difference, order);
      CHECK(order == Approx(2).margin(0.2));
    } else {
      std::cout << fmt::format("  {:>5} {:>18.15f} {:>12.4e}\n", N[i], e[i], difference);
    }
    previous = difference;
  }
  // The default (ElasticRodSetup::default_elements = 20) against the Richardson limit
  // e(inf) ~ e(160) + (e(160) - e(80)) / 3: within 2e-6, as the option's help promises (the
  // second-order error at N = 20 is |e(20) - e(10)| / 3 ~ 6e-7; the bound is three times it).
  const double limit = e.back() + (e.back() - e[e.size() - 2]) / 3;
  CHECK(ElasticRodSetup::default_elements == 20);
  CHECK(std::abs(e[2] - limit) < 2e-6);
}
