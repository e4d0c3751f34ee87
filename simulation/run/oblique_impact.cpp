// One oblique impact (simulation/run/oblique_impact.hpp): the law chosen by name among the
// registered ones, its force's jet type-erased (NormalForceJet), so that the oblique system and
// Dormand-Prince are compiled once.
#include "hertzdash/simulation/run/oblique_impact.hpp"

#include "hertzdash/integrators/dormand_prince.hpp"
#include "hertzdash/model/contact_system.hpp"
#include "hertzdash/model/damping/registered_law_types.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/oblique_contact.hpp"
#include "hertzdash/model/oblique_contact_mdr.hpp"
#include "hertzdash/model/parameter.hpp"
#include "hertzdash/model/tangential/registry.hpp"
#include "hertzdash/model/two_spheres.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"  // with_calibrated_time_constant

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace hertzdash {

namespace {

/// A law's force and its partials: exact for a law with force_of_root, else central differences
/// with steps 1e-4 of u (1e-7 of its scale at u = 0 only) and 1e-6 of v0: truncation about 1e-8
/// relative, round-off 1e-12. (Forward differences, 1e-6 relative, made the cone's rate noisy
/// enough for the stick/slip test to chatter; a floor of 1e-7 of the scale on the step made it
/// a tenth of u at the onset probe, and dF/du of an x^{1/4} dashpot wrong by 11 % near onset.)
template <DampingLaw Law>
class LawNormalForce final : public NormalForceJet {
 public:
  LawNormalForce(const ImpactConditions& c, const DampingSettings& s, double u_scale, double v_scale)
      : law_(c, s), du_(1e-7 * u_scale), dv_(1e-6 * v_scale) {}
  ForceJet at(double u, double xdot) const override {
    if constexpr (RootPolynomialLaw<Law>) {
      return law_.force_of_root(root_leaf(u), rate_leaf(xdot));
    } else {
      auto F = [&](double r, double rate) { return law_.force(r * r, rate); };
      const double du = u > 0 ? 1e-4 * u : du_;
      return {F(u, xdot), {(F(u + du, xdot) - F(u - du, xdot)) / (2 * du), (F(u, xdot + dv_) - F(u, xdot - dv_)) / (2 * dv_)}};
    }
  }

 private:
  Law law_;
  double du_, dv_;
};

/// What a run observes of either system (its state opens with u and v; its first three events are
/// separation, the normal force's maximum and the observation time): the stopping event that is a
/// switch of the contact (a system's own, by index; -1 for none) and the largest normal force.
template <class State>
struct Observer {
  bool separated = false;
  int switch_event = -1;
  double peak_force_N = 0;
  const NormalForceJet* force = nullptr;
  // The largest force: at the located maxima (dF/dtau through 0), at every step, and at onset
  // (where a dashpot's force peaks for a heavily damped kelvin-voigt: no maximum inside).
  void note(const State& y) { peak_force_N = std::max(peak_force_N, force->at(std::max(y[0], 0.0), y[1]).value); }
  void on_step(double, const State& y) { note(y); }
  void on_event(int which, double, const State& y, EventAction) {
    if (which == static_cast<int>(ObliqueContactEvent::separation)) separated = true;
    else if (which == static_cast<int>(ObliqueContactEvent::peak_normal_force)) note(y);
    else if (which != static_cast<int>(ObliqueContactEvent::observation_time)) switch_event = which;
  }
};

void validate(const ObliqueImpactSpec& s) {
  if (!find_tangential_model(s.tangential_model))
    throw InvalidParameter("tangential-model", s.tangential_model, "one of " + registered_tangential_model_names(", "));
  if (!(s.friction >= 0 && std::isfinite(s.friction))) throw InvalidParameter("friction", format_value(s.friction), ">= 0");
  if (!(s.incidence_angle_deg >= 0 && s.incidence_angle_deg < 90))
    throw InvalidParameter("incidence-angle", format_value(s.incidence_angle_deg), "in [0, 90) degrees from the normal");
  if (!(s.speed_mps > 0 && std::isfinite(s.speed_mps)))
    throw InvalidParameter("impact-velocity", format_value(s.speed_mps), "> 0");
  if (!(s.inertia_factor > 0 && s.inertia_factor <= 1))
    throw InvalidParameter("inertia-factor", format_value(s.inertia_factor), "in (0, 1] (I / (m R^2): 2/5 solid, 2/3 thin shell)");
  if (!std::isfinite(s.spin_rad_per_s)) throw InvalidParameter("spin", format_value(s.spin_rad_per_s), "finite");
  if (!(s.tangential_damping_ratio >= 0 && s.tangential_damping_ratio < 1))
    throw InvalidParameter("tangential-damping", format_value(s.tangential_damping_ratio), "in [0, 1) (an underdamped sticking oscillator)");
  // A stiffness that depends on the force (mindlin-deresiewicz's theta) would make the dashpot's
  // coefficient depend on it too; its runs with a dashpot did not finish (the modes chattered).
  const TangentialModelInfo* model = find_tangential_model(s.tangential_model);
  if (s.tangential_damping_ratio > 0 && (model->remembers_reversals || model->resolves_contact_area))
    throw InvalidParameter("tangential-damping", format_value(s.tangential_damping_ratio),
                           "0 with the tangential model " + s.tangential_model +
                               " (its stiffness depends on the force or on the slip over the contact; the dashpot is offered with the other models)");
  if (model->resolves_contact_area && !(s.contact_cells >= 1 && s.contact_cells <= MdrObliqueContactSystem::max_cells))
    throw InvalidParameter("contact-cells", std::to_string(s.contact_cells),
                           fmt::format("in [1, {}]", MdrObliqueContactSystem::max_cells));
  if (s.linear_stiffness_N_per_m && !(*s.linear_stiffness_N_per_m > 0 && std::isfinite(*s.linear_stiffness_N_per_m)))
    throw InvalidParameter("tangential-stiffness", format_value(*s.linear_stiffness_N_per_m), "> 0");
  if (s.second) {
    if (!(s.second->inertia_factor > 0 && s.second->inertia_factor <= 1))
      throw InvalidParameter("second-inertia-factor", format_value(s.second->inertia_factor), "in (0, 1]");
    if (!std::isfinite(s.second->spin_rad_per_s))
      throw InvalidParameter("second-spin", format_value(s.second->spin_rad_per_s), "finite");
  }
}

/// Two spheres as one (model/oblique_contact.hpp's sphere on a flat): the normal contact of the
/// reduced mass m* and radius R* (model/two_spheres.hpp), and a sphere of mass m*, radius R* and
/// inertia factor kappa* whose slip obeys the pair's s' = T (1/m1 + 1/m2 + R1^2/I1 + R2^2/I2):
/// with w = w1 - w2 (w' = T/m*) and R* omega = R1 omega1 + R2 omega2, R*^2/I* = 1/(kappa1 m1) +
/// 1/(kappa2 m2), i.e. kappa* = 1 / (m* (1/(kappa1 m1) + 1/(kappa2 m2))), a mean of kappa1 and
/// kappa2 (kappa itself when they are equal).
struct EquivalentSphere {
  DropTestSetup setup;
  double inertia_factor, spin_rad_per_s;
};
EquivalentSphere equivalent_sphere(const ObliqueImpactSpec& spec, double v0) {
  if (!spec.second) return {spec.setup, spec.inertia_factor, spec.spin_rad_per_s};
  const SecondSphere& b = *spec.second;
  const Sphere first{spec.setup.ball_radius_m, spec.setup.mass_kg, spec.setup.ball}, second{b.radius_m, b.mass_kg, b.material};
  DropTestSetup setup = two_spheres_contact(spec.setup, first, second, v0);
  const double m = setup.mass_kg, R = setup.ball_radius_m;
  const double kappa = 1 / (m * (1 / (spec.inertia_factor * first.mass_kg) + 1 / (b.inertia_factor * b.mass_kg)));
  return {setup, kappa, (first.radius_m * spec.spin_rad_per_s + b.radius_m * b.spin_rad_per_s) / R};
}

/// Mindlin's 8 G* a at the undamped Hertz maximum overlap X of the normal impact at v0 of `setup`.
double matched_stiffness_N_per_m(const DropTestSetup& setup, double v0) {
  const double X = undamped_hertz_max_deformation_m(hertz_stiffness(setup), setup.mass_kg, v0);
  const TangentialPair pair{.shear_modulus_Pa = tangential_shear_modulus_Pa(setup.ball.E_Pa, setup.ball.nu, setup.rod.E_Pa,
                                                                            setup.rod.nu),
                            .radius_m = setup.ball_radius_m, .linear_stiffness_N_per_m = 0};
  return mindlin_stiffness_N_per_m(pair, {.overlap_m = X});
}

/// Integrates sys from y (at tau = 0) until separation or the observation time t_obs [s] by
/// Dormand-Prince, stopping at each switch of the contact (between sticking and sliding, of the
/// whole contact or of one cell, and for a model with memory at each reversal of the slip) and going
/// on from switched(y, event, progress), progress the piece's length in tau. A contact that switches
/// more than max_switches times is refused (no run here needs a hundredth). Returns the work.
template <class System, class Switched>
IntegrationStats integrate_switching(const System& sys, typename System::State& y, const DormandPrinceOptions& options,
                                     double t_obs, Observer<typename System::State>& observer, Switched&& switched) {
  constexpr int max_switches = 100000;
  observer.note(y);
  IntegrationStats work;
  const double tau_end = regularised_tau_end(t_obs, sys.state_scale());
  for (double tau = 0, switches = 0;; ++switches) {
    observer.switch_event = -1;
    const IntegrationStats piece = integrate_dormand_prince(sys, y, tau, tau_end, options, observer);
    work.add_work(piece);
    if (observer.separated || observer.switch_event < 0) return work;
    if (switches >= max_switches)
      throw std::runtime_error(fmt::format("the contact switched between sticking and sliding more than {} times", max_switches));
    y = switched(y, observer.switch_event, piece.t_final - tau);
    tau = piece.t_final;
  }
}

/// The result's fields from the state y after the contact of either system (both name their
/// components alike) and what its observer saw: for two spheres each sphere's velocities from the
/// pair's.
template <class System>
void read_final_state(const System& sys, const typename System::State& y, const Observer<typename System::State>& observer,
                      const ObliqueImpactSpec& spec, double m, double w0, double v0, ObliqueImpactResult& out) {
  using I = typename System::Index;
  const double vn = -y[I::v], s = sys.slip_mps(y);
  out.separated = observer.separated;
  out.peak_normal_force_N = observer.peak_force_N;
  out.contact_time_s = y[I::t];
  out.normal_restitution = vn / v0;
  out.tangential_velocity_after_mps = y[I::w];
  out.spin_after_rad_per_s = y[I::omega];
  if (spec.second) {
    // The tangential impulse J = m* (w_after - w0) on the first sphere, -J on the second.
    const SecondSphere& b = *spec.second;
    const double J = m * (y[I::w] - w0), m1 = spec.setup.mass_kg, R1 = spec.setup.ball_radius_m;
    out.tangential_velocity_after_mps = w0 + J / m1;
    out.spin_after_rad_per_s = spec.spin_rad_per_s + J / (spec.inertia_factor * m1 * R1);
    out.second_tangential_velocity_after_mps = -J / b.mass_kg;
    out.second_spin_after_rad_per_s = b.spin_rad_per_s + J / (b.inertia_factor * b.mass_kg * b.radius_m);
  }
  out.tangential_restitution = w0 != 0 ? y[I::w] / w0 : std::nan("");
  out.rebound_angle_deg = std::atan(s / vn) * 180 / std::numbers::pi;
  out.centre_rebound_angle_deg = std::atan(y[I::w] / vn) * 180 / std::numbers::pi;
  out.sliding_fraction = y[I::t_slide] / y[I::t];
  out.tangential_work_J = y[I::W];
}

}  // namespace

double matched_linear_stiffness_N_per_m(const ObliqueImpactSpec& spec) {
  const double v0 = spec.speed_mps * std::cos(spec.incidence_angle_deg * std::numbers::pi / 180);
  return matched_stiffness_N_per_m(equivalent_sphere(spec, v0).setup, v0);
}

ObliqueImpactResult run_oblique_impact(const ObliqueImpactSpec& spec) {
  validate(spec);
  const double theta = spec.incidence_angle_deg * std::numbers::pi / 180;
  const double v0 = spec.speed_mps * std::cos(theta), w0 = spec.speed_mps * std::sin(theta);
  const EquivalentSphere equivalent = equivalent_sphere(spec, v0);
  DropTestSetup setup = equivalent.setup;
  setup.impact_velocity_mps = v0;
  const double m = setup.mass_kg, K = hertz_stiffness(setup), X = undamped_hertz_max_deformation_m(K, m, v0);
  std::unique_ptr<NormalForceJet> force;
  with_damping_law(spec.law, [&]<class Law>(std::type_identity<Law>) {
    DropTestSetup calibrated = setup;
    if constexpr (MaterialTimeConstantLaw<Law>)
      if (!Law::material_constant(setup.damping)) calibrated = with_calibrated_time_constant<Law>(setup);
    force = std::make_unique<LawNormalForce<Law>>(ImpactConditions{K, m, v0, setup.restitution}, calibrated.damping,
                                                   std::sqrt(X), v0);
  });
  if (!force) throw InvalidParameter("damping", spec.law, "a registered damping law");

  ObliqueImpactResult out;
  TangentialContact c{.model = find_tangential_model(spec.tangential_model), .pair = {}, .friction = spec.friction,
                      .inertia_factor = equivalent.inertia_factor, .radius_m = setup.ball_radius_m,
                      .damping_ratio = spec.tangential_damping_ratio};
  c.pair.shear_modulus_Pa = tangential_shear_modulus_Pa(setup.ball.E_Pa, setup.ball.nu, setup.rod.E_Pa, setup.rod.nu);
  c.pair.radius_m = setup.ball_radius_m;
  if (c.model->name == "linear-spring") {
    c.pair.linear_stiffness_N_per_m = spec.linear_stiffness_N_per_m.value_or(matched_stiffness_N_per_m(setup, v0));
    out.linear_stiffness_N_per_m = c.pair.linear_stiffness_N_per_m;
  }
  // Followed for at most 100 undamped Hertz contact times: a contact that lasts longer has not
  // separated (a law whose dashpot holds the sphere).
  const double t_obs = 100 * undamped_hertz_contact_time_factor() * X / v0;
  const ObliqueOnset onset{v0, w0, equivalent.spin_rad_per_s};
  const DormandPrinceOptions options{.rtol = spec.solver.rtol, .atol = spec.solver.atol, .singular_points = false};
  if (c.model->resolves_contact_area) {
    const MdrObliqueContactSystem sys(*force, c, K, m, onset, t_obs, spec.contact_cells);
    MdrObliqueContactSystem::State y = sys.initial_state();
    Observer<MdrObliqueContactSystem::State> observer{.force = force.get()};
    out.work = integrate_switching(sys, y, options, t_obs, observer, [&](const auto& z, int, double progress) {
      // A switch undone at once, or one that leaves a cell's switch function at 0 (which would
      // hide every later switch): settle again, looking ahead past the jump in the rates.
      const MdrObliqueContactSystem::State settled = sys.settled(z, progress < sys.probe_step());
      return sys.switches_armed(settled) ? settled : sys.settled(z, true);
    });
    read_final_state(sys, y, observer, spec, m, w0, v0, out);
    return out;
  }
  const ObliqueContactSystem sys(*force, c, K, m, onset, t_obs);
  ObliqueContactSystem::State y = sys.initial_state();
  Observer<ObliqueContactSystem::State> observer{.force = force.get()};
  out.work = integrate_switching(sys, y, options, t_obs, observer, [&](const auto& z, int which, double) {
    using E = ObliqueContactEvent;
    if (which == static_cast<int>(E::slip_reversal)) return sys.reversal_state(z);  // T* recorded
    if (which == static_cast<int>(E::stick_end)) return sys.settled_mode(z, false, true);
    return sys.stuck_state(z);
  });
  read_final_state(sys, y, observer, spec, m, w0, v0, out);
  return out;
}

}  // namespace hertzdash
