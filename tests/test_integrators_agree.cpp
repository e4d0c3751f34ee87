// The three integrators on the paper's steel case (h = 20 mm, Table defaults, the
// paper's law, gravity throughout) agree within their own errors.
//
// Reference: CVODE (Adams) at rtol 1e-12; its error, ~N rtol with N ~ 10^3 steps,
// is below 1e-9 and negligible here.
// RK4 at h = 1e-6 s (t_c/1245): the paper's dashpot force K tau sqrt(x) x' makes the
// acceleration ~ t^{1/2} right after onset, which the RK4 stages integrate with a
// relative velocity error ~ 2 zeta c (h/t_c)^{3/2}, c = O(1) -> 0.15 * 2.3e-5 = 3.4e-6
// per kink: bound 1e-5.
// Euler at h = 1e-7 s: energy error pi^2 h/t_c = 7.9e-4 over the contact, half of it
// in the rebound speed: bound 1e-3 (the free fall adds O(h/t_fall) = 1.5e-6).
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace hertzdash;

namespace {
ImpactSummary steel_case(const SolverSettings& solver) {
  return ImpactSimulator(solver).run(paper_setup(load_paper_parameters(), "steel", 0.02), "hongo");
}
void check_close(const ImpactSummary& r, const ImpactSummary& ref, double rel) {
  CHECK(r.separated);
  CHECK(std::abs(r.e_effective / ref.e_effective - 1) < rel);
  CHECK(std::abs(r.peak_force_N / ref.peak_force_N - 1) < rel);
  CHECK(std::abs(r.max_deformation_m / ref.max_deformation_m - 1) < rel);
  CHECK(std::abs(r.contact_time_s / ref.contact_time_s - 1) < rel);
  CHECK(std::abs(r.impact_velocity_mps / ref.impact_velocity_mps - 1) < rel);
}
}  // namespace

TEST_CASE("Paper's steel case: Euler, RK4 and CVODE agree within their errors", "[integrators][paper]") {
  SolverSettings cvode;
  cvode.rtol = 1e-12;
  cvode.atol = 1e-16;
  const ImpactSummary ref = steel_case(cvode);
  REQUIRE(ref.separated);
  // Free fall is exact for any consistent method: v0 = sqrt(2 g h).
  CHECK(ref.impact_velocity_mps == Approx(std::sqrt(2 * 9.80665 * 0.02)).epsilon(1e-9));

  SECTION("CVODE BDF") {
    SolverSettings bdf = cvode;
    bdf.cvode_method = CvodeMethod::bdf;
    check_close(steel_case(bdf), ref, 1e-8);
  }
  SECTION("RK4") {
    SolverSettings rk4;
    rk4.integrator = IntegratorKind::rk4;
    rk4.dt_s = 1e-6;
    check_close(steel_case(rk4), ref, 1e-5);
  }
  SECTION("Euler") {
    SolverSettings euler;
    euler.integrator = IntegratorKind::euler;
    euler.dt_s = 1e-7;
    check_close(steel_case(euler), ref, 1e-3);
  }
}
