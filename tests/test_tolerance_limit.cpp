// The limit above which a tolerance is flagged loose_tolerance (simulation/run/result_checks.hpp,
// loose_rtol_limit = 1e-4) rests on a measurement, made here and printed as a table:
// the relative error of e_effective of every adaptive integrator at rtol 1e-2, 1e-3 and
// 1e-4 against the same integrator at rtol 1e-12 (atol at its default, relative to the
// impact's scales), worst over two impacts -- the paper's steel rod from 20 mm with the
// paper's law, and duralumin-b from 50 mm with hunt-crossley.
//
// Asserted: at the limit every integrator is within step_resolution_target_error (0.1 %,
// what the fixed steps are held to); at ten times the limit at least one is not, so the
// limit could not be looser. The reference's own error (rtol 1e-12) is below 1e-10, far
// under either bound.
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"
#include "hertzdash/simulation/run/result_checks.hpp"
#include "hertzdash/simulation/run/step_resolution.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

using namespace hertzdash;

namespace {

double e_effective(const DropTestSetup& setup, const std::string& law, IntegratorKind kind, double rtol) {
  SolverSettings s;
  s.integrator = kind;
  s.rtol = rtol;
  ImpactSimulator simulator(s);
  return simulator.run(setup, law).e_effective;
}

}  // namespace

TEST_CASE("loose_rtol_limit: at 1e-4 every adaptive integrator's e_effective is within 0.1 %, at 1e-3 not every one",
          "[result_checks][tolerance]") {
  const PaperParameters paper = load_paper_parameters();
  const std::vector<std::pair<DropTestSetup, std::string>> impacts{{paper_setup(paper, "steel", 0.02), "hongo"},
                                                                   {paper_setup(paper, "duralumin-b", 0.05), "hunt-crossley"}};
  const std::vector<IntegratorKind> integrators{IntegratorKind::cvode,
                                                IntegratorKind::dopri5,
                                                IntegratorKind::cvode_regularized,
                                                IntegratorKind::dopri5_regularized,
                                                IntegratorKind::gbs8_regularized,
                                                IntegratorKind::taylor_regularized};
  const std::vector<double> tolerances{1e-2, 10 * loose_rtol_limit, loose_rtol_limit};
  std::printf("relative error of e_effective against rtol 1e-12, worst over steel/hongo 20 mm and "
              "duralumin-b/hunt-crossley 50 mm\n%-20s", "rtol");
  for (double tol : tolerances) std::printf("%12.0e", tol);
  std::printf("\n");
  std::vector<double> worst_at(tolerances.size(), 0.0);
  for (IntegratorKind kind : integrators) {
    std::vector<double> worst(tolerances.size(), 0.0);
    for (const auto& [setup, law] : impacts) {
      validate(setup);
      const double reference = e_effective(setup, law, kind, 1e-12);
      for (std::size_t i = 0; i < tolerances.size(); ++i)
        worst[i] = std::max(worst[i], std::abs(e_effective(setup, law, kind, tolerances[i]) / reference - 1));
    }
    std::printf("%-20s", std::string(to_string(kind)).c_str());
    for (std::size_t i = 0; i < tolerances.size(); ++i) {
      std::printf("%11.3g%%", 100 * worst[i]);
      worst_at[i] = std::max(worst_at[i], worst[i]);
    }
    std::printf("\n");
    INFO(to_string(kind));
    CHECK(worst.back() <= step_resolution_target_error);
  }
  CHECK(worst_at[1] > step_resolution_target_error);
}
