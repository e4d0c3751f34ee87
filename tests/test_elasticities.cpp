// CVODES forward sensitivities of the paper's impact (validation/common/contact_sensitivity,
// paper_law_elasticities) against central finite differences of the full drop-test
// simulation (simulation/run/impact_simulator: free fall + contact, events located).
//
// The two share no code beyond the force law: the FD side perturbs the physical set-up
// (E_b, nu_b, e, m, h, R) and lets the model recompute K, v0, zeta, omega_n; the CVODES
// side differentiates the contact ODE and applies the closed-form chain rule.
//
// FD error budget for a central difference of ln y in ln p with relative step d:
//   truncation  ~ d^2/6 |d^3 ln y / d ln p^3|, d = 1e-3: ~2e-7 for third log-derivatives O(1);
//   solver      ~ eps_y / d with eps_y ~ 1e-10 (CVODE rtol 1e-12; events located; the peak
//               force is stationary so its timing error enters squared): ~1e-7.
// The CVODES side is accurate to ~1e-8 (rtol 1e-10, sensitivities in the error test).
// Elasticities are O(1e-3..1); an absolute tolerance of 2e-6 is ~5x the budget and still
// resolves the smallest elasticities (e_effective to E, m, R, h, which act only through
// gravity during contact) to a few per cent of their size.
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "validation/common/paper_law_elasticities.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

using namespace hertzdash;

namespace {

struct Outputs {
  double e_eff, peak, tc;
};

Outputs simulate(ImpactSimulator& sim, const DropTestSetup& s) {
  const ImpactSummary r = sim.run<HongoPaper>(s);
  REQUIRE(r.separated);
  return {r.e_effective, r.peak_force_N, r.contact_time_s};
}

}  // namespace

TEST_CASE("CVODES elasticities agree with central differences of the full simulation", "[elasticities]") {
  SolverSettings solver;
  solver.rtol = 1e-12;
  solver.atol = 1e-16;
  ImpactSimulator sim(solver);
  const double d = 1e-3;
  const double tol = 2e-6;
  for (const char* rod : {"steel", "duralumin-c"})
    for (ZetaForm z : {ZetaForm::paper, ZetaForm::exact}) {
      DropTestSetup base = paper_setup(load_paper_parameters(), rod, 0.020);
      base.damping.zeta_form = z;
      const PaperLawElasticities el = paper_law_elasticities(base);
      // The values themselves: same impact, two solvers (1e-8 relative: both well inside).
      const Outputs y0 = simulate(sim, base);
      CHECK(el.e_effective == Approx(y0.e_eff).epsilon(1e-8));
      CHECK(el.peak_force_N == Approx(y0.peak).epsilon(1e-8));
      CHECK(el.contact_time_s == Approx(y0.tc).epsilon(1e-8));
      std::printf("%s, zeta %s: elasticity  CVODES / central difference (d = %g)\n", rod, to_string(z), d);
      std::printf("  %-12s %12s %12s %12s %12s %12s %12s\n", "p", "e_eff", "FD", "P_max", "FD", "t_c", "FD");
      for (int p = 0; p < elasticity_parameter_count; ++p) {
        DropTestSetup up = base, down = base;
        elasticity_parameter(up, p) *= 1 + d;
        elasticity_parameter(down, p) *= 1 - d;
        const Outputs a = simulate(sim, up), b = simulate(sim, down);
        const double dlnp = std::log((1 + d) / (1 - d));
        const double fd_e = std::log(a.e_eff / b.e_eff) / dlnp, fd_P = std::log(a.peak / b.peak) / dlnp,
                     fd_t = std::log(a.tc / b.tc) / dlnp;
        std::printf("  %-12s %12.8f %12.8f %12.8f %12.8f %12.8f %12.8f\n", elasticity_parameter_name(p).data(),
                    el.e_effective_el[p], fd_e, el.peak_force_el[p], fd_P, el.contact_time_el[p], fd_t);
        CAPTURE(rod, to_string(z), elasticity_parameter_name(p));
        CHECK(el.e_effective_el[p] == Approx(fd_e).margin(tol));
        CHECK(el.peak_force_el[p] == Approx(fd_P).margin(tol));
        CHECK(el.contact_time_el[p] == Approx(fd_t).margin(tol));
      }
    }
}

TEST_CASE("elasticities obey the dimensional identities of the Hertz impact", "[elasticities]") {
  // Without gravity the undamped-scaled impact depends on K, m, v0 only through the scales
  // X* = (m v0^2/K)^{2/5}, T* = X*/v0, and the paper's tau*omega_n depends on e alone, so
  //   e_effective: independent of E_b, nu_b, m, h, R  (elasticities 0);
  //   P_max ~ K X*^{3/2} = K^{2/5} m^{3/5} v0^{6/5}:  d ln P/d ln m = 3/5, d ln P/d ln h = 3/5,
  //                                                  d ln P/d ln R = (2/5)(1/2) = 1/5;
  //   t_c ~ X*/v0 = K^{-2/5} m^{2/5} v0^{-1/5}:     d ln t_c/d ln m = 2/5, .../d ln h = -1/10,
  //                                                  d ln t_c/d ln R = -1/5.
  // These hold exactly with g = 0 (here: g -> 0 is emulated by a tiny g, 1e-9 m/s^2, with h
  // scaled so that v0 is unchanged); the CVODES solution meets them to its tolerance, 1e-7.
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.020);
  const double v0 = approach_speed(s);
  s.gravity_mps2 = 1e-9;
  s.height_m = v0 * v0 / (2 * s.gravity_mps2);
  const PaperLawElasticities el = paper_law_elasticities(s);
  for (int p : {p_ball_E, p_ball_nu, p_mass, p_height, p_radius}) CHECK(el.e_effective_el[p] == Approx(0).margin(1e-7));
  CHECK(el.peak_force_el[p_mass] == Approx(0.6).margin(1e-7));
  CHECK(el.peak_force_el[p_height] == Approx(0.6).margin(1e-7));
  CHECK(el.peak_force_el[p_radius] == Approx(0.2).margin(1e-7));
  CHECK(el.contact_time_el[p_mass] == Approx(0.4).margin(1e-7));
  CHECK(el.contact_time_el[p_height] == Approx(-0.1).margin(1e-7));
  CHECK(el.contact_time_el[p_radius] == Approx(-0.2).margin(1e-7));
}
