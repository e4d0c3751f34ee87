#include "validation/common/contact_sensitivity.hpp"

#include "hertzdash/integrators/cvode_check.hpp"
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/force_rate.hpp"
#include "hertzdash/model/hertz.hpp"

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace hertzdash {

namespace {

constexpr int Ns = 4;  // sensitivity parameters q = (K, tau, m, v0)

void check(int flag, const char* call) { check_cvode_flag(flag, call, "CVODES"); }
template <class T> T* check_ptr(T* p, const char* call) { return check_cvode_ptr(p, call, "CVODES"); }

/// The contact-phase model: the paper's force and its partial derivatives, all from the
/// law (HongoPaper::gradient_of_root at u = x^{1/2}), and the acceleration.
struct ContactModel {
  ContactPhaseParameters p;
  HongoPaper::Gradient gradient(double x, double v) const {
    return HongoPaper::gradient_of_root(p.K, p.tau_s, std::sqrt(std::max(x, 0.0)), v);
  }
  double force(double x, double v) const { return gradient(x, v).F; }
  double accel(double x, double v) const { return p.gravity_mps2 - force(x, v) / p.mass_kg; }
  /// dF/dx * s_x = F_u s_x / (2u) for the gradient G at x, with its x -> 0 limit 0 (see the header).
  static double force_x_times(const HongoPaper::Gradient& G, double x, double s_x) {
    if (x <= 0) return 0.0;
    return G.F_u * s_x / (2.0 * std::sqrt(x));
  }
  /// Explicit partial derivatives dF/dq (F does not depend on m or v0 explicitly).
  static ContactGradient force_q(const HongoPaper::Gradient& G) { return {G.F_K, G.F_tau, 0.0, 0.0}; }
  /// The peak-force event: dF/dtau / (2K) = x^{1/2} dF/dt / K (model/force_rate.hpp), finite at x = 0.
  double peak_force_event(double x, double v) const {
    const HongoPaper::Gradient G = gradient(x, v);
    const double u = std::sqrt(std::max(x, 0.0));
    return force_rate(G.F_u, G.F_xdot, v, 2.0 * u * (p.gravity_mps2 - G.F / p.mass_kg)) / (2.0 * p.K);
  }
};

int rhs(realtype, N_Vector y, N_Vector dy, void* user) {
  const auto& m = *static_cast<const ContactModel*>(user);
  const double* Y = N_VGetArrayPointer(y);
  double* D = N_VGetArrayPointer(dy);
  D[0] = Y[1];
  D[1] = m.accel(Y[0], Y[1]);
  return 0;
}

// s_i' = J s_i + df/dq_i, f = (v, g - F/m).
int sensitivity_rhs(int ns, realtype, N_Vector y, N_Vector, N_Vector* yS, N_Vector* ySdot, void* user, N_Vector,
                    N_Vector) {
  const auto& m = *static_cast<const ContactModel*>(user);
  const double* Y = N_VGetArrayPointer(y);
  const double x = Y[0], v = Y[1], M = m.p.mass_kg;
  const HongoPaper::Gradient G = m.gradient(x, v);
  const ContactGradient Fq = ContactModel::force_q(G);
  for (int i = 0; i < ns; ++i) {
    const double* s = N_VGetArrayPointer(yS[i]);
    double* ds = N_VGetArrayPointer(ySdot[i]);
    ds[0] = s[1];
    double explicit_term = -Fq[i] / M;
    if (i == q_mass) explicit_term = G.F / (M * M);  // d(-F/m)/dm
    ds[1] = -(ContactModel::force_x_times(G, x, s[0]) + G.F_xdot * s[1]) / M + explicit_term;
  }
  return 0;
}

int roots(realtype, N_Vector y, realtype* g, void* user) {
  const auto& m = *static_cast<const ContactModel*>(user);
  const double* Y = N_VGetArrayPointer(y);
  const double x = Y[0], v = Y[1];
  g[0] = x;                            // separation
  g[1] = v;                            // max compression
  g[2] = m.peak_force_event(x, v);     // x^{1/2} dF/dt / K
  return 0;
}

/// Owns the CVODES objects; frees them on every path.
struct Cvodes {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  N_Vector* yS = nullptr;
  SUNNonlinearSolver nls = nullptr, nls_sens = nullptr;
  void* mem = nullptr;
  ~Cvodes() {
    if (mem) CVodeFree(&mem);
    if (nls_sens) SUNNonlinSolFree(nls_sens);
    if (nls) SUNNonlinSolFree(nls);
    if (yS) N_VDestroyVectorArray(yS, Ns);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

}  // namespace

ContactPhaseSensitivities contact_phase_sensitivities(const ContactPhaseParameters& p,
                                                      const ContactSensitivityOptions& options) {
  if (!(p.K > 0 && p.tau_s >= 0 && p.mass_kg > 0 && p.v0_mps > 0 && p.gravity_mps2 >= 0))
    throw std::invalid_argument("contact_phase_sensitivities: need K, m, v0 > 0 and tau, g >= 0");
  ContactModel model{p};
  Cvodes c;
  check(SUNContext_Create(nullptr, &c.ctx), "SUNContext_Create");
  c.y = check_ptr(N_VNew_Serial(2, c.ctx), "N_VNew_Serial");
  double* Y = N_VGetArrayPointer(c.y);
  Y[0] = 0.0;
  Y[1] = p.v0_mps;
  c.yS = check_ptr(N_VCloneVectorArray(Ns, c.y), "N_VCloneVectorArray");
  for (int i = 0; i < Ns; ++i) N_VConst(0.0, c.yS[i]);
  N_VGetArrayPointer(c.yS[q_v0])[1] = 1.0;  // dv(0)/dv0

  c.mem = check_ptr(CVodeCreate(CV_ADAMS, c.ctx), "CVodeCreate");
  check(CVodeInit(c.mem, rhs, 0.0, c.y), "CVodeInit");
  check(CVodeSetUserData(c.mem, &model), "CVodeSetUserData");
  N_Vector atol = check_ptr(N_VClone(c.y), "N_VClone");
  N_VGetArrayPointer(atol)[0] = options.atol * undamped_hertz_impact(p.K, p.mass_kg, p.v0_mps).max_deformation_m;
  N_VGetArrayPointer(atol)[1] = options.atol * p.v0_mps;
  const int tol_flag = CVodeSVtolerances(c.mem, options.rtol, atol);
  N_VDestroy(atol);
  check(tol_flag, "CVodeSVtolerances");
  check(CVodeSetMaxNumSteps(c.mem, 100000), "CVodeSetMaxNumSteps");
  // At separation s_x != 0 while x -> 0, so J s has an integrable (t_c - t)^{-1/2} term (see the
  // header); CVODES resolves it with steps near the roundoff of t and would warn each time.
  check(CVodeSetMaxHnilWarns(c.mem, -1), "CVodeSetMaxHnilWarns");
  c.nls = check_ptr(SUNNonlinSol_FixedPoint(c.y, 0, c.ctx), "SUNNonlinSol_FixedPoint");
  check(CVodeSetNonlinearSolver(c.mem, c.nls), "CVodeSetNonlinearSolver");

  check(CVodeSensInit(c.mem, Ns, CV_SIMULTANEOUS, sensitivity_rhs, c.yS), "CVodeSensInit");
  // Scale each sensitivity by its parameter (pbar), so the estimated tolerances are relative.
  double q[Ns] = {p.K, p.tau_s, p.mass_kg, p.v0_mps};
  double pbar[Ns];
  for (int i = 0; i < Ns; ++i) pbar[i] = q[i] > 0 ? q[i] : 1.0;
  check(CVodeSetSensParams(c.mem, nullptr, pbar, nullptr), "CVodeSetSensParams");
  check(CVodeSensEEtolerances(c.mem), "CVodeSensEEtolerances");
  check(CVodeSetSensErrCon(c.mem, SUNTRUE), "CVodeSetSensErrCon");
  c.nls_sens = check_ptr(SUNNonlinSol_FixedPointSens(Ns + 1, c.y, 0, c.ctx), "SUNNonlinSol_FixedPointSens");
  check(CVodeSetNonlinearSolverSensSim(c.mem, c.nls_sens), "CVodeSetNonlinearSolverSensSim");
  check(CVodeRootInit(c.mem, 3, roots), "CVodeRootInit");
  int direction[3] = {-1, -1, -1};
  check(CVodeSetRootDirection(c.mem, direction), "CVodeSetRootDirection");

  // Long enough for any separation: 20 undamped contact times.
  const double t_end = 20.0 * undamped_hertz_impact(p.K, p.mass_kg, p.v0_mps).contact_time_s;
  ContactPhaseSensitivities out;
  bool peak_seen = false, max_seen = false;
  double t = 0.0;
  while (true) {
    const int flag = CVode(c.mem, t_end, c.y, &t, CV_NORMAL);
    check(flag, "CVode");
    if (flag != CV_ROOT_RETURN) throw std::runtime_error("contact_phase_sensitivities: no separation before t_end");
    int found[3];
    check(CVodeGetRootInfo(c.mem, found), "CVodeGetRootInfo");
    realtype t_sens = 0;
    check(CVodeGetSens(c.mem, &t_sens, c.yS), "CVodeGetSens");
    const double x = Y[0], v = Y[1];
    auto s = [&](int i, int k) { return N_VGetArrayPointer(c.yS[i])[k]; };
    if (found[2] && !peak_seen) {  // the first (compressive) force maximum
      peak_seen = true;
      const HongoPaper::Gradient G = model.gradient(x, v);
      const ContactGradient Fq = ContactModel::force_q(G);
      out.peak_force_N = G.F;
      for (int i = 0; i < Ns; ++i)
        out.d_peak_force[i] = ContactModel::force_x_times(G, x, s(i, 0)) + G.F_xdot * s(i, 1) + Fq[i];
    }
    if (found[1] && !max_seen) {
      max_seen = true;
      out.max_deformation_m = x;
      for (int i = 0; i < Ns; ++i) out.d_max_deformation[i] = s(i, 0);
    }
    if (found[0]) {
      const double a = model.accel(x, v);
      out.contact_time_s = t;
      out.rebound_velocity_mps = -v;
      for (int i = 0; i < Ns; ++i) {
        out.d_contact_time[i] = -s(i, 0) / v;
        out.d_rebound_velocity[i] = -(s(i, 1) + a * out.d_contact_time[i]);
      }
      break;
    }
  }
  if (!peak_seen || !max_seen) throw std::runtime_error("contact_phase_sensitivities: peak or max compression missed");
  check(CVodeGetNumSteps(c.mem, &out.steps), "CVodeGetNumSteps");
  return out;
}

}  // namespace hertzdash
