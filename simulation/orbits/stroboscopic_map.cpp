// The stroboscopic map and its monodromy matrix (simulation/orbits/stroboscopic_map.hpp).
#include "hertzdash/simulation/orbits/stroboscopic_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

namespace hertzdash {

namespace {

/// Phi(tau): one oscillator's flight's fundamental matrix, the free responses from (1, 0) and (0, 1).
Eigen::Matrix2d flight_matrix(const ForcedOscillator& body, double tau_s) {
  ForcedOscillator free = body;
  free.force_amplitude_N = 0;
  free.constant_force_N = 0;
  const OscillatorMotion from_position(free, 0, 1, 0), from_velocity(free, 0, 0, 1);
  Eigen::Matrix2d phi;
  phi << from_position.position_m(tau_s), from_velocity.position_m(tau_s), from_position.velocity_mps(tau_s),
      from_velocity.velocity_mps(tau_s);
  return phi;
}

/// The section's flight matrix over tau [s]: the body's block, and the box's for a box of its own.
Eigen::MatrixXd section_flight_matrix(const ImpactSequenceSpec& spec, double tau_s) {
  if (spec.prescribed) return flight_matrix(spec.body, tau_s);
  Eigen::MatrixXd phi = Eigen::MatrixXd::Zero(4, 4);
  phi.topLeftCorner<2, 2>() = flight_matrix(spec.body, tau_s);
  phi.bottomRightCorner<2, 2>() = flight_matrix(spec.box, tau_s);
  return phi;
}

/// The body's acceleration a(t, y, u) in flight [m/s^2].
double acceleration(const ForcedOscillator& b, double t, double y, double u) {
  return (b.force_derivative(0, t) + b.constant_force_N - b.stiffness_N_per_m * y - b.damping_N_s_per_m() * u) / b.mass_kg;
}

/// The smallest interior local minimum over [ta, tb] of the gaps of `body` to `walls` on the box
/// (inf: none): each gap sampled 64 times a drive cycle, a minimum refined by bisection on the
/// gap's rate between the samples where it turns from falling to rising.
double min_interior_gap(const OscillatorMotion& body, const OscillatorMotion& box, const std::vector<SequenceWall>& walls,
                        double ta, double tb, double frequency_Hz) {
  double least = std::numeric_limits<double>::infinity();
  const int samples = std::max(2, static_cast<int>(std::ceil(64 * (tb - ta) * frequency_Hz)));
  for (const SequenceWall& w : walls) {
    auto rate = [&](double t) { return w.sigma * (body.velocity_mps(t) - box.velocity_mps(t)); };
    double t0 = ta, r0 = rate(ta);
    for (int k = 1; k <= samples; ++k) {
      const double t1 = ta + (tb - ta) * k / samples, r1 = rate(t1);
      if (r0 < 0 && r1 >= 0) {
        double lo = t0, hi = t1;
        for (int i = 0; i < 60 && hi - lo > 1e-15 * tb; ++i) (rate(0.5 * (lo + hi)) < 0 ? lo : hi) = 0.5 * (lo + hi);
        const double t = 0.5 * (lo + hi);
        least = std::min(least, w.sigma * (body.position_m(t) - box.position_m(t) - w.offset_m));
      }
      t0 = t1, r0 = r1;
    }
  }
  return least;
}

/// The monodromy over the run `run` from z at t_s for a box of its own (see the header), the
/// image's closeness to grazing updated on the way; its failure set where a soft contact spans the
/// section's time or does not end.
Eigen::MatrixXd own_box_monodromy(const ImpactSequenceSpec& spec, double t_s, const Eigen::VectorXd& z,
                                  const ImpactSequence& run, SectionImage& image) {
  const ForcedOscillator &body = spec.body, &primary = spec.box;
  const double e = spec.restitution, m = body.mass_kg, beta = (1 + e) / (m + primary.mass_kg);
  Eigen::MatrixXd M = Eigen::MatrixXd::Identity(4, 4);
  double t_prev = t_s;
  OscillatorMotion flight(body, t_s, z(0), z(1)), box(primary, t_s, z(2), z(3));
  auto flight_gap = [&](double t_end) {
    image.min_flight_gap_m =
        std::min(image.min_flight_gap_m, min_interior_gap(flight, box, spec.walls, t_prev, t_end, spec.frequency_Hz));
  };
  for (const SequenceImpact& i : run.impacts) {
    const double t = i.time_s, sigma = spec.walls[static_cast<std::size_t>(i.wall)].sigma;
    const double y = flight.position_m(t), u_minus = flight.velocity_mps(t), X = box.position_m(t),
                 V_minus = box.velocity_mps(t);
    flight_gap(t);
    image.min_impact_speed_mps = std::min(image.min_impact_speed_mps, i.impact_speed_mps);
    if (spec.soft) {
      // The contact's block Q (J + E_11) P (the header): P the onset's (t_on, v0, X_on, V_on) from
      // the state before it at fixed time, Q the state after it from (t_sep, v_sep, X_sep, V_sep).
      const double v0 = i.impact_speed_mps, offset = spec.walls[static_cast<std::size_t>(i.wall)].offset_m;
      const ContactTangent c = spec.soft_tangent(i.wall, t, v0, X, V_minus, soft_contact_window_s(spec.frequency_Hz));
      const double t_sep = t + c.contact_time_s;
      if (!c.separated || !(t_sep < *spec.end_time_s)) {
        image.failure = c.separated ? fmt::format("the contact beginning at t = {:.9g} s spans the section's time", t)
                                    : fmt::format("the contact beginning at t = {:.9g} s did not end within {:g} drive cycles",
                                                  t, soft_contact_window_cycles);
        return M;
      }
      const double A = acceleration(primary, t, X, V_minus), a = acceleration(body, t, y, u_minus);
      const double X_sep = c.other_state(0), V_sep = c.other_state(1), y_sep = X_sep + offset,
                   u_plus = V_sep + sigma * c.rebound_speed_mps;
      const Eigen::RowVector4d onset(sigma / v0, 0, -sigma / v0, 0);  // dt_on
      Eigen::Matrix4d P;
      P.row(0) = onset;
      P.row(1) = sigma * (A - a) * onset + Eigen::RowVector4d(0, -sigma, 0, sigma);
      P.row(2) = V_minus * onset + Eigen::RowVector4d(0, 0, 1, 0);
      P.row(3) = A * onset + Eigen::RowVector4d(0, 0, 0, 1);
      Eigen::Matrix4d J = c.jacobian, Q;
      J(0, 0) += 1;  // t_sep = t_on + t_c
      Q.col(0) = -Eigen::Vector4d(u_plus, acceleration(body, t_sep, y_sep, u_plus), V_sep,
                                  acceleration(primary, t_sep, X_sep, V_sep));
      Q.col(1) << 0, sigma, 0, 0;
      Q.col(2) << 1, 0, 1, 0;
      Q.col(3) << 0, 1, 0, 1;
      M = Q * J * P * section_flight_matrix(spec, t - t_prev) * M;
      t_prev = t_sep;
      flight = OscillatorMotion(body, t_sep, y_sep, u_plus);
      box = OscillatorMotion(primary, t_sep, X_sep, V_sep);
      continue;
    }
    const double jump = beta * (V_minus - u_minus);
    const double u_plus = u_minus + primary.mass_kg * jump, V_plus = V_minus - m * jump;
    Eigen::Matrix4d R = Eigen::Matrix4d::Identity();
    R(1, 1) = 1 - primary.mass_kg * beta, R(1, 3) = primary.mass_kg * beta;
    R(3, 1) = m * beta, R(3, 3) = 1 - m * beta;
    const Eigen::Vector4d f_minus(u_minus, acceleration(body, t, y, u_minus), V_minus, acceleration(primary, t, X, V_minus)),
        f_plus(u_plus, acceleration(body, t, y, u_plus), V_plus, acceleration(primary, t, X, V_plus)),
        n(sigma, 0, -sigma, 0);
    const Eigen::Matrix4d S = R + (f_plus - R * f_minus) * n.transpose() / n.dot(f_minus);
    M = S * section_flight_matrix(spec, t - t_prev) * M;
    t_prev = t;
    flight = OscillatorMotion(body, t, y, u_plus);
    box = OscillatorMotion(primary, t, X, V_plus);
  }
  flight_gap(*spec.end_time_s);
  return section_flight_matrix(spec, *spec.end_time_s - t_prev) * M;
}

}  // namespace

const char* monodromy_method(const ImpactSequenceSpec& spec) {
  return spec.soft ? "stroboscopic map, monodromy from the contacts' variational equations (soft impacts)"
                   : "stroboscopic map, monodromy from saltation matrices (instantaneous impacts)";
}

ImpactSequenceSpec in_flight_from(ImpactSequenceSpec spec, double t0_s, double y0_m, double u0_mps) {
  spec.t0_s = t0_s;
  spec.y0_m = y0_m;
  spec.u0_mps = u0_mps;
  spec.carried_by = -1;
  spec.energy = false;
  spec.sampled = ImpactSequenceSpec::Sampled::none;
  return spec;
}

ImpactSequenceSpec flow_spec(ImpactSequenceSpec spec, double t0_s, const Eigen::VectorXd& z, double t_end_s) {
  spec = in_flight_from(std::move(spec), t0_s, z(0), z(1));
  if (!spec.prescribed) spec.X0_m = z(2), spec.V0_mps = z(3);
  spec.transient = 0;
  spec.impacts = max_shaker_impacts;
  spec.end_time_s = t_end_s;
  return spec;
}

namespace {
constexpr std::string_view coordinates[] = {"position_m", "velocity_mps", "box_position_m", "box_velocity_mps"};
}  // namespace

std::span<const std::string_view> section_coordinates(const ImpactSequenceSpec& spec) {
  return std::span(coordinates).first(spec.prescribed ? 2 : 4);
}

Eigen::VectorXd section_state(const ImpactSequenceSpec& spec, const ImpactSequence& run) {
  if (spec.prescribed) return Eigen::Vector2d(run.end_position_m, run.end_velocity_mps);
  return Eigen::Vector4d(run.end_position_m, run.end_velocity_mps, run.end_box_position_m, run.end_box_velocity_mps);
}

double smallest_gap_m(const ImpactSequenceSpec& spec, double t_s, const Eigen::VectorXd& z) {
  const double X = spec.prescribed ? spec.prescribed->position_m(t_s) : z(2);
  double gap = std::numeric_limits<double>::infinity();
  for (const SequenceWall& w : spec.walls) gap = std::min(gap, w.sigma * (z(0) - X - w.offset_m));
  return gap;
}

StroboscopicMap::StroboscopicMap(ImpactSequenceSpec spec, double section_phase, int cycles)
    : t_s_(section_phase / spec.frequency_Hz), cycles_(cycles) {
  if (spec.soft && !spec.soft_tangent) throw std::invalid_argument("StroboscopicMap: soft impacts with their tangents");
  if (cycles < 1) throw std::invalid_argument("StroboscopicMap: cycles >= 1");
  const Eigen::VectorXd origin = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(section_coordinates(spec).size()));
  const double t_end = t_s_ + cycles / spec.frequency_Hz;
  spec_ = flow_spec(std::move(spec), t_s_, origin, t_end);
}

double StroboscopicMap::smallest_gap_m(const Eigen::VectorXd& z) const { return hertzdash::smallest_gap_m(spec_, t_s_, z); }

SectionImage StroboscopicMap::operator()(const Eigen::VectorXd& z) const {
  SectionImage image{.state = z, .monodromy = Eigen::MatrixXd::Identity(z.size(), z.size()), .impacts = {},
                     .min_impact_speed_mps = std::numeric_limits<double>::infinity(),
                     .min_flight_gap_m = std::numeric_limits<double>::infinity(), .failure = {}};
  if (!z.allFinite()) {  // a Newton step through a singular matrix: refused before any contact sees it
    image.failure = "a state that is not finite";
    return image;
  }
  if (!(smallest_gap_m(z) > 0)) {
    image.failure = fmt::format("the state (y = {:.9g} m, u = {:.9g} m/s) is not {}", z(0), z(1),
                                spec_.walls.size() == 1 ? "above the wall" : "between the walls");
    return image;
  }
  ImpactSequence run = run_impact_sequence(flow_spec(spec_, t_s_, z, *spec_.end_time_s));
  if (run.sticking_episodes > 0 || run.end_carried) {
    image.failure = "the body is carried by a wall on the way (a sticking orbit: the map is not smooth there)";
    return image;
  }
  if (!(run.end_time_s == *spec_.end_time_s)) {
    image.failure = run.end_reason;
    return image;
  }
  if (!spec_.prescribed) {
    image.monodromy = own_box_monodromy(spec_, t_s_, z, run, image);
    if (!image.failure.empty()) return image;
    image.state = section_state(spec_, run);
    image.impacts = std::move(run.impacts);
    return image;
  }
  const ForcedOscillator& body = spec_.body;
  const OscillatorMotion& box = *spec_.prescribed;
  const double e = spec_.restitution;
  Eigen::Matrix2d M = Eigen::Matrix2d::Identity();
  double t_prev = t_s_;
  OscillatorMotion flight(body, t_s_, z(0), z(1));
  auto flight_gap = [&](double t_end) {
    image.min_flight_gap_m =
        std::min(image.min_flight_gap_m, min_interior_gap(flight, box, spec_.walls, t_prev, t_end, spec_.frequency_Hz));
  };
  for (const SequenceImpact& i : run.impacts) {
    const double t = i.time_s, V = box.velocity_mps(t), A = box.acceleration_mps2(t);
    const SequenceWall& w = spec_.walls[static_cast<std::size_t>(i.wall)];
    const double sigma = w.sigma, y = box.position_m(t) + w.offset_m;
    const double u_minus = V - sigma * i.impact_speed_mps;
    const Eigen::Matrix2d to_onset = flight_matrix(body, t - t_prev);
    flight_gap(t);
    if (!spec_.soft) {
      // S = R + (f+ - R f- - r_t) n^T / (n.f- + dh/dt); n/(n.f- + dh/dt) = (1, 0)/(u- - V).
      const double u_plus = V + sigma * i.rebound_speed_mps;
      Eigen::Matrix2d R;
      R << 1, 0, 0, -e;
      const Eigen::Vector2d f_minus(u_minus, acceleration(body, t, y, u_minus)),
          f_plus(u_plus, acceleration(body, t, y, u_plus)), r_t(0, (1 + e) * A);
      Eigen::Matrix2d S = R;
      S.col(0) += (f_plus - R * f_minus - r_t) / (u_minus - V);
      M = S * to_onset * M;
      t_prev = t;
      flight = OscillatorMotion(body, t, y, u_plus);
    } else {
      const double v0 = i.impact_speed_mps, t_sep = t + i.contact_time_s;
      if (!(t_sep < *spec_.end_time_s)) {
        image.failure = fmt::format("the contact beginning at t = {:.9g} s spans the section's time", t);
        return image;
      }
      const ContactTangent c = spec_.soft_tangent(i.wall, t, v0, 0, 0, soft_contact_window_s(spec_.frequency_Hz));
      if (!c.separated) {
        image.failure = fmt::format("the contact beginning at t = {:.9g} s did not end within {:g} drive cycles", t,
                                    soft_contact_window_cycles);
        return image;
      }
      const double V_sep = box.velocity_mps(t_sep), A_sep = box.acceleration_mps2(t_sep);
      const double y_sep = box.position_m(t_sep) + w.offset_m, u_plus = V_sep + sigma * i.rebound_speed_mps;
      Eigen::Matrix2d P, Q, J = c.jacobian;
      P << sigma / v0, 0, (A - acceleration(body, t, y, u_minus)) / v0, -sigma;
      Q << V_sep - u_plus, 0, A_sep - acceleration(body, t_sep, y_sep, u_plus), sigma;
      J(0, 0) += 1;  // t_sep = t_on + t_c
      M = Q * J * P * to_onset * M;
      t_prev = t_sep;
      flight = OscillatorMotion(body, t_sep, y_sep, u_plus);
    }
    image.min_impact_speed_mps = std::min(image.min_impact_speed_mps, i.impact_speed_mps);
  }
  M = flight_matrix(body, *spec_.end_time_s - t_prev) * M;
  flight_gap(*spec_.end_time_s);
  image.state = section_state(spec_, run);
  image.monodromy = M;
  image.impacts = std::move(run.impacts);
  return image;
}

}  // namespace hertzdash
