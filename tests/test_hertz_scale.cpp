// Set-ups outside the Hertz model's scale are refused before any run (model/drop_test_setup.hpp,
// validate_hertz_scale): the reproducers of issue #19 that gave all-zero results, infinite
// forces, raw CVODE errors or a deformation larger than the ball.
#include "cli_runner.hpp"

#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace hertzdash;
using hertzdash::test::run_cli;

TEST_CASE("The speed at which the undamped Hertz deformation reaches the ball radius bounds the set-up", "[scale]") {
  // X = (5 m v^2 / (4K))^{2/5} = R at v* = sqrt(4 K R^{5/2} / (5 m)). For the steel rod (m = 0.778 kg,
  // K = 3.54e8 N/m^1.5, R = 0.0127 m): v* = sqrt(4 x 3.54e8 x 1.8176e-5 / 3.89) = 81.3 m/s.
  // Just below v* the set-up is valid, just above it is refused naming --impact-velocity.
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  const double K = hertz_stiffness(s);
  const double v_star = std::sqrt(4.0 * K * std::pow(s.ball_radius_m, 2.5) / (5.0 * s.mass_kg));
  CHECK(v_star == Approx(81.3).epsilon(2e-3));
  CHECK(undamped_hertz_impact(K, s.mass_kg, v_star).max_deformation_m == Approx(s.ball_radius_m).epsilon(1e-12));
  s.impact_velocity_mps = 0.999 * v_star;
  CHECK_NOTHROW(validate(s));
  s.impact_velocity_mps = 1.001 * v_star;
  CHECK_THROWS_WITH(validate(s), Catch::StartsWith("invalid impact-velocity = ") && Catch::Contains("m/s") &&
                                     Catch::Contains("small-deformation Hertz contact"));
  // The same bound as a drop height: h* = v*^2 / (2 g), blamed on the height (what() spells
  // keys as a case file does; the command line writes --height).
  s.impact_velocity_mps.reset();
  s.height_m = 1.001 * v_star * v_star / (2 * s.gravity_mps2);
  CHECK_THROWS_WITH(validate(s), Catch::StartsWith("invalid height = "));
  s.height_m = 0.999 * v_star * v_star / (2 * s.gravity_mps2);
  CHECK_NOTHROW(validate(s));
}

TEST_CASE("A deformation below a picometre is refused: no continuum contact model applies", "[scale]") {
  // X ~ v0^{4/5}: X = 1e-12 m for the steel rod at v0 = sqrt(4K (1e-12)^{5/2} / (5 m)) = 1.9e-11 m/s.
  DropTestSetup s = paper_setup(load_paper_parameters(), "steel", 0.02);
  const double v_min = std::sqrt(4.0 * hertz_stiffness(s) * std::pow(min_hertz_deformation_m, 2.5) / (5.0 * s.mass_kg));
  s.impact_velocity_mps = 1.01 * v_min;
  CHECK_NOTHROW(validate(s));
  s.impact_velocity_mps = 0.99 * v_min;
  CHECK_THROWS_WITH(validate(s), Catch::Contains("X >= 1e-12 m"));
}

TEST_CASE("Issue #19's extreme-scale reproducers exit 2 naming the option the user gave", "[scale][cli]") {
  // Each gave all-zero results, an infinite peak force, a raw [CVODES ERROR] or a deformation of
  // metres; each is now refused before any run, naming an option on the command line (before,
  // --gravity 1e308 was blamed on "--height = 0.02", a default nobody typed, and --mass 1e-308 too).
  const std::pair<const char*, const char*> cases[] = {
      {"--height 1e308", "invalid --height = 1e+308: must be below"},
      {"--gravity 1e308", "invalid --gravity = 1e+308: must be below"},
      {"--impact-velocity 1e-308", "invalid --impact-velocity = 1e-308: must be at least"},
      {"--ball-radius 1e308", "invalid --ball-radius = 1e+308: must be a value that, with the others, gives a Hertz "
                              "deformation X of at least 1e-12 m"},
      {"--mass 1e-308", "invalid --mass = 1e-308: must be at least"},
      {"--mass 1e308", "invalid --mass = 1e+308: must be below"},
      {"--rod-E 1e-308", "invalid --rod-E = 1e-308: must be a value that, with the others, gives a Hertz deformation X "
                         "below the ball radius"},
      {"--integrator rk4 --gravity 1e300", "invalid --gravity = 1e+300: must be below"},
      {"--ball-E 1e-3", "invalid --ball-E = 0.001"},
      {"--impact-velocity 100", "invalid --impact-velocity = 100: must be below 81.3"},
      {"--gravity 0 --impact-velocity 1e-20 --rtol 1e-11 --atol 1e-15", "invalid --impact-velocity = 1e-20"},
      {"--integrator cvode-regularized --damping zhiying-qishao --impact-velocity 3.99 --mass 0.086 --rod-E 1e-20",
       "invalid --impact-velocity = 3.99: must be below 5.284e-13 m/s"},
  };
  for (const auto& [args, expected] : cases) {
    INFO(args);
    const auto r = run_cli(std::string("simulate ") + args);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, Catch::StartsWith(std::string("hertzdash: ") + expected));
  }
  // A fall of 1e-20 m under g = 3.18 m/s^2 is within scale (X = 6e-12 m) but this law ends the
  // contact at ~0 force and the rod settles on the ball; CVODE's million-step bound ends the run
  // in seconds (it ran for more than 40 s) with a clear error and exit 1.
  const auto slow = run_cli("simulate --integrator cvode-regularized --damping gharib-hurmuzlu --no-tension "
                            "--height 1e-20 --gravity 3.18");
  CHECK(slow.exit_code == 1);
  CHECK_THAT(slow.err, Catch::Contains("did not finish: CVODE took 1000000 steps"));
  // restitution and bounce validate the same set-up.
  CHECK(run_cli("restitution --impact-velocity 1e-20").exit_code == 2);
  CHECK(run_cli("bounce --height 1e308").exit_code == 2);
}

TEST_CASE("A scale refusal lists the inputs that give the deformation and marks the defaults", "[scale][cli]") {
  // --gravity 1e308 from the default 20 mm: v0^2 = 2 g h = 4e306, X far above R. The bound on
  // g is v*^2 / (2 h) with the steel rod's v*^2 = 4 K R^{5/2} / (5 m) = 4 x 3.54e8 x 1.8176e-5 /
  // 3.89 = 6616 m^2/s^2: 6616 / 0.04 = 1.654e5 m/s^2.
  const auto r = run_cli("simulate --gravity 1e308");
  CHECK(r.exit_code == 2);
  CHECK_THAT(r.err, Catch::StartsWith("hertzdash: invalid --gravity = 1e+308: must be below 1.654e+05 m/s^2 (with --height "
                                      "0.02 m (default), --gravity 1e+308 m/s^2, --mass 0.778 kg (default), --ball-radius "
                                      "0.0127 m (default) and K = 3.54e+08 N/m^1.5 from --ball-E 2e+09 Pa (default), "
                                      "--rod-E 2.04e+11 Pa (default), --ball-nu 0.4 (default), --rod-nu 0.3 (default), the "
                                      "undamped Hertz deformation X"));
  // Given together, the speed's option is named and nothing is marked a default but the rest.
  const auto both = run_cli("simulate --height 1e308 --mass 0.5");
  CHECK_THAT(both.err, Catch::StartsWith("hertzdash: invalid --height = 1e+308: must be below") &&
                           Catch::Contains("--gravity 9.80665 m/s^2 (default), --mass 0.5 kg, --ball-radius"));
}
