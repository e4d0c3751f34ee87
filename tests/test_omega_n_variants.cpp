// The omega_n assumptions of the paper's law (model/omega_n_variant.hpp,
// model/damping/laws/hongo_paper.hpp) and the fixed-point iteration of the
// iterated ones (simulation/run/omega_n_fixed_point.hpp).
//
// Each closed-form variant is checked against its defining energy balance, not
// against a re-typed copy of its formula: from omega_n = sqrt((4K/(5m)) X^{1/2})
// (eq. 9, corrected) the amplitude is X = (5 m omega_n^2 / (4K))^2, and the
// strain energy (2/5) K X^{5/2} must equal the energy the variant names.
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/omega_n_fixed_point.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

using namespace hertzdash;

namespace {

// Steel rod of Table 1 on the nylon ball (data/assumptions.csv), h = 20 mm.
DropTestSetup steel_20mm() { return paper_setup(load_paper_parameters(), "steel", 0.020); }

ImpactConditions conditions_of(const DropTestSetup& s) {
  return {hertz_stiffness(s), s.mass_kg, approach_speed(s), s.restitution};
}

double omega_n_of(const ImpactConditions& c, OmegaNVariant v) {
  DampingSettings settings;
  settings.omega_n = v;
  return paper_law_natural_frequency(c, settings);
}

// Strain energy (2/5) K X^{5/2} at the amplitude X implied by omega_n through eq. (9).
double strain_energy_implied(const ImpactConditions& c, double omega_n) {
  const double X = std::pow(5.0 * c.mass_kg * omega_n * omega_n / (4.0 * c.K), 2.0);
  return 0.4 * c.K * std::pow(X, 2.5);
}

// Shell out to the CLI; returns the exit code and captures stderr+stdout.
int run_cli(const std::string& args, std::string& output) {
  const std::string cmd = std::string(HERTZDASH_BIN) + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  REQUIRE(pipe != nullptr);
  char buf[512];
  output.clear();
  while (fgets(buf, sizeof buf, pipe)) output += buf;
  const int status = pclose(pipe);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

TEST_CASE("closed-form omega_n variants satisfy their defining energy balances", "[omega_n]") {
  // Only floating-point rounding separates the two sides: a few pow/sqrt calls, each
  // within 1 ulp; the inversion X = (5 m w^2/(4K))^2 and X^{5/2} amplify relative
  // rounding by at most ~10, so 1e-13 relative is a generous bound.
  const double tol = 1e-13;
  for (double e : {0.1, 0.5, 0.795, 0.99}) {
    ImpactConditions c = conditions_of(steel_20mm());
    c.restitution = e;
    const double T0 = 0.5 * c.mass_kg * c.v0_mps * c.v0_mps;  // impact kinetic energy [J]
    CAPTURE(e);
    // paper, eq. (10): strain energy = mean of the kinetic energies before and after impact.
    CHECK(strain_energy_implied(c, omega_n_of(c, OmegaNVariant::paper)) ==
          Approx(0.5 * (T0 + e * e * T0)).epsilon(tol));
    // impact-energy: = impact energy (eq. 10 with e = 1).
    CHECK(strain_energy_implied(c, omega_n_of(c, OmegaNVariant::impact_energy)) == Approx(T0).epsilon(tol));
    // rebound-energy: = rebound energy e^2 T0.
    CHECK(strain_energy_implied(c, omega_n_of(c, OmegaNVariant::rebound_energy)) ==
          Approx(e * e * T0).epsilon(tol));
    // Eq. (11) written out in full is the paper variant.
    const double eq11 = std::sqrt(4.0 * c.K / (5.0 * c.mass_kg) *
                                  std::pow(5.0 * c.mass_kg * c.v0_mps * c.v0_mps * (1 + e * e) / (8.0 * c.K), 0.2));
    CHECK(omega_n_of(c, OmegaNVariant::paper) == Approx(eq11).epsilon(tol));
    // as-printed (erratum): X^{1/2} outside the radical, so omega_as^2 = (4K/(5m)) X with X from
    // eq. (10); against the corrected omega^2 = (4K/(5m)) X^{1/2} the ratio is X^{1/4}.
    const double X10 = paper_peak_deformation(c.K, c.mass_kg, c.v0_mps, e);
    CHECK(omega_n_of(c, OmegaNVariant::as_printed) / omega_n_of(c, OmegaNVariant::paper) ==
          Approx(std::pow(X10, 0.25)).epsilon(tol));
    // Energy ordering: impact >= mean >= rebound, so omega_n (increasing in X) follows it.
    CHECK(omega_n_of(c, OmegaNVariant::impact_energy) > omega_n_of(c, OmegaNVariant::paper));
    CHECK(omega_n_of(c, OmegaNVariant::paper) > omega_n_of(c, OmegaNVariant::rebound_energy));
  }
}

TEST_CASE("the paper's law uses the variant's omega_n in c_e = 2 K zeta / omega_n", "[omega_n]") {
  const ImpactConditions c = conditions_of(steel_20mm());
  for (OmegaNVariant v : all_omega_n_variants) {
    DampingSettings s;
    s.omega_n = v;
    s.omega_n_rad_per_s = 1234.5;  // used only by the iterated variants
    const double w = is_iterated(v) ? 1234.5 : omega_n_of(c, v);
    const HongoPaper law(c, s);
    const double zeta = zeta_from_restitution(c.restitution, s.zeta_form);
    // Force at x = 1e-4 m, xdot = 0.5 m/s: K x^{3/2} + (2 K x^{1/2} zeta / w) xdot (eqs. 2, 5).
    const double x = 1e-4, xdot = 0.5;
    const double expected = c.K * std::pow(x, 1.5) + 2.0 * c.K * std::sqrt(x) * zeta / w * xdot;
    CAPTURE(to_string(v));
    CHECK(law.force(x, xdot) == Approx(expected).epsilon(1e-14));
  }
  // An iterated variant without an omega_n from its iteration is an error, not a silent default.
  DampingSettings unset;
  unset.omega_n = OmegaNVariant::self_consistent;
  CHECK_THROWS_AS(HongoPaper(c, unset), InvalidParameter);
}

TEST_CASE("iterated omega_n variants converge to fixed points of their definitions", "[omega_n]") {
  ImpactSimulator sim(SolverSettings{});
  for (OmegaNVariant v : {OmegaNVariant::self_consistent, OmegaNVariant::contact_time}) {
    DropTestSetup s = steel_20mm();
    s.damping.omega_n = v;
    const OmegaNFixedPoint r = solve_omega_n_fixed_point(sim, s);
    CAPTURE(to_string(v), r.iterations, r.contraction, r.failure);
    REQUIRE(r.converged);
    CHECK(r.contraction < 1.0);
    // Picard iteration converges linearly: the distances to the limit shrink monotonically.
    const double w_star = r.history.back();
    for (std::size_t k = 1; k + 1 < r.history.size(); ++k)
      CHECK(std::abs(r.history[k] - w_star) < std::abs(r.history[k - 1] - w_star));
    // Independent re-check of the definition: simulate again with omega_n = w* and evaluate
    // the defining quantity directly. The run with w* was the last iterate, so G(w*) differs
    // from w* by the iteration's rtol (1e-9) at most; the solver is deterministic.
    s.damping.omega_n_rad_per_s = r.omega_n_rad_per_s;
    const ImpactSummary again = sim.run<HongoPaper>(s);
    const double K = hertz_stiffness(s);
    const double implied = v == OmegaNVariant::contact_time
                               ? std::numbers::pi / again.contact_time_s
                               : std::sqrt(4.0 * K / (5.0 * s.mass_kg) * std::sqrt(again.max_deformation_m));
    CHECK(implied == Approx(r.omega_n_rad_per_s).epsilon(1e-9));
  }
}

TEST_CASE("without damping the iterated variants reduce to the undamped Hertz closed forms", "[omega_n]") {
  // e = 1 makes zeta = 0, so omega_n does not affect the impact and G is constant: the
  // iteration stops after at most two simulations (one for self-consistent, whose start,
  // eq. 11 at e = 1, is already the undamped amplitude's omega_n). With g = 0 and an impact velocity the impact is
  // the undamped Hertz impact, whose X and t_c are closed forms (model/hertz.hpp):
  //   self-consistent: omega_n = sqrt((4K/(5m)) X^{1/2}) = the impact-energy variant;
  //   contact-time:    omega_n = pi / t_c.
  // Integrated with RK4 at dt = 1e-7 s (~1.2e4 steps per contact, global error ~(dt/t_c)^4
  // ~ 1e-16 relative) with Illinois event location, so 1e-8 relative is dominated by nothing
  // but leaves room for the event tolerance.
  SolverSettings solver;
  solver.integrator = IntegratorKind::rk4;
  solver.dt_s = 1e-7;
  ImpactSimulator sim(solver);
  DropTestSetup s = steel_20mm();
  s.restitution = 1.0;
  s.gravity_mps2 = 0.0;
  s.impact_velocity_mps = 0.6;
  const ImpactConditions c = conditions_of(s);
  const UndampedHertzImpact exact = undamped_hertz_impact(c.K, c.mass_kg, c.v0_mps);

  s.damping.omega_n = OmegaNVariant::self_consistent;
  const OmegaNFixedPoint sc = solve_omega_n_fixed_point(sim, s);
  REQUIRE(sc.converged);
  CHECK(sc.iterations <= 2);
  CHECK(sc.omega_n_rad_per_s == Approx(omega_n_of(c, OmegaNVariant::impact_energy)).epsilon(1e-8));

  s.damping.omega_n = OmegaNVariant::contact_time;
  const OmegaNFixedPoint ct = solve_omega_n_fixed_point(sim, s);
  REQUIRE(ct.converged);
  CHECK(ct.iterations <= 2);
  CHECK(ct.omega_n_rad_per_s == Approx(std::numbers::pi / exact.contact_time_s).epsilon(1e-8));
}

TEST_CASE("hertzdash simulate --omega-n selects variants and rejects misuse", "[omega_n][cli]") {
  std::string out;
  // An iterated variant reports its fixed point.
  REQUIRE(run_cli("simulate --omega-n self-consistent --json", out) == 0);
  CHECK(out.find("\"omega_n_fixed_point\"") != std::string::npos);
  CHECK(out.find("\"converged\": true") != std::string::npos);
  // The variant changes omega_n: impact-energy > paper (test above), visible in the output.
  REQUIRE(run_cli("simulate --omega-n impact-energy", out) == 0);
  // With another law the option is an error naming it, exit 2.
  CHECK(run_cli("simulate --damping none --omega-n paper", out) == 2);
  CHECK(out.find("--omega-n") != std::string::npos);
  // An unknown variant: exit 2, message lists the valid ones.
  CHECK(run_cli("simulate --omega-n sometimes", out) == 2);
  CHECK(out.find("self-consistent") != std::string::npos);
}
