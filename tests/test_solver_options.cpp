// Solver options are validated whether or not the chosen integrator reads them (issue 19):
// a setting the integrator does not read is an error naming it and the integrators that
// read it, and a fixed step that cannot resolve the contact is refused before the run.
#include "cli_runner.hpp"

#include "hertzdash/model/hertz.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/step_resolution.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <unistd.h>

using hertzdash::test::run_cli;

namespace {

struct Refused {
  const char* args;
  const char* option;  // must appear in the message
  const char* range;   // must appear in the message
};

void check_refused(const Refused& c) {
  const auto trace = std::filesystem::temp_directory_path() /
                     ("hertzdash_solver_options_" + std::to_string(::getpid()) + ".csv");
  std::filesystem::remove(trace);
  const auto r = run_cli(std::string("simulate ") + c.args + " --trace " + trace.string());
  INFO("hertzdash simulate " << c.args << "\n  stderr: " << r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find(c.option) != std::string::npos);
  CHECK(r.err.find(c.range) != std::string::npos);
  CHECK(r.out.empty());
  CHECK_FALSE(std::filesystem::exists(trace));
}

}  // namespace

TEST_CASE("A solver option the integrator does not read is an error naming the integrators that read it", "[cli][solver]") {
  // Issue 19: "--dt 0, --dt -1e-6, --dt nan, --max-step 0 are ignored when the integrator
  // does not use them; --rtol with rk4 likewise". Each is now refused, values valid or not
  // (an invalid value is reported as such first; see test_cli_bad_input.cpp).
  const Refused cases[] = {
      {"--integrator rk4 --rtol 1e-6", "--rtol", "given only with --integrator cvode"},
      {"--integrator euler --atol 1e-12", "--atol", "given only with --integrator cvode"},
      {"--dt 1e-6", "--dt", "given only with --integrator euler, rk4"},
      {"--integrator dopri5 --dt 1e-6", "--dt", "given only with --integrator euler, rk4"},
      {"--no-event-location", "--no-event-location", "given only with --integrator euler, rk4"},
      {"--integrator rk4 --cvode-method bdf", "--cvode-method", "given only with --integrator cvode, cvode-regularized"},
      {"--integrator dopri5 --cvode-method adams", "--cvode-method", "given only with --integrator cvode, cvode-regularized"},
      {"--integrator rk4 --max-step 1e-6", "--max-step", "given only with --integrator cvode, dopri5"},
      {"--integrator dopri5-regularized --max-step 0", "--max-step", "given only with --integrator cvode, dopri5"},
      {"--dt 0", "--dt", "> 0"},
      {"--dt -1e-6", "--dt", "> 0"},
      {"--dt nan", "--dt", "> 0"},
  };
  for (const Refused& c : cases) check_refused(c);
}

TEST_CASE("The same options are accepted with an integrator that reads them", "[cli][solver]") {
  for (const char* args : {"--integrator rk4 --dt 1e-6 --no-event-location", "--rtol 1e-6 --atol 1e-12 --max-step 1e-4",
                           "--cvode-method bdf", "--integrator cvode-regularized --cvode-method adams",
                           "--integrator gbs8-regularized --rtol 1e-9", "--integrator dopri5 --max-step 1e-5"}) {
    const auto r = run_cli(std::string("simulate ") + args);
    INFO("hertzdash simulate " << args << "\n  stderr: " << r.err);
    CHECK(r.exit_code == 0);
  }
}

TEST_CASE("A fixed step coarser than t_H / 5 is refused with the bound it must meet", "[cli][solver]") {
  // Steel rod, h = 20 mm: v0 = sqrt(2 g h) = 0.6263 m/s. The undamped Hertz contact lasts
  // t_H = 2.9432 X / v0 with X = (5 m v0^2 / 4K)^(2/5) (model/hertz.hpp), 1.2 ms here, so the
  // coarsest step allowed is t_H / 5 = 0.24 ms. Issue 19: --dt 0.01 gave e_effective 2.8e4
  // with exit 0, --dt 1e308 gave 0. Both are refused; so is one step just above the bound.
  const auto setup = hertzdash::resolve_setup(hertzdash::RunOptions{}, hertzdash::load_paper_parameters());
  const double v0 = hertzdash::approach_speed(setup);
  const double t_hertz =
      hertzdash::undamped_hertz_impact(hertzdash::hertz_stiffness(setup), setup.mass_kg, v0).contact_time_s;
  const double bound = t_hertz / static_cast<double>(hertzdash::min_steps_per_hertz_contact);
  const std::string above = fmt::format("--integrator rk4 --dt {:.17g}", bound * (1 + 1e-9));
  const std::string below = fmt::format("--integrator rk4 --dt {:.17g}", bound * (1 - 1e-9));
  for (const std::string& args : {std::string("--integrator rk4 --dt 0.01"), std::string("--integrator rk4 --dt 1e308"),
                                  std::string("--integrator euler --dt 0.01"), above})
    check_refused({args.c_str(), "--dt", "at most"});
  // Just below the bound the run goes ahead (under-resolved, with a warning on stderr).
  const auto r = run_cli("simulate " + below);
  INFO("hertzdash simulate " << below << "\n  stderr: " << r.err);
  CHECK(r.exit_code == 0);
}

TEST_CASE("A non-finite result is an error, never a silent number", "[solver]") {
  hertzdash::ImpactSummary s;
  s.e_effective = 0.83;
  s.peak_force_N = 600;
  s.max_deformation_m = 1e-4;
  s.contact_time_s = 1e-3;
  s.rebound_velocity_mps = 0.5;
  CHECK_NOTHROW(hertzdash::require_finite_results(s));
  s.peak_force_N = std::numeric_limits<double>::infinity();
  CHECK_THROWS_WITH(hertzdash::require_finite_results(s), Catch::Contains("peak_force_N = inf"));
  s.peak_force_N = 600;
  s.e_effective = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(hertzdash::require_finite_results(s), Catch::Contains("e_effective = nan"));
}
