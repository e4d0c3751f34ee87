#pragma once
// The stroboscopic map of a rig on the impact-sequence driver: a box that moves as prescribed (the
// shaker's wall, the driven box, the impact oscillator's stop at rest), with instantaneous or soft
// impacts, or a box of its own (the impact damper's primary; below), with either.
// The body's state z = (y [m], u [m/s]) at the drive phase phi_s is carried over N drive periods by the
// impact-sequence driver (simulation/shaker/impact_sequence.hpp, its `end_time_s`), and its
// Jacobian, the monodromy matrix, follows from the flights' fundamental matrices and the impacts'
// saltation matrices (no finite differences):
//   M = Phi(t_end - t_k) S_k Phi(t_k - t_{k-1}) ... S_1 Phi(t_1 - t_s).
// Flight: m y'' + c y' + k y = F(t), linear, so its variational equation is dz' = A dz with A
// constant, and Phi(tau) = exp(A tau) has as columns the free responses (no force) from (1, 0) and
// (0, 1) (model/forced_oscillator.hpp).
// Impact at t_i on a wall at X(t) + offset, the body on side sigma: the gap h = sigma (y - X -
// offset) reaches 0, and Newton's law resets z to r(t, z) = (y, (1 + e) V(t) - e u), V = X'. The
// impact time moves with the state, dt_i = -n.dz / (n.f- + dh/dt), so (di Bernardo et al.,
// Piecewise-smooth Dynamical Systems, 2008, sec. 2.5; Leine and Nijmeijer 2004)
//   S = R + (f+ - R f- - dr/dt) n^T / (n.f- + dh/dt),
//   R = dr/dz = [[1, 0], [0, -e]],  n = sigma (1, 0),  dh/dt = -sigma V,  dr/dt = (0, (1 + e) X''),
// with f-+ = (u-+, a(t, y, u-+)) the flight's vector field before and after. For a free flight
// (a = -g) this is S = [[-e, 0], [(1 + e)(g + X'')/(V - u-), -e]], det S = e^2; det Phi =
// exp(-c tau/m); so det M = e^(2k) exp(-c N T/m) for k impacts in N periods.
// A box of its own (the impact damper's primary, mass M, X'' from its spring, dashpot and drive):
// the state is z = (y, u, X, V), the flight's Phi the two oscillators' blocks, and an
// instantaneous impact conserves momentum (simulation/shaker/impact_sequence.hpp), so with
// beta = (1 + e)/(m + M)
//   u+ = u + M beta (V - u),   V+ = V - m beta (V - u),   positions unchanged,
// R = dr/dz the identity but for the rows of u (1 - M beta in u's column, M beta in V's) and V
// (m beta, 1 - m beta); the gap h = sigma (y - X - offset) does not depend on t, so
//   S = R + (f+ - R f-) n^T / (n.f-),   n = sigma (1, 0, -1, 0),   n.f- = sigma (u- - V-),
// f = (u, a_body, V, a_box). det R = -e (its (u, V) block) and n^T R^-1 = n^T (R keeps the
// positions), so det S = det R (n.f+ / n.f-) = (-e)(-e) = e^2 as for a prescribed box; with
// det Phi = exp(-(c/m + C/M) tau), det M = e^(2k) exp(-(c/m + C/M) N T).
// Soft impacts (the same rigs, any law that declares dF/dv0): a contact begins at t_on at relative
// speed v0 and ends t_c later at relative speed v_sep, and its variational equations give
// J = d(t_c, v_sep)/d(t_on, v0) (simulation/run/soft_contact_tangent.hpp). The state's
// perturbation before the contact, dz- at fixed time, moves the onset and the speed,
//   dt_on = sigma dy / v0,   dv0 = sigma (X''(t_on) - a-) dt_on - sigma du  (P = d(t_on, v0)/dz-),
// and the separation (t_sep = t_on + t_c, y = X + offset, u+ = V + sigma v_sep) gives the
// perturbation after it at fixed time,
//   dz+ = (V dt_sep, X'' dt_sep + sigma dv_sep) - f+ dt_sep                 (Q = d dz+/d(t_sep, v_sep)),
// so the contact's block is C = Q [[1, 0], [0, 0]] + Q J' P with J' = J + [[1, 0], [0, 0]] the
// derivative of (t_sep, v_sep): C = Q (J + E11) P, and M = Phi C_k Phi ... C_1 Phi between the
// separations and the next onsets. As the contact stiffens (t_c -> 0, v_sep -> e v0) C tends to
// the saltation matrix S above: the check of one against the other (tests/test_orbit_soft.cpp).
// A contact that spans the section's time is refused (the section lies in flight by its choice).
// A soft contact with a box of its own also takes the box's state (X_on, V_on) at onset and gives
// it at separation, J = d(t_c, v_sep, X_sep, V_sep)/d(t_on, v0, X_on, V_on) (the SprungPrimary
// contact's variational equations), and with n.dz = sigma (dy - dX), A the box's free acceleration
// and a- the body's at onset, f+ the vector field after,
//   dt_on = sigma (dy - dX)/v0,  dv0 = sigma (A - a-) dt_on + sigma (dV - du),
//   dX_on = dX + V- dt_on,  dV_on = dV + A dt_on                          (P, 4 x 4),
//   dz+ = (dX_sep, dV_sep + sigma dv_sep, dX_sep, dV_sep) - f+ dt_sep      (Q, 4 x 4),
// the block again Q (J + E11) P: y_sep = X_sep + offset and u+ = V_sep + sigma v_sep.
// Refused (as a failed image, not an exception: Newton steps back from it) are a state that is not
// finite, a state inside a wall, a body carried by a wall (a sticking orbit: the map is not smooth there) and a chatter cap.
#include "hertzdash/simulation/shaker/impact_sequence.hpp"

#include <Eigen/Core>

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

/// `spec` started with the body in flight at (t0 [s], y0 [m], u0 [m/s]), no energy account or
/// samples (the basins' starts, and flow_spec's).
ImpactSequenceSpec in_flight_from(ImpactSequenceSpec spec, double t0_s, double y0_m, double u0_mps);
/// `spec` as a flow from the section state z at t0 [s] (in flight), run to t_end [s], every
/// impact kept (the map's runs, the guess's flow to the section).
ImpactSequenceSpec flow_spec(ImpactSequenceSpec spec, double t0_s, const Eigen::VectorXd& z, double t_end_s);

/// The coordinates of the section of `spec`, as reports name them (unit suffixed): the body's
/// position_m and velocity_mps, then, for a box of its own (the damper's primary), the box's
/// box_position_m and box_velocity_mps.
std::span<const std::string_view> section_coordinates(const ImpactSequenceSpec& spec);
/// The section's state of a run's end: (y, u), and (X, V) for a box of its own.
Eigen::VectorXd section_state(const ImpactSequenceSpec& spec, const ImpactSequence& run);
/// The gap [m] of the section state z at time t [s] to the nearest wall of the box of `spec`
/// (< 0: inside it).
double smallest_gap_m(const ImpactSequenceSpec& spec, double t_s, const Eigen::VectorXd& z);

/// The image of one state under the map.
struct SectionImage {
  Eigen::VectorXd state;                 ///< z N periods later (section_coordinates)
  Eigen::MatrixXd monodromy;             ///< d state / d start
  std::vector<SequenceImpact> impacts;   ///< the impacts on the way, in order
  double min_impact_speed_mps = 0;       ///< the slowest of them (0 near grazing); inf: none
  /// The smallest gap to a wall at a local minimum inside a flight [m] (0 near a grazing flight,
  /// which touches a wall tangentially); inf: no interior minimum. Sampled 64 times a drive
  /// cycle, each minimum refined where the gap's rate changes sign.
  double min_flight_gap_m = 0;
  std::string failure;                   ///< empty: a valid image; else why not
};

/// How the map of `spec` computes its monodromy, in words (a report's `method`).
const char* monodromy_method(const ImpactSequenceSpec& spec);

/// The map P^N from phase phi_s of a prescribed-box sequence `spec`.
class StroboscopicMap {
 public:
  /// Throws std::invalid_argument for soft impacts without their tangents (spec.soft_tangent), or
  /// cycles < 1.
  StroboscopicMap(ImpactSequenceSpec spec, double section_phase, int cycles);
  SectionImage operator()(const Eigen::VectorXd& state) const;
  /// The section's time in the first drive period [s], phi_s / f.
  double section_time_s() const { return t_s_; }
  int cycles() const { return cycles_; }
  const ImpactSequenceSpec& spec() const { return spec_; }
  /// The gap of `state` to each wall at the section time [m] (< 0: inside it).
  double smallest_gap_m(const Eigen::VectorXd& state) const;

 private:
  ImpactSequenceSpec spec_;
  double t_s_;
  int cycles_;
};

}  // namespace hertzdash
