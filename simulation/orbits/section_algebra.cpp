// Linear algebra of a section (simulation/orbits/section_algebra.hpp).
#include "hertzdash/simulation/orbits/section_algebra.hpp"

#include "hertzdash/simulation/orbits/planar_algebra.hpp"

#include <gsl/gsl_eigen.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_linalg.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>

namespace hertzdash::section {

namespace {

/// GSL reports by return codes here, never by aborting (the library default).
void errors_by_return_code() {
  static std::once_flag once;
  std::call_once(once, [] { gsl_set_error_handler_off(); });
}

/// A GSL copy of a (row-major, as GSL stores it).
struct GslMatrix {
  std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> m;
  GslMatrix(const Eigen::MatrixXd& a, Eigen::Index rows, Eigen::Index cols)
      : m(gsl_matrix_calloc(static_cast<std::size_t>(rows), static_cast<std::size_t>(cols)), &gsl_matrix_free) {
    if (!m) throw std::bad_alloc();
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      for (Eigen::Index j = 0; j < a.cols(); ++j) gsl_matrix_set(m.get(), static_cast<std::size_t>(i), static_cast<std::size_t>(j), a(i, j));
  }
};

/// a's LU factors with row permutation p and sign, or false where GSL refuses.
struct Lu {
  GslMatrix lu;
  std::unique_ptr<gsl_permutation, decltype(&gsl_permutation_free)> p;
  int sign = 0;
  int status = 0;
  explicit Lu(const Eigen::MatrixXd& a)
      : lu(a, a.rows(), a.cols()), p(gsl_permutation_alloc(static_cast<std::size_t>(a.rows())), &gsl_permutation_free) {
    errors_by_return_code();
    if (!p) throw std::bad_alloc();
    status = gsl_linalg_LU_decomp(lu.m.get(), p.get(), &sign);
  }
};

void require_square(const Eigen::MatrixXd& a, const char* what) {
  if (a.rows() != a.cols() || a.rows() == 0) throw std::invalid_argument(std::string("section::") + what + ": a square matrix");
}

}  // namespace

double det(const Eigen::MatrixXd& a) {
  require_square(a, "det");
  if (a.rows() == 2) return planar::det(a);
  const Lu f(a);
  return f.status == GSL_SUCCESS ? gsl_linalg_LU_det(f.lu.m.get(), f.sign) : std::numeric_limits<double>::quiet_NaN();
}

Eigen::VectorXd solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& b) {
  require_square(a, "solve");
  if (a.rows() == 2) return planar::inverse(a) * b;
  if (a.rows() == 3) return planar::solve(a, b);
  Eigen::VectorXd x = Eigen::VectorXd::Constant(a.rows(), std::numeric_limits<double>::quiet_NaN());
  const Lu f(a);
  if (f.status != GSL_SUCCESS) return x;
  for (Eigen::Index i = 0; i < a.rows(); ++i)  // a zero pivot: singular
    if (gsl_matrix_get(f.lu.m.get(), static_cast<std::size_t>(i), static_cast<std::size_t>(i)) == 0) return x;
  gsl_vector_const_view bv = gsl_vector_const_view_array(b.data(), static_cast<std::size_t>(b.size()));
  gsl_vector_view xv = gsl_vector_view_array(x.data(), static_cast<std::size_t>(x.size()));
  if (gsl_linalg_LU_solve(f.lu.m.get(), f.p.get(), &bv.vector, &xv.vector) != GSL_SUCCESS) x.setConstant(std::nan(""));
  return x;
}

std::vector<std::complex<double>> eigenvalues(const Eigen::MatrixXd& a) {
  require_square(a, "eigenvalues");
  if (a.rows() == 2) {
    const auto l = planar::eigenvalues(a);
    return {l.begin(), l.end()};
  }
  errors_by_return_code();
  const auto n = static_cast<std::size_t>(a.rows());
  GslMatrix m(a, a.rows(), a.cols());
  std::unique_ptr<gsl_vector_complex, decltype(&gsl_vector_complex_free)> eval(gsl_vector_complex_alloc(n), &gsl_vector_complex_free);
  std::unique_ptr<gsl_eigen_nonsymm_workspace, decltype(&gsl_eigen_nonsymm_free)> w(gsl_eigen_nonsymm_alloc(n), &gsl_eigen_nonsymm_free);
  if (!eval || !w) throw std::bad_alloc();
  std::vector<std::complex<double>> out(n, std::complex<double>(NAN, NAN));
  if (gsl_eigen_nonsymm(m.m.get(), eval.get(), w.get()) != GSL_SUCCESS) return out;  // QR did not converge: NaN
  for (std::size_t i = 0; i < n; ++i) {
    const gsl_complex z = gsl_vector_complex_get(eval.get(), i);
    out[i] = {GSL_REAL(z), GSL_IMAG(z)};
  }
  // Largest modulus first; a conjugate pair with its positive imaginary part first.
  std::ranges::stable_sort(out, [](auto x, auto y) {
    return std::abs(x) != std::abs(y) ? std::abs(x) > std::abs(y) : x.imag() > y.imag();
  });
  return out;
}

Eigen::VectorXd null_vector(const Eigen::MatrixXd& a) {
  if (a.rows() == 2 && a.cols() == 2) return planar::null_vector(a);
  if (a.rows() == 2 && a.cols() == 3) {
    const Eigen::Vector3d t = planar::cross(a.row(0).transpose(), a.row(1).transpose());
    return t / t.norm();
  }
  if (a.cols() < a.rows() || a.cols() > a.rows() + 1) throw std::invalid_argument("section::null_vector: n x n or n x (n + 1)");
  errors_by_return_code();
  // The SVD of a padded to square with zero rows (GSL's needs rows >= columns): a = U S V^T, the
  // singular values in decreasing order, so V's last column spans the null space.
  const auto n = static_cast<std::size_t>(a.cols());
  GslMatrix u(a, a.cols(), a.cols());
  std::unique_ptr<gsl_matrix, decltype(&gsl_matrix_free)> v(gsl_matrix_alloc(n, n), &gsl_matrix_free);
  std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> s(gsl_vector_alloc(n), &gsl_vector_free), work(gsl_vector_alloc(n), &gsl_vector_free);
  if (!v || !s || !work) throw std::bad_alloc();
  Eigen::VectorXd out = Eigen::VectorXd::Constant(a.cols(), std::numeric_limits<double>::quiet_NaN());
  if (gsl_linalg_SV_decomp(u.m.get(), v.get(), s.get(), work.get()) != GSL_SUCCESS) return out;
  for (std::size_t i = 0; i < n; ++i) out(static_cast<Eigen::Index>(i)) = gsl_matrix_get(v.get(), i, n - 1);
  return out;
}

}  // namespace hertzdash::section
