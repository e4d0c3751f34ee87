// The physics behind the rods_h20 and height_sweep figures and the nylon-modulus bands
// of Figs. 5 and 6: similarity of the paper's model (law "hongo") without gravity.
//
// Scale x by X* = (m v0^2 / K)^{2/5} and t by X*/v0. The spring K x^{3/2} becomes
// dimensionless; the dashpot c_e xdot = K tau x^{1/2} xdot with tau = 2 zeta / omega_n,
// omega_n = sqrt((4K/5m) X^{1/2}) and X ~ X* (eq. 11), gives tau v0 / X* = const: it
// depends on e only. Hence, at fixed e and g = 0,
//   P_max ~ K X*^{3/2} = K^{2/5} m^{3/5} v0^{6/5},  x_max ~ X*,  t_c ~ X*/v0,
//   e_effective independent of K, m and v0.
// So the height sweep must follow the Hertz exponents exactly without gravity, and a
// band over the nylon modulus is a rescaling of one curve.
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_history.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace hertzdash;

namespace {

DropTestSetup weightless(double v0, double ball_E_Pa, double mass_kg) {
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.gravity_mps2 = 0.0;
  s.impact_velocity_mps = v0;
  s.ball.E_Pa = ball_E_Pa;
  s.mass_kg = mass_kg;
  validate(s);
  return s;
}

}  // namespace

TEST_CASE("without gravity the paper's model is self-similar in v0, K and m", "[similarity]") {
  SolverSettings solver;
  solver.rtol = 1e-10;
  solver.atol = 1e-16;  // of X and v0: the absolute part far below rtol |y|
  ImpactSimulator sim(solver);
  const DropTestSetup base = weightless(0.6, 2.0e9, 0.778);
  const ImpactSummary a = sim.run<HongoPaper>(base);
  REQUIRE(a.separated);

  // Three changes of scale, each against the base run. With rtol 1e-10 the accumulated
  // error over ~1e2 steps is ~1e-8; event times are located to roundoff of that. 1e-6
  // relative leaves two orders of margin while a wrong exponent (e.g. 1 instead of 6/5
  // for a doubling of v0: 2^{0.2} = 1.15) fails by five orders.
  struct Case { const char* what; DropTestSetup setup; };
  const double K0 = hertz_stiffness(base);
  for (const Case& c : {Case{"v0 x 2.5", weightless(1.5, 2.0e9, 0.778)}, Case{"nylon E 1.2 GPa", weightless(0.6, 1.2e9, 0.778)},
                        Case{"nylon E 2.9 GPa", weightless(0.6, 2.9e9, 0.778)}, Case{"mass / 3", weightless(0.6, 2.0e9, 0.778 / 3)}}) {
    INFO(c.what);
    const ImpactSummary b = sim.run<HongoPaper>(c.setup);
    REQUIRE(b.separated);
    const double k = hertz_stiffness(c.setup) / K0, m = c.setup.mass_kg / base.mass_kg,
                 v = *c.setup.impact_velocity_mps / *base.impact_velocity_mps;
    const double X = std::pow(m * v * v / k, 0.4);  // ratio of the length scales X*
    CHECK(b.peak_force_N / a.peak_force_N == Approx(k * std::pow(X, 1.5)).epsilon(1e-6));
    CHECK(b.max_deformation_m / a.max_deformation_m == Approx(X).epsilon(1e-6));
    CHECK(b.contact_time_s / a.contact_time_s == Approx(X / v).epsilon(1e-6));
    CHECK(b.e_effective == Approx(a.e_effective).epsilon(1e-6));
  }
}

TEST_CASE("an impact history is free flight before onset and after separation", "[similarity]") {
  // ImpactHistory extends the contact trace by exact ballistic motion, x = x0 + v s + g s^2/2.
  SolverSettings solver;
  solver.max_step_s = 1e-6;
  ImpactSimulator sim(solver);
  const DropTestSetup s = paper_setup(load_paper_parameters(), "duralumin-c", 0.02);
  std::vector<TraceSample> trace;
  const ImpactSummary r = sim.run<HongoPaper>(s, &trace);
  const TraceSample first = trace.front(), last = trace.back();
  const ImpactHistory h(trace, s.gravity_mps2);
  const double g = s.gravity_mps2, v0 = r.impact_velocity_mps, tc = r.contact_time_s;
  CHECK(h.contact_time_s() == Approx(tc).epsilon(1e-14));
  const double before = -2e-4;
  CHECK(h.at(before).displacement_m == Approx(v0 * before + 0.5 * g * before * before).epsilon(1e-14));
  CHECK(h.at(before).force_N == 0.0);
  const double after = 3e-4;
  CHECK(h.at(tc + after).displacement_m ==
        Approx(last.x_m + last.xdot_mps * after + 0.5 * g * after * after).epsilon(1e-12));
  CHECK(h.at(tc + after).velocity_mps == Approx(-r.rebound_velocity_mps + g * after).epsilon(1e-12));
  // Inside contact it reproduces the samples it was built from.
  CHECK(h.at(0.0).velocity_mps == Approx(first.xdot_mps).epsilon(1e-14));
  const TraceSample mid = trace[trace.size() / 2];
  CHECK(h.at(mid.t_s - first.t_s).force_N == Approx(mid.force_N).epsilon(1e-12));
}
