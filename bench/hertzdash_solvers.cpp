// hertzdash's own integrators as benchmark solvers: the library path, ImpactSimulator.
#include "bench/impact_solvers.hpp"

#include "hertzdash/model/damping/laws/hongo_paper.hpp"

namespace hertzdash::bench {

namespace {

class HertzdashSolver final : public ImpactSolver {
 public:
  explicit HertzdashSolver(const SolverSettings& s) : simulator_(s) {}
  ImpactResult run(const DropTestSetup& setup) override {
    const ImpactSummary s = simulator_.run<HongoPaper>(setup);
    return {s.e_effective, s.work.rhs_evaluations};
  }

 private:
  ImpactSimulator simulator_;
};

}  // namespace

std::unique_ptr<ImpactSolver> make_hertzdash_solver(IntegratorKind kind, double tol_or_dt) {
  SolverSettings s;
  s.integrator = kind;
  const Tolerances tol = tolerances_for(tol_or_dt);
  s.rtol = tol.rtol;
  s.atol = tol.atol;
  s.dt_s = tol_or_dt;
  validate(s);
  return std::make_unique<HertzdashSolver>(s);
}

}  // namespace hertzdash::bench
