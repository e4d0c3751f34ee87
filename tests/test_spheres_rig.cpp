// The rig `spheres` (simulation/rigs/spheres_rig.hpp): two spheres of their own head-on.
//
// The relative motion of two free spheres obeys m* x'' = -F(x, x') with m* = m1 m2/(m1 + m2), and
// the Hertz contact of radii R1, R2 is a sphere of R* = R1 R2/(R1 + R2) on a flat with eq. (3)'s E*
// (Johnson 1985, sec. 4.2). The tests derive what follows from that and from momentum, and check the
// rig against it and against the drop test's sphere on a plate.
#include "tests/cli_runner.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

using hertzdash::test::run_cli;

namespace {

nlohmann::json spheres(const std::string& args) {
  const auto r = run_cli("spheres " + args + " --json");
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  return nlohmann::json::parse(r.out);
}

// A glass bead (R = 1 mm, E = 63 GPa, nu = 0.22, 2500 kg/m^3) and a steel ball (R = 2 mm, 200 GPa,
// 0.3, 7800 kg/m^3) at 1 m/s.
const std::string glass = "--density 2500 --ball-radius 1e-3 --ball-E 63e9 --ball-nu 0.22 --impact-velocity 1 ";
const std::string steel = "--second-radius 2e-3 --second-E 200e9 --second-nu 0.3 --second-density 7800 ";

}  // namespace

TEST_CASE("spheres, undamped: the Hertz contact of m*, R* and E*, momentum and energy conserved", "[rigs][spheres]") {
  // With the law `none` (no dashpot) the impact is Hertz's: X = (5 m* v^2 / (4 K))^{2/5}, K = (4/3) E*
  // sqrt(R*), the peak force K X^{3/2}, the contact time (4/5) B(2/5, 1/2) X / v (the time integral of
  // the energy equation m* x'^2/2 + (2/5) K x^{5/2} = m* v^2/2 from 0 to X, twice). The solver runs at
  // rtol 1e-8: the tolerance 1e-6 is a hundred times that.
  const auto j = spheres(glass + steel + "--damping none --rtol 1e-10");
  const double m1 = 4.0 / 3 * std::numbers::pi * 1e-9 * 2500, m2 = 4.0 / 3 * std::numbers::pi * 8e-9 * 7800;
  const double m = m1 * m2 / (m1 + m2), R = 1e-3 * 2e-3 / 3e-3;
  const double E = 1 / ((1 - 0.22 * 0.22) / 63e9 + (1 - 0.3 * 0.3) / 200e9), K = 4.0 / 3 * E * std::sqrt(R), v = 1;
  const double X = std::pow(5 * m * v * v / (4 * K), 0.4);
  const double B = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  CHECK(j["reduced_mass_kg"].get<double>() == Approx(m).epsilon(1e-14));
  CHECK(j["reduced_radius_m"].get<double>() == Approx(R).epsilon(1e-14));
  CHECK(j["effective_modulus_Pa"].get<double>() == Approx(E).epsilon(1e-14));
  CHECK(j["e_effective"].get<double>() == Approx(1).epsilon(1e-6));
  CHECK(j["max_compression_m"].get<double>() == Approx(X).epsilon(1e-6));
  CHECK(j["peak_force_N"].get<double>() == Approx(K * std::pow(X, 1.5)).epsilon(1e-6));
  CHECK(j["contact_time_s"].get<double>() == Approx(0.8 * B * X / v).epsilon(1e-6));
  // Momentum m1 v = m1 v1 + m2 v2 and, undamped, the kinetic energy m1 v^2 = m1 v1^2 + m2 v2^2.
  const double v1 = j["first_velocity_after_mps"], v2 = j["second_velocity_after_mps"];
  CHECK(m1 * v1 + m2 * v2 == Approx(m1 * v).epsilon(1e-12));
  CHECK(m1 * v1 * v1 + m2 * v2 * v2 == Approx(m1 * v * v).epsilon(1e-5));
}

TEST_CASE("spheres: the same contact whichever sphere is first, and a sphere on a plate as the second grows",
          "[rigs][spheres]") {
  // m*, R* and E* are symmetric in the two spheres, so e, the contact time and the peak force do
  // not depend on which is first (to the solver's round-off: the same numbers in another order).
  const std::string law = "--damping kuwabara-kono --restitution 0.9 ";
  const auto ab = spheres(glass + steel + law);
  const auto ba = spheres("--density 7800 --ball-radius 2e-3 --ball-E 200e9 --ball-nu 0.3 --impact-velocity 1 "
                          "--second-radius 1e-3 --second-E 63e9 --second-nu 0.22 --second-density 2500 " + law);
  for (const char* k : {"e_effective", "contact_time_s", "peak_force_N", "reduced_mass_kg", "reduced_radius_m"})
    CHECK(ab[k].get<double>() == Approx(ba[k].get<double>()).epsilon(1e-9));
  // A second sphere of radius 10^6 R1 and mass 10^9 m1 is a plate: m* -> m1, R* -> R1 to 1e-6, and
  // the contact is the drop test's ball on a plate with no gravity (`simulate`), to the same 1e-6
  // (X scales as m*^{2/5} R*^{-1/5}: relative changes of 1e-6 move it by less than that).
  const auto plate = spheres(glass + law + "--second-radius 1e3 --second-E 200e9 --second-nu 0.3 --second-mass 1e1");
  const auto r = run_cli("simulate " + glass + law + "--rod-E 200e9 --rod-nu 0.3 --gravity 0 --json");
  REQUIRE(r.exit_code == 0);
  const auto drop = nlohmann::json::parse(r.out);
  CHECK(plate["e_effective"].get<double>() == Approx(drop["e_effective"].get<double>()).epsilon(1e-6));
  CHECK(plate["contact_time_s"].get<double>() == Approx(drop["contact_time_s"].get<double>()).epsilon(1e-6));
  CHECK(plate["peak_force_N"].get<double>() == Approx(drop["peak_force_N"].get<double>()).epsilon(1e-6));
}

TEST_CASE("spheres: the velocities after follow e and momentum, and the law is calibrated on the pair",
          "[rigs][spheres]") {
  // Kuwabara-Kono's A is calibrated so that this pair's e is 0.9 at 1 m/s; then v2 - v1 = e v and
  // m1 v1 + m2 v2 = m1 v. Equal spheres: v1 = v (1 - e)/2, v2 = v (1 + e)/2.
  const auto j = spheres(glass + "--damping kuwabara-kono --restitution 0.9");
  CHECK(j["e_effective"].get<double>() == Approx(0.9).epsilon(1e-6));
  CHECK(j["first_velocity_after_mps"].get<double>() == Approx(0.05).epsilon(1e-5));
  CHECK(j["second_velocity_after_mps"].get<double>() == Approx(0.95).epsilon(1e-6));
  const double m = 4.0 / 3 * std::numbers::pi * 1e-9 * 2500 / 2;
  CHECK(j["energy_lost_J"].get<double>() == Approx(0.5 * m * (1 - 0.81)).epsilon(1e-5));
  CHECK(j["inputs"]["second_mass_kg"].get<double>() == Approx(2 * m).epsilon(1e-14));  // the first's density
}

TEST_CASE("spheres: bad input exits 2 naming the option", "[rigs][spheres]") {
  const std::vector<std::pair<std::string, std::string>> refused{
      {"--density 2500 --ball-radius 1e-3 --restitution 0.9", "--impact-velocity"},
      {"--impact-velocity 1 --restitution 0.9", "--mass"},
      {"--impact-velocity 1 --density 2500", "--restitution"},  // the paper's law reads e
      {glass + "--restitution 0.9 --height 0.1", "--height"},   // no drop
      {glass + "--restitution 0.9 --rod-E 1e9", "--rod-E"},     // no flat
      {glass + "--restitution 0.9 --second-mass 1e-3 --second-density 7800", "--second-density"},
      {glass + "--restitution 0.9 --second-nu 0.5", "--second-nu"},
      {glass + "--restitution 0.9 --second-radius -1", "--second-radius"},
  };
  for (const auto& [args, named] : refused) {
    CAPTURE(args);
    const auto r = run_cli("spheres " + args);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::Contains(named));
  }
}
