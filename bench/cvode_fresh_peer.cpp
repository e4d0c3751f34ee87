// Peer: CVODE (Adams, fixed-point corrector) created afresh for every impact -- the
// naive use, which pays the solver set-up on each impact.
//
// One root function g = -x in flight, x in contact (direction -1, decreasing
// through zero), CV_NORMAL mode to a far end time with root return; at onset the
// law is calibrated and CVODE re-initialised (CVodeReInit) in contact mode; at
// separation the state at the root is CVODE's own interpolant. Every SUNDIALS return
// code is checked.
#include "bench/impact_solvers.hpp"
#include "hertzdash/integrators/cvode_check.hpp"

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <stdexcept>
#include <string>

namespace hertzdash::bench {

namespace {

struct CvodeContext {
  const DropTest<HongoPaper>* sys;
};

int cvode_rhs(realtype t, N_Vector y, N_Vector dy, void* user_data) {
  const auto* c = static_cast<CvodeContext*>(user_data);
  const double* yv = N_VGetArrayPointer(y);
  DropTest<HongoPaper>::State ye{yv[0], yv[1]}, de;
  c->sys->rhs(t, ye, de);
  double* d = N_VGetArrayPointer(dy);
  d[0] = de[0];
  d[1] = de[1];
  return 0;
}

int cvode_gap(realtype, N_Vector y, realtype* g, void* user_data) {
  const auto* c = static_cast<CvodeContext*>(user_data);
  const double x = N_VGetArrayPointer(y)[0];
  g[0] = c->sys->in_contact() ? x : -x;
  return 0;
}

/// Owns one CVODE instance for one impact.
struct CvodeInstance {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  SUNNonlinearSolver nls = nullptr;
  void* mem = nullptr;
  ~CvodeInstance() {
    if (mem) CVodeFree(&mem);
    if (nls) SUNNonlinSolFree(nls);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

class CvodeFresh final : public ImpactSolver {
 public:
  explicit CvodeFresh(double tol) : tol_(tolerances_for(tol)) {}

  ImpactResult run(const DropTestSetup& setup) override {
    PeerImpact impact(setup);
    const auto& y0 = impact.y0;
    CvodeContext user{&impact.sys};
    const double t_end = 10 * impact.fall_time_s + 20 * impact.contact_time_s;

    CvodeInstance c;
    check_cvode_flag(SUNContext_Create(nullptr, &c.ctx), "SUNContext_Create");
    c.y = check_cvode_ptr(N_VNew_Serial(2, c.ctx), "N_VNew_Serial");
    double* yv = N_VGetArrayPointer(c.y);
    yv[0] = y0[0], yv[1] = y0[1];
    c.mem = check_cvode_ptr(CVodeCreate(CV_ADAMS, c.ctx), "CVodeCreate");
    check_cvode_flag(CVodeInit(c.mem, cvode_rhs, 0.0, c.y), "CVodeInit");
    check_cvode_flag(CVodeSetUserData(c.mem, &user), "CVodeSetUserData");
    check_cvode_flag(CVodeSStolerances(c.mem, tol_.rtol, tol_.atol), "CVodeSStolerances");
    check_cvode_flag(CVodeSetMaxNumSteps(c.mem, 1000000), "CVodeSetMaxNumSteps");
    c.nls = check_cvode_ptr(SUNNonlinSol_FixedPoint(c.y, 0, c.ctx), "SUNNonlinSol_FixedPoint");
    check_cvode_flag(CVodeSetNonlinearSolver(c.mem, c.nls), "CVodeSetNonlinearSolver");
    check_cvode_flag(CVodeRootInit(c.mem, 1, cvode_gap), "CVodeRootInit");
    int direction = -1;
    check_cvode_flag(CVodeSetRootDirection(c.mem, &direction), "CVodeSetRootDirection");

    long evaluations = 0;
    double t = 0, v_impact = y0[1];
    for (;;) {
      const int flag = CVode(c.mem, t_end, c.y, &t, CV_NORMAL);
      check_cvode_flag(flag, "CVode");
      if (flag != CV_ROOT_RETURN) throw std::runtime_error("CVODE peer: no crossing before the end time");
      if (impact.sys.in_contact()) break;
      // Onset: calibrate the law, restart in contact mode.
      impact.sys.handle_event(event_index(DropTestEvent::contact), t, DropTest<HongoPaper>::State{yv[0], yv[1]});
      v_impact = yv[1];
      long n = 0;
      check_cvode_flag(CVodeGetNumRhsEvals(c.mem, &n), "CVodeGetNumRhsEvals");
      evaluations += n;
      check_cvode_flag(CVodeReInit(c.mem, t, c.y), "CVodeReInit");
    }
    long n = 0;
    check_cvode_flag(CVodeGetNumRhsEvals(c.mem, &n), "CVodeGetNumRhsEvals");
    return {-yv[1] / v_impact, evaluations + n};
  }

 private:
  Tolerances tol_;
};

}  // namespace

std::unique_ptr<ImpactSolver> make_cvode_fresh(double tol) { return std::make_unique<CvodeFresh>(tol); }

}  // namespace hertzdash::bench
