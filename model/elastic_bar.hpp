#pragma once
// The rod as a one-dimensional elastic bar: longitudinal motion only, N two-node linear
// finite elements with lumped (row-sum) masses, free at both ends.
//
// Node j = 0..N sits at depth j h below the top face (h = L / N); u_j is its displacement
// and v_j its velocity, downward positive. With rho A = m / L (Table 1's mass and
// dimensions) and c = sqrt(E / rho):
//   element stiffness  k_e = E A / h,      node masses  m_j = rho A h  (m_0 = m_N = rho A h / 2),
//   internal force     f_j = -(K u)_j - beta (K v)_j,   (K u)_j = k_e (2 u_j - u_{j-1} - u_{j+1})
//   (end rows with one neighbour). Damping is stiffness-proportional (Rayleigh, beta K): it
//   leaves the rigid-body motion undamped and gives mode k the ratio zeta_k = beta w_k / 2,
//   so `first_mode_damping_ratio` zeta_1 fixes beta = 2 zeta_1 / w_1 and higher modes are
//   damped in proportion to their frequency.
//
// Why lumped finite elements rather than free-free modes: the contact acts at one node, the
// stiffness is tridiagonal (a banded Jacobian for CVODE's BDF, O(N) work per evaluation),
// the accelerometer reads a node, and the discrete free-free frequencies have the closed form
//   w_k = (2 c / h) sin(k pi / (2 N)),   k = 0..N   (eigenvectors cos(k pi j / N)),
// which converge to the bar's w_k = k pi c / L at second order: w_k / (k pi c / L) - 1
// = -(k pi / N)^2 / 24 + O(N^-4). A truncated modal basis would need many modes to carry the
// point load at the end face (its modal forces do not decay), the elements need none.
// Reference: K.-J. Bathe, Finite Element Procedures (1996), sections 9.2-9.3 (lumped mass,
// free-free bar); S. Timoshenko et al., Vibration Problems in Engineering (1974), section 5.2.
#include <cmath>
#include <numbers>

namespace hertzdash {

/// Constant parameters of the discretised bar.
class ElasticBar {
 public:
  /// A bar of length L [m], cross-section A [m^2], mass m [kg] and modulus E [Pa] in N
  /// elements, with damping ratio zeta_1 [-] in its first longitudinal mode.
  ElasticBar(double length_m, double area_m2, double mass_kg, double E_Pa, int elements,
             double first_mode_damping_ratio)
      : elements_(elements),
        length_m_(length_m),
        mass_kg_(mass_kg),
        wave_speed_mps_(std::sqrt(E_Pa * area_m2 * length_m / mass_kg)),
        element_stiffness_N_per_m_(E_Pa * area_m2 * elements / length_m),
        interior_node_mass_kg_(mass_kg / elements),
        beta_s_(2.0 * first_mode_damping_ratio / frequency_rad_per_s(1)) {}

  int elements() const { return elements_; }
  int nodes() const { return elements_ + 1; }
  double length_m() const { return length_m_; }
  double mass_kg() const { return mass_kg_; }
  double wave_speed_mps() const { return wave_speed_mps_; }                ///< c = sqrt(E / rho) [m/s]
  double element_stiffness_N_per_m() const { return element_stiffness_N_per_m_; }  ///< k_e = E A / h
  double damping_beta_s() const { return beta_s_; }                        ///< beta [s]
  double element_mass_kg() const { return interior_node_mass_kg_; }         ///< rho A h = m / N
  /// m_j [kg]: rho A h inside, half of it at the two end faces.
  double node_mass_kg(int j) const {
    return (j == 0 || j == elements_) ? 0.5 * interior_node_mass_kg_ : interior_node_mass_kg_;
  }

  /// Discrete free-free angular frequency w_k = (2 c / h) sin(k pi / (2 N)) [rad/s], k = 0..N.
  double frequency_rad_per_s(int k) const {
    return 2.0 * wave_speed_mps_ * elements_ / length_m_ * std::sin(k * std::numbers::pi / (2.0 * elements_));
  }
  /// The continuous bar's k-th free-free longitudinal frequency k c / (2 L) [Hz].
  double continuum_frequency_hz(int k) const { return k * wave_speed_mps_ / (2.0 * length_m_); }
  /// The time a longitudinal wave takes down the rod and back, 2 L / c [s].
  double wave_round_trip_s() const { return 2.0 * length_m_ / wave_speed_mps_; }

  /// Internal force f = -(K u) - beta (K v) on every node [N]; u, v, f indexable by node
  /// through the accessors (so the state's interleaved layout needs no copy). O(N).
  template <class U, class V, class F>
  void internal_force(U&& u, V&& v, F&& f) const {
    for (int j = 0; j <= elements_; ++j) f(j) = 0.0;
    for (int e = 0; e < elements_; ++e) {
      const double n = tension_N(u, v, e);
      f(e) += n;
      f(e + 1) -= n;
    }
  }

  /// Tension in element e [N]: k_e (stretch + beta stretch rate).
  template <class U, class V>
  double tension_N(U&& u, V&& v, int e) const {
    return element_stiffness_N_per_m_ * (u(e + 1) - u(e) + beta_s_ * (v(e + 1) - v(e)));
  }

  /// Internal force on node j alone [N]: the tensions of its one or two elements. O(1).
  template <class U, class V>
  double node_internal_force_N(U&& u, V&& v, int j) const {
    return (j < elements_ ? tension_N(u, v, j) : 0.0) - (j > 0 ? tension_N(u, v, j - 1) : 0.0);
  }

  /// Strain energy (1/2) u^T K u [J].
  template <class U>
  double strain_energy_J(U&& u) const {
    double s = 0;
    for (int e = 0; e < elements_; ++e) s += (u(e + 1) - u(e)) * (u(e + 1) - u(e));
    return 0.5 * element_stiffness_N_per_m_ * s;
  }

  /// Material dissipation rate v^T (beta K) v [W].
  template <class V>
  double dissipation_rate_W(V&& v) const {
    double s = 0;
    for (int e = 0; e < elements_; ++e) s += (v(e + 1) - v(e)) * (v(e + 1) - v(e));
    return beta_s_ * element_stiffness_N_per_m_ * s;
  }

 private:
  int elements_;
  double length_m_, mass_kg_, wave_speed_mps_, element_stiffness_N_per_m_, interior_node_mass_kg_, beta_s_;
};

}  // namespace hertzdash
