// The contact system over an environment (model/contact_system.hpp) with the oscillator's stop
// (model/contact_environments.hpp, HarmonicForcing), run by the soft-contact runner
// (simulation/run/soft_contact.hpp): the free Hertz impact's closed form where the oscillator's
// spring, damper and drive are off, and the energy balance where they are on.
#include "hertzdash/integrators/fixed_step.hpp"
#include "hertzdash/integrators/rk4.hpp"
#include "hertzdash/model/contact_environments.hpp"
#include "hertzdash/model/contact_system.hpp"
#include "hertzdash/model/damping/laws/undamped.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"  // to_string(IntegratorKind)
#include "hertzdash/simulation/run/soft_contact.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <string>

using namespace hertzdash;

namespace {

/// The paper's steel rod on its ball (K, m), at the impact speed of a 2 cm drop.
DropTestSetup steel() { return paper_setup(load_paper_parameters(), "steel", 0.02); }

}  // namespace

TEST_CASE("contact system: the oscillator's stop without spring, damper or drive is the free Hertz impact",
          "[contact]") {
  // k = c = F0 = 0 (and no gravity): x'' = -K x^{3/2}/m, the undamped Hertz impact whatever the
  // stop's position d, with the closed forms of model/hertz.hpp: contact time (4/5) B(2/5, 1/2)
  // X/v0, peak force K X^{3/2}, rebound speed v0 (energy conserved). Every row in regularising
  // variables (the Taylor row evaluates the environment on power series) at rtol 1e-11: the
  // system is smooth, so the global error follows the tolerance; 1e-8 leaves a factor 1000 for
  // its accumulation over the contact's steps.
  const DropTestSetup s = steel();
  const double v0 = 0.6, K = hertz_stiffness(s);
  const UndampedHertzImpact h = undamped_hertz_impact(K, s.mass_kg, v0);
  for (const IntegratorKind row : {IntegratorKind::dopri5_regularized, IntegratorKind::gbs8_regularized,
                                   IntegratorKind::taylor_regularized, IntegratorKind::cvode_regularized}) {
    INFO(to_string(row));
    SolverSettings solver;
    solver.integrator = row;
    solver.rtol = 1e-11;
    const auto contact = make_soft_contact<HarmonicForcing>("none", s, solver, "oscillator");
    CHECK(contact->integrator_used() == row);
    const auto c = contact->run(HarmonicForcing{.omega_rad_per_s = 100.0, .stop_m = 0.01, .t_onset_s = 0.3}, v0,
                                10.0 * h.contact_time_s);
    REQUIRE(c.separated);
    CHECK(c.contact_time_s == Approx(h.contact_time_s).epsilon(1e-8));
    CHECK(c.peak_force_N == Approx(h.peak_force_N).epsilon(1e-8));
    CHECK(c.rebound_speed_mps == Approx(v0).epsilon(1e-8));
    // The drive's phase (S, C) = (sin w t, cos w t) carried to the contact's end, t = 0.3 s + tc.
    const double w_t = 100.0 * (0.3 + c.contact_time_s);
    CHECK(c.environment[0] == Approx(std::sin(w_t)).margin(1e-8));
    CHECK(c.environment[1] == Approx(std::cos(w_t)).margin(1e-8));
  }
}

TEST_CASE("contact system: the oscillator's energy changes by the drive's and the damper's work only", "[contact]") {
  // m x'' + c x' + k x = F0 cos(w t) - F, F = K (x - d)^{3/2} on the stop (undamped law), so with
  // u^2 = x - d, v = x' the energy E = m v^2/2 + k x^2/2 + (2/5) K u^5 has
  //   dE/dt = v (m v' + k x + K u^3) = v (F0 cos(w t) - c v)   (d/dt (2/5) K u^5 = K u^3 v),
  // and over the contact E_end - E_0 = W_drive - W_damper, W_drive = int F0 cos(w t) v dt,
  // W_damper = int c v^2 dt, both integrated along tau (dt = 2u dtau) by the trapezoidal rule.
  // Sizes from the free impact's X, peak force P and contact time tc: spring force 0.2 P at the
  // stop d = 10 X, damping force 0.1 P at v0, drive 0.3 P with period 5 tc, the contact
  // beginning at a quarter period (the drive's force zero, then pulling away). Then E ~ P X and
  // each work is ~0.1 P X: W_damper ~ c v0^2 tc / 2, and W_drive = F0 int cos(w t) dx =
  // F0 w int x sin(w t) dt ~ F0 w X tc / 2 (x returns to 0), both checked below, so that a term
  // of the wrong sign errs by that much. RK4 in tau with 20000
  // steps over the contact: its error ~(1/20000)^4, the trapezoid's ~(1/20000)^2 / 12 ~ 2e-10 of
  // the works: 1e-8 P X bounds both.
  const DropTestSetup s = steel();
  const double v0 = 0.6, K = hertz_stiffness(s), m = s.mass_kg;
  const UndampedHertzImpact h = undamped_hertz_impact(K, m, v0);
  const double X = h.max_deformation_m, P = h.peak_force_N, tc = h.contact_time_s, d = 10.0 * X;
  const double w = 2.0 * std::numbers::pi / (5.0 * tc);
  const HarmonicForcing stop{.stiffness_N_per_m = 0.2 * P / d, .damping_N_s_per_m = 0.1 * P / v0,
                            .force_amplitude_N = 0.3 * P, .omega_rad_per_s = w, .stop_m = d,
                            .t_onset_s = 0.5 * std::numbers::pi / w};
  using System = ContactSystem<Undamped, HarmonicForcing>;
  System sys(ImpactConditions{K, m, v0, s.restitution}, s.damping, stop, 20.0 * tc);
  auto energy = [&](const System::State& y) {
    const double x = d + y[0] * y[0];
    return 0.5 * m * y[1] * y[1] + 0.5 * stop.stiffness_N_per_m * x * x + 0.4 * K * std::pow(y[0], 5);
  };
  struct Works {
    const HarmonicForcing& stop;
    double tau = 0, drive_rate = 0, damper_rate = 0, drive = 0, damper = 0;
    bool separated = false;
    void on_step(double t, const System::State& y) {
      // The integrands along tau: dW/dtau = 2u (F0 C v) and 2u (c v^2).
      const double two_u = 2.0 * y[0], drive_now = two_u * stop.force_amplitude_N * y[4] * y[1],
                   damper_now = two_u * stop.damping_N_s_per_m * y[1] * y[1];
      drive += 0.5 * (t - tau) * (drive_rate + drive_now);
      damper += 0.5 * (t - tau) * (damper_rate + damper_now);
      tau = t, drive_rate = drive_now, damper_rate = damper_now;
    }
    void on_event(int which, double, const System::State&, EventAction) {
      separated |= which == event_index(ContactEvent::separation);
    }
  } works{stop};
  auto y = sys.initial_state();
  const double E0 = energy(y);
  const double tau_step = tc / (2.0 * std::sqrt(X)) / 20000.0;  // the contact's tau extent is ~tc / (2 X^{1/2})
  integrate_fixed_step<ClassicalRk4>(sys, y, 0.0, 1e6 * tau_step, FixedStepOptions{tau_step, true}, works);
  REQUIRE(works.separated);
  CHECK(std::abs(works.drive) > 0.05 * P * X);
  CHECK(works.damper > 0.05 * P * X);
  CHECK(energy(y) - E0 == Approx(works.drive - works.damper).margin(1e-8 * P * X));
}

TEST_CASE("contact system: a soft contact refuses the physical variables, the tension clamp and the elastic rod, "
          "naming the command",
          "[contact]") {
  DropTestSetup s = steel();
  SolverSettings solver;
  solver.integrator = IntegratorKind::dopri5;
  auto refused_key = [&](const DropTestSetup& setup) {
    try {
      make_soft_contact<HarmonicForcing>("hongo", setup, solver, "oscillator");
    } catch (const InvalidParameter& e) {
      CHECK(e.valid_range.find("`oscillator`") != std::string::npos);
      return e.key;
    }
    return std::string("none");
  };
  CHECK(refused_key(s) == "integrator");
  solver.integrator = IntegratorKind::taylor_regularized;
  s.no_tension = true;
  CHECK(refused_key(s) == "no-tension");
  s.no_tension = false;
  s.elastic_rod = ElasticRodSetup{};
  CHECK(refused_key(s) == "rod-model");
}
