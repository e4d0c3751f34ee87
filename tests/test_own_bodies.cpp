// Your own bodies (issue 43): a sphere of the user's own is described by its own inputs, not by
// the paper's rod and nylon hemisphere whose values fill what is not given.
//   - `--density` instead of `--mass`: the falling body is the sphere, m = (4/3) pi R^3 rho;
//   - the yield check uses nylon's yield stress only for the paper's hemisphere: a sphere whose
//     modulus, Poisson ratio and radius are all given (or a dropped ball, `--density`) is checked
//     only against a `--ball-yield-stress` the user gives;
//   - the run names the rod preset only where the preset supplies a value: with the mass, the
//     flat's modulus and Poisson ratio and e all given it supplies none.
// The glass bead: R = 1 mm, rho = 2500 kg/m^3, E = 63 GPa, nu = 0.22, on steel at 1 m/s, where
// the Hertz peak pressure (1.5 GPa) is far above nylon's 1.52 x 70 MPa.
#include "tests/cli_runner.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <numbers>
#include <string>

using hertzdash::test::run_cli;

namespace {

const std::string bead = "--ball-radius 1e-3 --ball-E 63e9 --ball-nu 0.22 --rod-E 200e9 --rod-nu 0.3 --restitution 0.9 "
                         "--impact-velocity 1 ";

bool warns_of_yield(const nlohmann::json& j) {
  for (const auto& w : j["warnings"])
    if (w["code"] == "yield_onset") return true;
  return false;
}

}  // namespace

TEST_CASE("your own bodies: --density gives the ball's mass, its own sphere no nylon yield check, and no rod preset",
          "[cli][bodies]") {
  const auto by_density = run_cli("simulate --json --density 2500 " + bead);
  REQUIRE(by_density.exit_code == 0);
  const auto j = nlohmann::json::parse(by_density.out);
  // m = (4/3) pi (1e-3)^3 2500 = 1.0471975511965977e-5 kg.
  CHECK(j["inputs"]["mass_kg"].get<double>() == Approx(4.0 / 3.0 * std::numbers::pi * 1e-9 * 2500).epsilon(1e-15));
  CHECK_FALSE(warns_of_yield(j));
  CHECK_FALSE(j["inputs"].contains("rod"));
  // The same bead by its mass: the same impact.
  const auto by_mass = nlohmann::json::parse(run_cli("simulate --json --mass 1.0471975511965977e-5 " + bead).out);
  CHECK(by_mass["peak_force_N"].get<double>() == j["peak_force_N"].get<double>());
  CHECK_FALSE(warns_of_yield(by_mass));
  // A yield stress the user gives is checked: soda-lime glass has no yield, but 100 MPa as a
  // stand-in is exceeded 10 times over.
  CHECK(warns_of_yield(nlohmann::json::parse(run_cli("simulate --json --density 2500 --ball-yield-stress 1e8 " + bead).out)));
  // The paper's hemisphere with another modulus (as a fit of it gives) is still nylon: checked.
  CHECK(warns_of_yield(nlohmann::json::parse(run_cli("simulate --json --ball-E 1.7e9").out)));
  // The preset still supplies the restitution: the run names it.
  const auto preset = nlohmann::json::parse(
      run_cli("simulate --json --mass 1e-5 --ball-radius 1e-3 --ball-E 63e9 --ball-nu 0.22 --rod-E 200e9 --rod-nu 0.3 "
              "--impact-velocity 1").out);
  CHECK(preset["inputs"]["rod"] == "steel");
  // --density and --mass together: refused, naming --density.
  const auto both = run_cli("simulate --density 2500 --mass 1e-5 " + bead);
  CHECK(both.exit_code == 2);
  CHECK_THAT(both.err, Catch::Contains("--density") && Catch::Contains("--mass"));
}
