#pragma once
// Forward-mode differentiation with N infinitesimals: a value and its derivatives along N
// directions, carried through the ring operations a law's force_of_root and an environment's
// rates are written in (model/damping/damping_law.hpp, RootPolynomialLaw):
//   (a, a') * (b, b') = (a b, a' b + a b')
// and linearly for sums and products with doubles. Exact to rounding.
//
// Two uses:
//   - ForceJet = Jet<2> on the leaves u = (u, 1, 0) and xdot = (xdot, 0, 1): one evaluation of
//     force_of_root gives (F, F_u, F_xdot). The regularised contact's peak-force event
//     (model/contact_system.hpp) takes its rate dF/dtau = F_u u' + F_xdot xdot' from it, in one
//     evaluation where differences need three.
//   - Jet<2> on a state whose derivatives along two parameters are carried with it: one
//     evaluation of the contact's right-hand side gives f and its directional derivatives
//     f_Y dY/dp, the variational equations of model/contact_tangent_system.hpp.
#include <array>

namespace hertzdash {

template <int N>
struct Jet {
  double value = 0;
  std::array<double, N> d{};  ///< the derivatives along the N directions

  /// A leaf: `value` with unit derivative along direction i.
  static Jet leaf(double value, int i) {
    Jet j{value, {}};
    j.d[static_cast<std::size_t>(i)] = 1.0;
    return j;
  }
};

/// A force and its partial derivatives with respect to (u, xdot): d[0] = dF/du [N/m^{1/2}],
/// d[1] = dF/dxdot [N s/m].
using ForceJet = Jet<2>;
inline ForceJet root_leaf(double u) { return ForceJet::leaf(u, 0); }
inline ForceJet rate_leaf(double xdot) { return ForceJet::leaf(xdot, 1); }

namespace detail {
/// a + s b, component by component.
template <int N> Jet<N> axpy(const Jet<N>& a, double s, const Jet<N>& b) {
  Jet<N> r{a.value + s * b.value, {}};
  for (std::size_t i = 0; i < N; ++i) r.d[i] = a.d[i] + s * b.d[i];
  return r;
}
}  // namespace detail

template <int N> Jet<N> operator+(const Jet<N>& a, const Jet<N>& b) { return detail::axpy(a, 1.0, b); }
template <int N> Jet<N> operator-(const Jet<N>& a, const Jet<N>& b) { return detail::axpy(a, -1.0, b); }
template <int N> Jet<N> operator*(const Jet<N>& a, const Jet<N>& b) {
  Jet<N> r{a.value * b.value, {}};
  for (std::size_t i = 0; i < N; ++i) r.d[i] = a.d[i] * b.value + a.value * b.d[i];
  return r;
}
template <int N> Jet<N> operator*(double s, const Jet<N>& a) {
  Jet<N> r{s * a.value, {}};
  for (std::size_t i = 0; i < N; ++i) r.d[i] = s * a.d[i];
  return r;
}
template <int N> Jet<N> operator-(const Jet<N>& a) { return -1.0 * a; }
template <int N> Jet<N> operator*(const Jet<N>& a, double s) { return s * a; }
template <int N> Jet<N> operator/(const Jet<N>& a, double s) { return (1.0 / s) * a; }
template <int N> Jet<N> operator+(double s, const Jet<N>& a) {
  Jet<N> r = a;
  r.value += s;
  return r;
}
template <int N> Jet<N> operator+(const Jet<N>& a, double s) { return s + a; }
template <int N> Jet<N> operator-(double s, const Jet<N>& a) { return s + (-a); }
template <int N> Jet<N> operator-(const Jet<N>& a, double s) { return (-s) + a; }

}  // namespace hertzdash
