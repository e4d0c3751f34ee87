// Exact restitution identities of the damping laws, in the rigid-wall contact
// phase without gravity (tests/damping_law_test_support.hpp). Each expected value
// is derived below; the simulations run CVODE at rtol 1e-10 (error in e_effective
// ~1e-8), so every comparison uses the bound 1e-7.
#include "damping_law_test_support.hpp"
#include "hunt_crossley_restitution.hpp"
#include "tested_laws.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <concepts>
#include <numbers>
#include <tuple>
#include <type_traits>
#include <vector>

using namespace hertzdash;
using namespace hertzdash::test;

namespace {

constexpr double solver_bound = 1e-7;
const std::vector<double> e_grid{0.05, 0.1, 0.2, 0.3, 0.5, 0.7, 0.795, 0.9, 0.99};

template <class L>
concept HuntCrossleyForm = requires(double e) {
  { L::chi_v0(e) } -> std::convertible_to<double>;
};

/// The laws of a std::tuple that are of the Hunt-Crossley form, in order, chosen at
/// compile time (a type list: the laws need not be default-constructible).
template <class L, class Tuple> struct Prepend;
template <class L, class... T> struct Prepend<L, std::tuple<T...>> {
  using type = std::tuple<L, T...>;
};
template <class Tuple> struct KeepHuntCrossleyForm {
  using type = std::tuple<>;
};
template <class L, class... Rest> struct KeepHuntCrossleyForm<std::tuple<L, Rest...>> {
  using rest = typename KeepHuntCrossleyForm<std::tuple<Rest...>>::type;
  using type = std::conditional_t<HuntCrossleyForm<L>, typename Prepend<L, rest>::type, rest>;
};
using HuntCrossleyFormLaws = KeepHuntCrossleyForm<TestedLaws>::type;

}  // namespace

TEST_CASE("The Lambert-W check runs on the guide's example and at least one registered law",
          "[damping][restitution]") {
  // The guide's example (ExactHertzDashpot) is always of the Hunt-Crossley form; a second
  // entry is a registered law (hunt-crossley itself and its relatives), so the closed
  // form below checks the library and not only the test's own example.
  REQUIRE(std::tuple_size_v<HuntCrossleyFormLaws> >= 2);
}

HERTZDASH_LAW_TEST_CASE(LambertWRestitution, HuntCrossleyFormLaws,
                        "Hunt-Crossley-form laws match the Lambert-W closed form of their restitution",
                        "[damping][restitution]") {
  const ContactScales p = paper_steel_contact();
  for (const bool clamp : {false, true})
    for (const double v0 : {0.01, p.v0_mps, 10.0})
      for (const double e : e_grid) {
        const double expected = hunt_crossley_form_restitution(TestType::chi_v0(e));
        const double e_eff = effective_restitution_of<TestType>(p.K, p.mass_kg, v0, e, clamp);
        INFO(TestType::info.name << ": e = " << e << ", v0 = " << v0 << ", clamp = " << clamp
                                 << ", closed form " << expected << ", simulated " << e_eff);
        CHECK(std::abs(e_eff - expected) < solver_bound);
      }
}

TEST_CASE("Lambert-W closed form: limits", "[damping][restitution]") {
  // Independent checks of the closed form itself: a -> 0 expands as
  // e = 1 - (2/3) a + O(a^2) (Hunt and Crossley's linearisation), and a -> inf gives
  // e -> 1/a (the rebound speed tends to 1/chi, where 1 + chi v = 0).
  for (const double a : {1e-3, 1e-2}) CHECK(std::abs(hunt_crossley_form_restitution(a) - (1 - 2 * a / 3)) < a * a);
  CHECK(hunt_crossley_form_restitution(50.0) * 50.0 == Approx(1.0).epsilon(1e-12));
}

TEMPLATE_TEST_CASE("Kelvin-Voigt and the x^{1/4} DEM dashpot with tension allowed return their input e",
                   "[damping][restitution]", KelvinVoigt, TsujiDem) {
  // Kelvin-Voigt: F = k x + c x' with c = 2 zeta sqrt(k m), so m x'' + c x' + k x = 0 from
  // x = 0, x' = v0. Contact lasts half a damped period pi/omega_d, omega_d = omega_n
  // sqrt(1 - zeta^2), and x'(pi/omega_d) = -v0 exp(-pi zeta/sqrt(1 - zeta^2)). With
  // zeta = ln(1/e)/sqrt(pi^2 + ln^2 e), pi zeta/sqrt(1 - zeta^2) = ln(1/e): the rebound
  // speed is e v0, for every k, m, v0.
  //
  // DEM dashpot: m x'' + c x^{1/4} x' + K x^{3/2} = 0, c = -sqrt(5) beta sqrt(K m). With
  // v = x' as a function of x:  m v dv/dx + c x^{1/4} v + K x^{3/2} = 0.  Change the
  // independent variable to z = x^{5/4}: dz = (5/4) x^{1/4} dx, so dividing by x^{1/4},
  //   (5m/4) v dv/dz + c v + K z = 0,
  // the phase-plane equation of the linear oscillator (5m/4) z'' + c z' + K z = 0 started
  // at z = 0, z' = v0. The phase curve v(z) is the same, so is the speed at the return to
  // z = 0 (x = 0): as above with zeta = c/(2 sqrt(K 5m/4)) = c/sqrt(5 K m) = -beta =
  // ln(1/e)/sqrt(pi^2 + ln^2 e), so vr = e v0. (Only the time along the curve differs.)
  // Checked over e and v0 three decades apart.
  const ContactScales p = paper_steel_contact();
  for (const double v0 : {0.01, p.v0_mps, 10.0})
    for (const double e : e_grid) {
      INFO(TestType::info.name << ": e = " << e << ", v0 = " << v0);
      CHECK(std::abs(effective_restitution_of<TestType>(p.K, p.mass_kg, v0, e) - e) < solver_bound);
    }
}

TEST_CASE("Kelvin-Voigt and the DEM dashpot under the tension clamp: closed form", "[damping][restitution]") {
  // The clamp ends contact where the force reaches zero. For the linear oscillator
  // x = (v0/omega_d) e^{-zeta omega t} sin(theta), theta = omega_d t, s = sqrt(1 - zeta^2):
  //   x' = v0 e^{-zeta omega t} (cos theta - (zeta/s) sin theta),
  //   F/m = omega^2 x + 2 zeta omega x' = v0 omega e^{-zeta omega t} ((1 - 2 zeta^2) sin theta / s
  //         + 2 zeta cos theta),
  // which vanishes (after onset) at tan theta = -2 zeta s / (1 - 2 zeta^2), i.e.
  //   theta_F = pi - atan2(2 zeta s, 1 - 2 zeta^2),  cos theta_F = -(1 - 2 zeta^2),
  //   sin theta_F = 2 zeta s   (since (2 zeta s)^2 + (1 - 2 zeta^2)^2 = 1),
  // where cos theta - (zeta/s) sin theta = -1. So the clamped rebound is
  //   e_clamped = exp(-(zeta/s) theta_F)  >  e = exp(-(zeta/s) pi):
  // the clamp RAISES e_effective (the tensile tail it removes would pull the rod back).
  // The DEM dashpot's force is x^{1/4} times the same oscillator's force on the same
  // phase curve (z = x^{5/4}, see below), so it reaches zero at the same point with the
  // same speed: e_clamped is identical for both laws.
  const ContactScales p = paper_steel_contact();
  for (const double e : e_grid) {
    const double zeta = zeta_from_restitution(e, ZetaForm::exact), s = std::sqrt(1 - zeta * zeta);
    const double theta_F = std::numbers::pi - std::atan2(2 * zeta * s, 1 - 2 * zeta * zeta);
    const double expected = std::exp(-zeta / s * theta_F);
    INFO("e = " << e << ": expected clamped e_effective " << expected);
    CHECK(std::abs(effective_restitution_of<KelvinVoigt>(p.K, p.mass_kg, p.v0_mps, e, true) - expected) <
          solver_bound);
    CHECK(std::abs(effective_restitution_of<TsujiDem>(p.K, p.mass_kg, p.v0_mps, e, true) - expected) <
          solver_bound);
    // The library's closed form (model/restitution.hpp, YADE's export uses it) and its inverse.
    CHECK(clamped_restitution(zeta) == Approx(expected).epsilon(1e-14));
    CHECK(zeta_from_clamped_restitution(expected) == Approx(zeta).epsilon(1e-12));
  }
}

TEST_CASE("The guide's example law returns its input restitution", "[damping][restitution]") {
  // ExactHertzDashpot (tests/example_law.hpp) inverts the closed form above for chi v0;
  // with or without the clamp (its force never turns tensile) e_effective = e.
  const ContactScales p = paper_steel_contact();
  for (const bool clamp : {false, true})
    for (const double e : e_grid) {
      INFO("e = " << e << ", clamp = " << clamp);
      CHECK(std::abs(effective_restitution_of<ExactHertzDashpot>(p.K, p.mass_kg, p.v0_mps, e, clamp) - e) <
            solver_bound);
    }
}

TEST_CASE("The paper's law: e_effective depends on e alone, not on m, K or v0", "[damping][restitution]") {
  // Dimensional analysis. In the contact phase (rigid wall, no gravity) the motion is
  // m x'' = -F(x, x'), and the paper's law F = K x^{1/2} (x + tau x') has
  // tau = 2 zeta/omega_n with zeta = zeta(e) and omega_n = sqrt((4K/5m) X0^{1/2}),
  // X0 = (5 m v0^2 (1 + e^2)/(8K))^{2/5}: everything is built from m [kg],
  // K [kg m^{-1/2} s^{-2}], v0 [m s^{-1}] and the pure number e. So e_effective =
  // Phi(m, K, v0, e). A dimensionless product m^alpha K^beta v0^gamma needs
  //   kg: alpha + beta = 0,   m: -beta/2 + gamma = 0,   s: -2 beta - gamma = 0,
  // whose only solution is alpha = beta = gamma = 0: no dimensionless group can be
  // formed from m, K, v0, and by the Pi theorem e_effective = Phi(e). (Explicitly:
  // x = X* s, t = (X*/v0) tau with X* = (m v0^2/K)^{2/5} give s'' = -s^{1/2}(s + tau' s'),
  // s(0) = 0, s'(0) = 1, where tau' = tau v0/X* depends on e alone.) Gravity would
  // add g and the group g X*/v0^2, which is why the map is taken without it.
  // Checked at parameter sets decades apart, each against the paper's steel case.
  const ContactScales p = paper_steel_contact();
  struct Set {
    double K, mass_kg, v0_mps;
  };
  const std::vector<Set> sets{{1e6, 1e-3, 0.01}, {1e8, 1e-2, 1.0}, {1e10, 100.0, 10.0}, {3e11, 5.0, 0.05}};
  for (const bool clamp : {false, true})
    for (const double e : {0.1, 0.5, 0.795, 0.95}) {
      const double reference = effective_restitution_of<HongoPaper>(p.K, p.mass_kg, p.v0_mps, e, clamp);
      for (const Set& s : sets) {
        const double e_eff = effective_restitution_of<HongoPaper>(s.K, s.mass_kg, s.v0_mps, e, clamp);
        INFO("e = " << e << ", clamp = " << clamp << ": K = " << s.K << ", m = " << s.mass_kg << ", v0 = "
                    << s.v0_mps << " -> " << e_eff << " vs " << reference << " at the paper's steel case");
        CHECK(std::abs(e_eff - reference) < solver_bound);
      }
    }
}

TEST_CASE("The paper's law does not return its input restitution", "[damping][restitution]") {
  // Not a closed form: a lower bound on the discrepancy the README reports. The paper's
  // dashpot is K tau x^{1/2} x', i.e. chi_eff = tau/x, and its damping is fixed from the
  // small-damping eq. (6) and an amplitude estimate (eq. 10); at the paper's e = 0.795 it
  // returns about 0.83 (tension allowed). The test asserts only that the difference from
  // e exceeds 100 solver bounds, so a law that happened to be exact would fail here and
  // force the README's statement to be revisited.
  const ContactScales p = paper_steel_contact();
  const double e_eff = effective_restitution_of<HongoPaper>(p.K, p.mass_kg, p.v0_mps, 0.795);
  INFO("e_effective = " << e_eff);
  CHECK(std::abs(e_eff - 0.795) > 100 * solver_bound);
}
