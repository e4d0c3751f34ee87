// Adaptive Dormand-Prince 5(4) with events landed on (integrators/dormand_prince.hpp),
// its place in ImpactSimulator and the CLI, the parallel sweep, and the CVODE
// root-at-zero regression.
#include "hertzdash/integrators/dormand_prince.hpp"
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/damping/laws/undamped.hpp"
#include "hertzdash/model/drop_test.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"
#include "hertzdash/simulation/sweep/parallel_sweep.hpp"
#include "undamped_hertz_errors.hpp"
#include "tests/allocation_count.hpp"

#include "harmonic_oscillator.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <new>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using namespace hertzdash;

using Oscillator = test::HarmonicOscillator;  // stops at t = pi/2

/// log10(e1/e2) / log10(t1/t2): the observed exponent of error against tolerance.
double observed_exponent(double e1, double e2, double t1, double t2) { return std::log10(e1 / e2) / std::log10(t1 / t2); }

DropTestSetup steel_contact_setup(double gravity_mps2) {
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  s.gravity_mps2 = gravity_mps2;
  s.impact_velocity_mps = std::sqrt(2 * 9.80665 * 0.02);
  validate(s);
  return s;
}

SolverSettings dopri5(double tol) {
  SolverSettings s;
  s.integrator = IntegratorKind::dopri5;
  s.rtol = tol;
  s.atol = tol;  // of the impact's scales (X and v0; X^{1/2}, v0, t_H regularised): every component relative
  return s;
}

}  // namespace

TEST_CASE("dopri5: global error proportional to tolerance on the oscillator, event located on the dense output",
          "[dopri5]") {
  // Exact: the event at t* = pi/2 with p(t*) = -1. With the local error per step held
  // at the tolerance and local extrapolation, the global error is C tol with C of
  // order one (a few tens of steps, each well inside the tolerance): the error
  // against tolerance has exponent 1, asserted within 0.15 over four decades.
  std::vector<double> tols{1e-6, 1e-8, 1e-10}, errors;
  std::printf("dopri5 oscillator: tol, |t* - pi/2|, |p(t*) + 1|, rhs evaluations\n");
  for (double tol : tols) {
    Oscillator sys;
    Oscillator::State y(1.0, 0.0);
    NullObserver obs;
    const IntegrationStats st = integrate_dormand_prince(sys, y, 0.0, 10.0, {tol, tol}, obs);
    REQUIRE(st.stopped_by_event);
    const double et = std::abs(st.t_final - std::numbers::pi / 2), ep = std::abs(y[1] + 1);
    std::printf("  %.0e  %.3e  %.3e  %ld\n", tol, et, ep, st.rhs_evaluations);
    CHECK(et <= 10 * tol);
    CHECK(ep <= 10 * tol);
    errors.push_back(std::max(et, ep));
  }
  const double k = observed_exponent(errors.front(), errors.back(), tols.front(), tols.back());
  std::printf("  observed exponent of error against tolerance: %.3f\n", k);
  CHECK(k == Approx(1.0).margin(0.15));
}

TEST_CASE("dopri5: undamped Hertz impact against the closed forms, error proportional to tolerance", "[dopri5]") {
  // Undamped law, no gravity: energy is conserved, so e_eff = 1; the peak deformation
  // X = (5 m v0^2 / 4K)^{2/5}, the peak force K X^{3/2} and the contact time
  // (4/5) B(2/5, 1/2) X / v0 are exact (model/hertz.hpp). The right-hand side is
  // K x^{3/2}/m, singular at onset and separation (x^{3/2} ~ t^{3/2}); the first step
  // after onset is checked by step doubling and the landing on separation too, so the
  // error stays proportional to the tolerance: within 10 tol, exponent 1 +- 0.2.
  // dopri5-regularized integrates the contact in u = x^{1/2}, where the right-hand side
  // is the polynomial K u^3 (model/contact_system.hpp): there the embedded
  // estimate is reliable everywhere, with the same bounds and no checks; and so is the
  // order-8 extrapolation method there (gbs8-regularized).
  const DropTestSetup setup = steel_contact_setup(0.0);
  const UndampedHertzImpact exact = undamped_hertz_impact(hertz_stiffness(setup), setup.mass_kg,
                                                          *setup.impact_velocity_mps);
  const IntegratorKind kind =
      GENERATE(IntegratorKind::dopri5, IntegratorKind::dopri5_regularized, IntegratorKind::gbs8_regularized);
  std::vector<double> tols{1e-6, 1e-8, 1e-10}, errors;
  std::printf("%s undamped Hertz: tol, |e-1|, rel err X, rel err F, rel err t_c, rhs evaluations\n", to_string(kind));
  for (double tol : tols) {
    SolverSettings settings = dopri5(tol);
    settings.integrator = kind;
    ImpactSimulator sim(settings);
    const ImpactSummary s = sim.run<Undamped>(setup);
    REQUIRE(s.separated);
    const testing::UndampedHertzErrors err = testing::undamped_hertz_errors(tol, s, exact);
    CHECK(err.e <= 10 * tol);
    CHECK(err.X <= 10 * tol);
    CHECK(err.F <= 10 * tol);
    CHECK(err.contact_time <= 10 * tol);
    errors.push_back(err.largest());
  }
  const double k = observed_exponent(errors.front(), errors.back(), tols.front(), tols.back());
  std::printf("  observed exponent of error against tolerance: %.3f\n", k);
  CHECK(k == Approx(1.0).margin(0.2));
}

TEST_CASE("dopri5: the paper's law converges to the same restitution as CVODE at tight tolerance", "[dopri5]") {
  // Independent methods (variable-order Adams vs Dormand-Prince) at rtol 1e-11 agree to
  // the tolerance times the tens of steps: 1e-8 is three decades of margin on e_eff.
  const DropTestSetup setup = steel_contact_setup(9.80665);
  ImpactSimulator dp(dopri5(1e-11));
  SolverSettings cv;
  cv.rtol = 1e-11;
  cv.atol = 1e-15;
  ImpactSimulator cvode(cv);
  const double e_dp = dp.run<HongoPaper>(setup).e_effective, e_cv = cvode.run<HongoPaper>(setup).e_effective;
  std::printf("paper's law e_eff: dopri5 %.12f, cvode %.12f\n", e_dp, e_cv);
  CHECK(std::abs(e_dp - e_cv) < 1e-8);
}

TEST_CASE("allocation count: every form of operator new is counted", "[dopri5]") {
  // The test below asserts zero allocations; this shows the count sees each form: plain,
  // array, nothrow and over-aligned news add one each (6). The pointers go through a volatile
  // so that the compiler may not elide the pairs.
  struct alignas(64) Wide {
    double v[8];
  };
  static void* volatile sink;
  const long before = hertzdash::test::allocation_count();
  int* a = new int(1);
  sink = a;
  int* b = new int[3];
  sink = b;
  int* c = new (std::nothrow) int(2);
  sink = c;
  Wide* d = new Wide();
  sink = d;
  Wide* e = new Wide[2];
  sink = e;
  Wide* f = new (std::nothrow) Wide();
  sink = f;
  CHECK(hertzdash::test::allocation_count() - before == 6);
  CHECK(sink == f);
  CHECK(reinterpret_cast<std::uintptr_t>(d) % 64 == 0);
  CHECK(reinterpret_cast<std::uintptr_t>(e) % 64 == 0);
  delete a;
  delete[] b;
  delete c;
  delete d;
  delete[] e;
  delete f;
}

TEST_CASE("dopri5: an impact allocates nothing", "[dopri5]") {
  const DropTestModel model(steel_contact_setup(9.80665));
  DropTest<HongoPaper> sys(model);
  auto y = sys.initial_state();
  NullObserver obs;
  const long before = hertzdash::test::allocation_count();
  const IntegrationStats st = integrate_dormand_prince(sys, y, 0.0, 1.0, {1e-9, 1e-13}, obs);
  const long during = hertzdash::test::allocation_count() - before;
  REQUIRE(st.stopped_by_event);
  CHECK(during == 0);
}

TEST_CASE("dopri5: bad tolerances are rejected", "[dopri5]") {
  Oscillator sys;
  Oscillator::State y(1.0, 0.0);
  NullObserver obs;
  CHECK_THROWS_AS(integrate_dormand_prince(sys, y, 0.0, 1.0, {0.0, 1e-9}, obs), std::invalid_argument);
  CHECK_THROWS_AS(integrate_dormand_prince(sys, y, 0.0, 1.0, {1e-9, -1.0}, obs), std::invalid_argument);
}

TEST_CASE("cvode: an event function exactly zero at a root no longer stops the run", "[cvode]") {
  // Before the fix, rtol 1e-4 and 1e-6 (atol 1e-8, 1e-10) on this impact ended in
  // CV_ILL_INPUT "root found at and very near t": the difference quotient of the
  // peak-force event is exactly zero over more than CVODE's root resolution. The run
  // must now complete, with e_eff within 1e-3 of the converged value (the tolerance
  // times the ~100 steps).
  const DropTestSetup setup = steel_contact_setup(9.80665);
  ImpactSimulator ref(dopri5(1e-11));
  const double e_ref = ref.run<HongoPaper>(setup).e_effective;
  for (double rtol : {1e-4, 1e-6}) {
    SolverSettings s;
    s.rtol = rtol;
    s.atol = rtol * 1e-4;
    ImpactSimulator sim(s);
    ImpactSummary r;
    REQUIRE_NOTHROW(r = sim.run<HongoPaper>(setup));
    REQUIRE(r.separated);
    CHECK(std::abs(r.e_effective - e_ref) < 1e-3);
  }
}

TEST_CASE("parallel_sweep: same results as a serial loop, and errors propagate", "[sweep]") {
  // Each impact is deterministic, so the parallel results equal the serial ones bitwise.
  const DropTestSetup base = steel_contact_setup(9.80665);
  const std::size_t n = 300;
  auto setup_for = [&](std::size_t i) {
    DropTestSetup s = base;
    s.restitution = 0.5 + 0.5 * static_cast<double>(i) / static_cast<double>(n - 1);
    return s;
  };
  std::vector<double> serial(n), parallel(n);
  ImpactSimulator sim(dopri5(1e-8));
  for (std::size_t i = 0; i < n; ++i) serial[i] = sim.run<HongoPaper>(setup_for(i)).e_effective;
  parallel_sweep(
      n, dopri5(1e-8),
      [&](ImpactSimulator& s, std::size_t i) { parallel[i] = s.run<HongoPaper>(setup_for(i)).e_effective; },
      {.threads = 2, .chunk = 16, .progress = false});
  CHECK(serial == parallel);
  CHECK_THROWS_AS(parallel_sweep(
                      n, dopri5(1e-8),
                      [&](ImpactSimulator&, std::size_t i) {
                        if (i == 123) throw std::runtime_error("impact 123 failed");
                      },
                      {.threads = 2, .chunk = 16, .progress = false}),
                  std::runtime_error);
}

TEST_CASE("cli: --integrator dopri5 is accepted, an unknown integrator exits 2", "[dopri5][cli]") {
  const std::string bin = HERTZDASH_BIN;
  CHECK(std::system((bin + " simulate --integrator dopri5 --rtol 1e-9 --atol 1e-13 > /dev/null").c_str()) == 0);
  const int rc = std::system((bin + " simulate --integrator nope > /dev/null 2>&1").c_str());
  CHECK(WEXITSTATUS(rc) == 2);
}
