#pragma once
// The linear algebra of a section of any dimension n (a prescribed box's (y, u), n = 2; the
// impact damper's (y, u, X, V), n = 4): determinants, solutions, eigenvalues and null vectors of
// the monodromy and of continuation's bordered systems. Two dimensions (and continuation's 2x3
// and 3x3) in closed form (planar_algebra.hpp); larger ones by GSL (LU with partial pivoting,
// the nonsymmetric Hessenberg-QR eigensolver, the SVD), compiled once here rather than Eigen's
// decompositions in every unit of simulation/orbits/.
#include <Eigen/Core>

#include <complex>
#include <vector>

namespace hertzdash::section {

/// det a of a square a.
double det(const Eigen::MatrixXd& a);

/// x with a x = b for a square a; NaN entries where a is singular.
Eigen::VectorXd solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b);

/// The eigenvalues of a square a, largest modulus first.
std::vector<std::complex<double>> eigenvalues(const Eigen::MatrixXd& a);

/// A unit vector v with a v ~ 0, for a square a that is (nearly) singular or an n x (n + 1) a of
/// full rank: the right singular vector of the smallest singular value.
Eigen::VectorXd null_vector(const Eigen::MatrixXd& a);

}  // namespace hertzdash::section
