#pragma once
// The linear algebra of a two-dimensional section (a prescribed-box rig's (y, u)) in closed form:
// a 2x2 determinant and inverse, eigenvalues from the trace and determinant, a null vector, and
// the 3x3 bordered systems of continuation by cross products (Cramer's rule). Closed forms, not
// Eigen's LU, QR and eigensolvers: exact enough at this size, and a fraction of their compile
// time (simulation/orbits/ took minutes with them).
#include <Eigen/Core>

#include <array>
#include <cmath>
#include <complex>

namespace hertzdash::planar {

inline double det(const Eigen::Matrix2d& a) { return a(0, 0) * a(1, 1) - a(0, 1) * a(1, 0); }

/// The inverse of a with det(a) != 0.
inline Eigen::Matrix2d inverse(const Eigen::Matrix2d& a) {
  Eigen::Matrix2d inv;
  inv << a(1, 1), -a(0, 1), -a(1, 0), a(0, 0);
  return inv / det(a);
}

/// The eigenvalues, largest modulus first: tr/2 +- sqrt(tr^2/4 - det), the root in the form
/// without cancellation for real ones (det / the larger).
inline std::array<std::complex<double>, 2> eigenvalues(const Eigen::Matrix2d& a) {
  const double half = 0.5 * a.trace(), d = det(a), disc = half * half - d;
  if (disc < 0) {
    const double im = std::sqrt(-disc);
    return {std::complex<double>(half, im), std::complex<double>(half, -im)};
  }
  const double big = half + std::copysign(std::sqrt(disc), half);
  const double small = big != 0 ? d / big : 0.0;
  return {std::complex<double>(big), std::complex<double>(small)};
}

/// A unit vector v with a v ~ 0 for a singular a: orthogonal to a's larger row.
inline Eigen::Vector2d null_vector(const Eigen::Matrix2d& a) {
  const Eigen::Vector2d row = a.row(0).squaredNorm() >= a.row(1).squaredNorm() ? a.row(0).transpose() : a.row(1).transpose();
  return Eigen::Vector2d(-row(1), row(0)).normalized();
}

inline Eigen::Vector3d cross(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return {a(1) * b(2) - a(2) * b(1), a(2) * b(0) - a(0) * b(2), a(0) * b(1) - a(1) * b(0)};
}

/// x with A x = b, A's rows r0, r1, r2: x = (b0 (r1 x r2) + b1 (r2 x r0) + b2 (r0 x r1)) / det;
/// NaN where det = r0.(r1 x r2) is 0.
inline Eigen::Vector3d solve(const Eigen::Matrix3d& A, const Eigen::Vector3d& b) {
  const Eigen::Vector3d r0 = A.row(0).transpose(), r1 = A.row(1).transpose(), r2 = A.row(2).transpose();
  const Eigen::Vector3d c0 = cross(r1, r2), c1 = cross(r2, r0), c2 = cross(r0, r1);
  const double d = r0.dot(c0);
  if (d == 0) return Eigen::Vector3d::Constant(NAN);
  return (b(0) * c0 + b(1) * c1 + b(2) * c2) / d;
}

}  // namespace hertzdash::planar
