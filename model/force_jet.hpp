#pragma once
// A force and its partial derivatives with respect to (u, xdot) in one evaluation of a
// law's force_of_root (model/damping/damping_law.hpp, RootPolynomialLaw): forward-mode
// differentiation with two infinitesimals. force_of_root is a template over any ring
// scalar type; evaluated on ForceJet leaves u = (u, 1, 0) and xdot = (xdot, 0, 1) it
// returns (F, F_u, F_xdot), exact to rounding:
//   (a, a_u, a_v) * (b, b_u, b_v) = (a b, a_u b + a b_u, a_v b + a b_v)
// and linearly for sums and products with doubles. The regularised contact's peak-force
// event (model/contact_system.hpp) takes its rate dF/dtau = F_u u' + F_xdot xdot'
// from it, in one evaluation where differences need three.

namespace hertzdash {

struct ForceJet {
  double value = 0;  ///< F [N]
  double d_u = 0;    ///< dF/du [N/m^{1/2}]
  double d_v = 0;    ///< dF/dxdot [N s/m]

  /// The leaves: u = x^{1/2} [m^{1/2}] and xdot [m/s], each with unit derivative along itself.
  static ForceJet root(double u) { return {u, 1.0, 0.0}; }
  static ForceJet rate(double xdot) { return {xdot, 0.0, 1.0}; }
};

inline ForceJet operator+(const ForceJet& a, const ForceJet& b) { return {a.value + b.value, a.d_u + b.d_u, a.d_v + b.d_v}; }
inline ForceJet operator-(const ForceJet& a, const ForceJet& b) { return {a.value - b.value, a.d_u - b.d_u, a.d_v - b.d_v}; }
inline ForceJet operator*(const ForceJet& a, const ForceJet& b) {
  return {a.value * b.value, a.d_u * b.value + a.value * b.d_u, a.d_v * b.value + a.value * b.d_v};
}
inline ForceJet operator-(const ForceJet& a) { return {-a.value, -a.d_u, -a.d_v}; }
inline ForceJet operator*(double s, const ForceJet& a) { return {s * a.value, s * a.d_u, s * a.d_v}; }
inline ForceJet operator*(const ForceJet& a, double s) { return s * a; }
inline ForceJet operator/(const ForceJet& a, double s) { return {a.value / s, a.d_u / s, a.d_v / s}; }
inline ForceJet operator+(double s, const ForceJet& a) { return {s + a.value, a.d_u, a.d_v}; }
inline ForceJet operator+(const ForceJet& a, double s) { return s + a; }
inline ForceJet operator-(double s, const ForceJet& a) { return s + (-a); }
inline ForceJet operator-(const ForceJet& a, double s) { return {a.value - s, a.d_u, a.d_v}; }

}  // namespace hertzdash
