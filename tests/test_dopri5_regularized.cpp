// The fast path dopri5-regularized (simulation/run/regularized_impact.hpp): the
// free fall in closed form, the contact in regularising variables u = x^{1/2},
// dt/dtau = 2u (model/contact_system.hpp) with Dormand-Prince 5(4), and the
// laws' declarations force_of_root(u, v) = force(u^2, v) (RootPolynomialLaw) it
// relies on.
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/damping/laws/tsuji_dem.hpp"
#include "hertzdash/model/damping/laws/undamped.hpp"
#include "hertzdash/model/damping/registered_law_types.hpp"
#include "hertzdash/model/force_jet.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"
#include "undamped_hertz_errors.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace {

using namespace hertzdash;

DropTestSetup steel_drop() {
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  validate(s);
  return s;
}

SolverSettings dopri5(IntegratorKind kind, double tol) {
  SolverSettings s;
  s.integrator = kind;
  s.rtol = tol;
  s.atol = tol * 1e-4;  // of the impact's scales X^{1/2}, v0, t_H (the benchmark's pair)
  return s;
}

/// Largest relative difference of e_eff, peak force, peak deformation, contact time.
double largest_difference(const ImpactSummary& a, const ImpactSummary& b) {
  auto rel = [](double p, double q) { return std::abs(p / q - 1); };
  return std::max({rel(a.e_effective, b.e_effective), rel(a.peak_force_N, b.peak_force_N),
                   rel(a.max_deformation_m, b.max_deformation_m), rel(a.contact_time_s, b.contact_time_s)});
}

}  // namespace

TEST_CASE("dopri5-regularized: undamped Hertz drop, onset in closed form and e_eff = 1",
          "[dopri5][regularized]") {
  // Undamped law, dropped from rest at h = 20 mm under gravity. Exact: onset at
  // t_on = sqrt(2h/g) with v0 = sqrt(2gh); the contact (spring and gravity both
  // conservative) returns the rod through x = 0 at speed v0, so e_eff = 1. With
  // gravity the peak deformation solves (1/2) m v0^2 + m g X = (2/5) K X^{5/2}; its
  // gravity-free value X0 = (5 m v0^2/4K)^{2/5} is within m g X0 / (m v0^2) ~ 1e-2
  // relative, so this test compares e_eff and the onset only, and the closed forms
  // for X, F and t_c without gravity in the next case. e_eff within 10 tol (the
  // bound of the next case; the undamped contact is time-reversible, so its e error
  // partly cancels and falls below that).
  const DropTestSetup setup = steel_drop();
  const double v0 = std::sqrt(2 * setup.gravity_mps2 * setup.height_m);
  std::printf("dopri5-regularized undamped drop: tol, |e-1|, rhs evaluations\n");
  for (double tol : {1e-6, 1e-8, 1e-10}) {
    ImpactSimulator sim(dopri5(IntegratorKind::dopri5_regularized, tol));
    const ImpactSummary s = sim.run<Undamped>(setup);
    REQUIRE(s.separated);
    // The onset is the closed form itself: exact to rounding.
    CHECK(s.t_onset_s == Approx(v0 / setup.gravity_mps2).epsilon(1e-15));
    CHECK(s.impact_velocity_mps == Approx(v0).epsilon(1e-15));
    const double ee = std::abs(s.e_effective - 1);
    std::printf("  %.0e  %.3e  %ld\n", tol, ee, s.work.rhs_evaluations);
    CHECK(ee <= 10 * tol);
  }
}

TEST_CASE("dopri5-regularized: the paper's law and DEM agree with dopri5 in the physical variables",
          "[dopri5][regularized]") {
  // Two integrations of the same drop in different variables (and, for the fall,
  // closed form against integration) at tolerance 1e-11: each within tens of tol of
  // the truth, so within 1e-8 of each other in e_eff, peak force, peak deformation and
  // contact time. DEM's x^{1/4} dashpot is not polynomial in u: its run keeps the
  // singular-point checks and must agree all the same.
  const DropTestSetup setup = steel_drop();
  ImpactSimulator fast(dopri5(IntegratorKind::dopri5_regularized, 1e-11));
  ImpactSimulator physical(dopri5(IntegratorKind::dopri5, 1e-11));
  const ImpactSummary a = fast.run<HongoPaper>(setup), b = physical.run<HongoPaper>(setup);
  std::printf("paper's law: e_eff regularized %.12f, physical %.12f; peak force %.9f, %.9f N\n", a.e_effective,
              b.e_effective, a.peak_force_N, b.peak_force_N);
  CHECK(largest_difference(a, b) < 1e-8);
  CHECK(a.t_onset_s == Approx(b.t_onset_s).epsilon(1e-8));
  const ImpactSummary c = fast.run<TsujiDem>(setup), d = physical.run<TsujiDem>(setup);
  std::printf("DEM: e_eff regularized %.12f, physical %.12f\n", c.e_effective, d.e_effective);
  CHECK(largest_difference(c, d) < 1e-8);
}

TEST_CASE("dopri5-regularized: with the tension clamp the run is dopri5's in the physical variables",
          "[dopri5][regularized]") {
  // The regularised contact has no force-zero event, so the clamp takes the physical
  // path: the very same computation, hence bitwise the same summary.
  DropTestSetup setup = steel_drop();
  setup.no_tension = true;
  ImpactSimulator fast(dopri5(IntegratorKind::dopri5_regularized, 1e-8));
  ImpactSimulator physical(dopri5(IntegratorKind::dopri5, 1e-8));
  const ImpactSummary a = fast.run<HongoPaper>(setup), b = physical.run<HongoPaper>(setup);
  CHECK(a.e_effective == b.e_effective);
  CHECK(a.work.rhs_evaluations == b.work.rhs_evaluations);
}

namespace {

/// A law with a material constant (kuwabara-kono's A, lee-herrmann's gamma) given one of its size
/// for the impact c (Law::material_constant_scale); every other law's settings as they are.
template <class Law>
DampingSettings with_material_constant(DampingSettings d, const ImpactConditions& c) {
  if constexpr (MaterialTimeConstantLaw<Law>)
    Law::set_material_constant(d, Law::material_constant_scale(undamped_hertz_max_deformation_m(c.K, c.mass_kg, c.v0_mps), c.v0_mps));
  return d;
}

}  // namespace

TEST_CASE("RootPolynomialLaw: force_of_root(u, v) equals force(u^2, v) for every law that declares it",
          "[regularized][damping]") {
  // The declaration is the same force written in u = x^{1/2}: equal to rounding
  // (a few ulp of the larger term) at deformations and speeds across an impact.
  const DropTestSetup setup = steel_drop();
  const ImpactConditions c{hertz_stiffness(setup), setup.mass_kg, 0.626, 0.8};
  int declared = 0;
  for_each_damping_law([&]<class Law>(std::type_identity<Law>) {
    if constexpr (RootPolynomialLaw<Law>) {
      ++declared;
      const Law law(c, with_material_constant<Law>(setup.damping, c));  // the identity holds for any constant
      for (double x : {0.0, 1e-7, 1e-5, 2.4e-4})
        for (double v : {0.626, 0.1, 0.0, -0.5}) {
          const double scale = std::abs(law.force(x, 0.0)) + std::abs(law.force(x, v) - law.force(x, 0.0)) + 1e-300;
          CHECK(std::abs(law.force_of_root(std::sqrt(x), v) - law.force(x, v)) <= 1e-14 * scale);
        }
    }
  });
  // Hertz, the paper's law, Kelvin-Voigt and the Hunt-Crossley family declare it.
  CHECK(declared >= 4);
}

TEST_CASE("ForceJet: force_of_root on jets gives the force and its partial derivatives in u and xdot",
          "[regularized][damping]") {
  // The regularised contact's peak-force event takes dF/dtau = F_u u' + F_xdot xdot' from
  // one evaluation of force_of_root on ForceJet (model/force_jet.hpp). Checked for every law
  // that declares force_of_root against central differences of force_of_root itself with
  // steps d = 1e-4 of the scales: the truncation, d^2/6 times a third derivative, is ~1e-9 of
  // the force's scale for these cubic polynomials and the rounding eps F/d ~ 1e-12, so 1e-6
  // of the scale is met by any correct product rule and by no wrong one (an O(1) error); and
  // for the paper's law against its closed form F_u = K (3u^2 + tau xdot), F_xdot = K tau u
  // (HongoPaper::gradient_of_root) to rounding.
  const DropTestSetup setup = steel_drop();
  const ImpactConditions c{hertz_stiffness(setup), setup.mass_kg, 0.626, 0.8};
  const double u_scale = std::sqrt(undamped_hertz_max_deformation_m(c.K, c.mass_kg, c.v0_mps)), v_scale = c.v0_mps;
  const double du = 1e-4 * u_scale, dv = 1e-4 * v_scale;
  int checked = 0;
  for_each_damping_law([&]<class Law>(std::type_identity<Law>) {
    if constexpr (RootPolynomialLaw<Law>) {
      const Law law(c, with_material_constant<Law>(setup.damping, c));
      const double scale = std::abs(law.force_of_root(u_scale, v_scale));  // the force's scale [N]
      for (double u : {0.0, 0.1 * u_scale, u_scale})
        for (double v : {0.626, 0.0, -0.5}) {
          const ForceJet jet = law.force_of_root(root_leaf(u), rate_leaf(v));
          const double F_u = (law.force_of_root(u + du, v) - law.force_of_root(u - du, v)) / (2 * du);
          const double F_v = (law.force_of_root(u, v + dv) - law.force_of_root(u, v - dv)) / (2 * dv);
          CHECK(jet.value == law.force_of_root(u, v));
          CHECK(std::abs(jet.d[0] - F_u) * u_scale <= 1e-6 * scale);
          CHECK(std::abs(jet.d[1] - F_v) * v_scale <= 1e-6 * scale);
          ++checked;
        }
    }
  });
  CHECK(checked >= 4 * 9);
  const HongoPaper paper_law(c, setup.damping);
  for (double u : {0.0, 0.3 * u_scale, u_scale})
    for (double v : {0.626, -0.5}) {
      const ForceJet jet = paper_law.force_of_root(root_leaf(u), rate_leaf(v));
      const HongoPaper::Gradient g = HongoPaper::gradient_of_root(c.K, paper_law.time_constant_s(), u, v);
      CHECK(jet.d[0] == Approx(g.F_u).epsilon(1e-14).margin(1e-14 * c.K * u_scale * u_scale));
      CHECK(jet.d[1] == Approx(g.F_xdot).epsilon(1e-14).margin(1e-300));
    }
}

/// Checks Law's dF/dv0 against central differences of laws built at v0 (1 +- 1e-5), at three
/// depths and three speeds; returns the number of points checked.
template <class Law>
int check_speed_derivative(double K, double mass_kg, double v0, double e, const DampingSettings& d) {
  // Differences err by O(1e-10) relative (the coefficients are smooth powers of v0) plus rounding
  // O(1e-16/1e-5): 1e-8 of the force's scale holds any correct derivative and no wrong one.
  const double u_scale = std::sqrt(undamped_hertz_max_deformation_m(K, mass_kg, v0)), h = 1e-5 * v0;
  const Law law(ImpactConditions{K, mass_kg, v0, e}, d), plus(ImpactConditions{K, mass_kg, v0 + h, e}, d),
      minus(ImpactConditions{K, mass_kg, v0 - h, e}, d);
  const double scale = K * u_scale * u_scale * u_scale;
  int checked = 0;
  for (double u : {0.0, 0.4 * u_scale, u_scale})
    for (double v : {v0, 0.0, -0.7 * v0}) {
      const double fd = (plus.force_of_root(u, v) - minus.force_of_root(u, v)) / (2 * h);
      CHECK(std::abs(law.force_speed_derivative(u, v) - fd) * v0 <= 1e-8 * scale);
      ++checked;
    }
  return checked;
}

TEST_CASE("SpeedDerivativeLaw: dF/dv0 of every law that declares it equals differences in v0", "[regularized][damping]") {
  // A law fixes its coefficients from v0 at onset; SpeedDerivativeLaw's force_speed_derivative
  // gives dF/dv0 at fixed (u, xdot), checked against differences (check_speed_derivative).
  const DropTestSetup s = steel_drop();
  const double K = hertz_stiffness(s), v0 = 0.4, e = 0.5;
  int checked = 0;
  for_each_damping_law([&]<class Law>(std::type_identity<Law>) {
    if constexpr (SpeedDerivativeLaw<Law>)
      checked += check_speed_derivative<Law>(K, s.mass_kg, v0, e, with_material_constant<Law>(s.damping, {K, s.mass_kg, v0, e}));
  });
  CHECK(checked >= 12 * 9);
  // Hunt-Crossley's closed form: dF/dv0 = -K u^3 chi xdot / v0 (chi = 3 (1 - e)/(2 v0)).
  const HuntCrossley hc(ImpactConditions{K, s.mass_kg, v0, e}, s.damping);
  const double u_scale = std::sqrt(undamped_hertz_max_deformation_m(K, s.mass_kg, v0));
  const double u = 0.5 * u_scale, v = 0.2, chi = 1.5 * (1 - e) / v0;
  CHECK(hc.force_speed_derivative(u, v) == Approx(-K * u * u * u * chi * v / v0).epsilon(1e-14));
  // The paper's law, F = K u (u^2 + tau xdot), tau = 2 zeta/omega_n: omega_n grows as v0^{1/5} by
  // eq. (11) and both energy variants (X ~ v0^{4/5}, omega_n ~ X^{1/4}), as v0^{2/5} as printed
  // (~ X^{1/2}), and is held fixed when given (an iterated variant's fixed point); so
  // dF/dv0 = -p K u xdot tau / v0 with p = 1/5, 2/5 and 0.
  for (const auto& [variant, p] : {std::pair{OmegaNVariant::paper, 0.2}, std::pair{OmegaNVariant::impact_energy, 0.2},
                                   std::pair{OmegaNVariant::rebound_energy, 0.2}, std::pair{OmegaNVariant::as_printed, 0.4},
                                   std::pair{OmegaNVariant::self_consistent, 0.0}}) {
    DampingSettings hd = s.damping;
    hd.omega_n = variant;
    hd.omega_n_rad_per_s = 5e3;
    CHECK(check_speed_derivative<HongoPaper>(K, s.mass_kg, v0, e, hd) == 9);
    const HongoPaper law(ImpactConditions{K, s.mass_kg, v0, e}, hd);
    CHECK(law.force_speed_derivative(u, v) == Approx(-p * K * u * v * law.time_constant_s() / v0).margin(1e-14 * K * u * u * u));
  }
}

TEST_CASE("cvode-regularized: undamped Hertz contact against the closed forms, error proportional to tolerance",
          "[cvode][regularized]") {
  // The closed forms of the dopri5 case (tests/test_dormand_prince.cpp), no gravity.
  // In the physical variables CVODE's Adams method restarts at order one on the
  // x^{3/2} singularity and its error does not follow the tolerance; in u = x^{1/2}
  // the right-hand side is the polynomial K u^3 and it does. A multistep method under
  // local error control, without local extrapolation, accumulates its local errors
  // over its hundred-odd steps: global error C tol with C of order ten (5 to 10 is
  // measured). Each within 100 tol, and the exponent 1 +- 0.2.
  DropTestSetup setup = steel_drop();
  setup.gravity_mps2 = 0.0;
  setup.impact_velocity_mps = 0.626;
  const UndampedHertzImpact exact = undamped_hertz_impact(hertz_stiffness(setup), setup.mass_kg, 0.626);
  std::vector<double> tols{1e-6, 1e-8, 1e-10}, errors;
  std::printf("cvode-regularized undamped Hertz: tol, |e-1|, rel err X, rel err F, rel err t_c, rhs evaluations\n");
  for (double tol : tols) {
    SolverSettings settings;
    settings.integrator = IntegratorKind::cvode_regularized;
    settings.rtol = tol;
    settings.atol = tol * 1e-4;
    ImpactSimulator sim(settings);
    const ImpactSummary s = sim.run<Undamped>(setup);
    REQUIRE(s.separated);
    errors.push_back(testing::undamped_hertz_errors(tol, s, exact).largest());
    CHECK(errors.back() <= 100 * tol);
  }
  const double k = std::log10(errors.front() / errors.back()) / std::log10(tols.front() / tols.back());
  std::printf("  observed exponent of error against tolerance: %.3f\n", k);
  CHECK(k == Approx(1.0).margin(0.2));
}
