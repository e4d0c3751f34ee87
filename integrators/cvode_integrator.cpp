#include "hertzdash/integrators/cvode_integrator.hpp"

#include "hertzdash/integrators/cvode_check.hpp"

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace hertzdash {

const char* to_string(CvodeMethod m) { return m == CvodeMethod::adams ? "adams" : "bdf"; }

namespace {

int rhs_thunk(realtype t, N_Vector y, N_Vector dy, void* user_data) {
  auto* cb = static_cast<CvodeCallbacks*>(user_data);
  cb->rhs(cb->system, cb->dimension, t, N_VGetArrayPointer(y), N_VGetArrayPointer(dy));
  return 0;
}

int events_thunk(realtype t, N_Vector y, realtype* g, void* user_data) {
  auto* cb = static_cast<CvodeCallbacks*>(user_data);
  cb->events(cb->system, cb->dimension, t, N_VGetArrayPointer(y), g);
  return 0;
}

}  // namespace

struct CvodeIntegrator::Impl {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  N_Vector atol = nullptr;  ///< absolute tolerance of each component, refilled at every restart
  SUNMatrix A = nullptr;
  SUNLinearSolver LS = nullptr;
  SUNNonlinearSolver NLS = nullptr;
  void* mem = nullptr;
  double stop_time = NAN;  ///< the stop time set since the last restart (NAN: none)
  int dimension = 0;
  int event_count = 0;
  std::vector<int> roots;
  std::vector<int> direction;  ///< -1 each: events fire as g decreases through zero

  ~Impl() {
    if (mem) CVodeFree(&mem);
    if (NLS) SUNNonlinSolFree(NLS);
    if (LS) SUNLinSolFree(LS);
    if (A) SUNMatDestroy(A);
    if (atol) N_VDestroy(atol);
    if (y) N_VDestroy(y);
    if (ctx) SUNContext_Free(&ctx);
  }
};

CvodeIntegrator::CvodeIntegrator(int dimension, int event_count, const CvodeOptions& options)
    : impl_(std::make_unique<Impl>()), options_(options) {
  if (!(options.rtol > 0)) throw std::invalid_argument("CVODE: rtol must be > 0");
  if (!(options.atol > 0)) throw std::invalid_argument("CVODE: atol must be > 0");
  Impl& d = *impl_;
  d.dimension = dimension;
  d.event_count = event_count;
  d.roots.assign(static_cast<std::size_t>(event_count), 0);
  check_cvode_flag(SUNContext_Create(nullptr, &d.ctx), "SUNContext_Create");
  d.y = check_cvode_ptr(N_VNew_Serial(dimension, d.ctx), "N_VNew_Serial");
  N_VConst(0.0, d.y);
  d.atol = check_cvode_ptr(N_VClone(d.y), "N_VClone");
  N_VConst(options.atol, d.atol);
  d.mem = check_cvode_ptr(CVodeCreate(options.method == CvodeMethod::adams ? CV_ADAMS : CV_BDF, d.ctx), "CVodeCreate");
  check_cvode_flag(CVodeInit(d.mem, rhs_thunk, 0.0, d.y), "CVodeInit");
  check_cvode_flag(CVodeSetUserData(d.mem, &callbacks_), "CVodeSetUserData");
  check_cvode_flag(CVodeSVtolerances(d.mem, options.rtol, d.atol), "CVodeSVtolerances");
  check_cvode_flag(CVodeSetMaxNumSteps(d.mem, options.max_num_steps), "CVodeSetMaxNumSteps");
  if (options.max_step > 0) check_cvode_flag(CVodeSetMaxStep(d.mem, options.max_step), "CVodeSetMaxStep");
  if (options.method == CvodeMethod::adams) {
    // Non-stiff: a fixed-point corrector needs no Jacobian.
    d.NLS = check_cvode_ptr(SUNNonlinSol_FixedPoint(d.y, 0, d.ctx), "SUNNonlinSol_FixedPoint");
    check_cvode_flag(CVodeSetNonlinearSolver(d.mem, d.NLS), "CVodeSetNonlinearSolver");
  } else {
    if (options.band_half_width >= 0 && options.band_half_width < dimension - 1) {
      const int w = options.band_half_width;
      d.A = check_cvode_ptr(SUNBandMatrix(dimension, w, w, d.ctx), "SUNBandMatrix");
      d.LS = check_cvode_ptr(SUNLinSol_Band(d.y, d.A, d.ctx), "SUNLinSol_Band");
    } else {
      d.A = check_cvode_ptr(SUNDenseMatrix(dimension, dimension, d.ctx), "SUNDenseMatrix");
      d.LS = check_cvode_ptr(SUNLinSol_Dense(d.y, d.A, d.ctx), "SUNLinSol_Dense");
    }
    check_cvode_flag(CVodeSetLinearSolver(d.mem, d.LS, d.A), "CVodeSetLinearSolver");
  }
  d.direction.assign(static_cast<std::size_t>(event_count), -1);
  if (event_count > 0) {
    check_cvode_flag(CVodeRootInit(d.mem, event_count, events_thunk), "CVodeRootInit");
    check_cvode_flag(CVodeSetRootDirection(d.mem, d.direction.data()), "CVodeSetRootDirection");
  }
}

CvodeIntegrator::~CvodeIntegrator() = default;

void CvodeIntegrator::check_dimensions(int dimension, int event_count) const {
  if (dimension != impl_->dimension || event_count != impl_->event_count) {
    throw std::invalid_argument("CvodeIntegrator: system size does not match the integrator's");
  }
}

void CvodeIntegrator::restart(double t, const double* y, const double* atol) {
  Impl& d = *impl_;
  double* yv = N_VGetArrayPointer(d.y);
  double* av = N_VGetArrayPointer(d.atol);
  for (int i = 0; i < d.dimension; ++i) yv[i] = y[i], av[i] = atol[i];
  check_cvode_flag(CVodeReInit(d.mem, t, d.y), "CVodeReInit");
  check_cvode_flag(CVodeSVtolerances(d.mem, options_.rtol, d.atol), "CVodeSVtolerances");  // copies d.atol
  d.stop_time = NAN;
}

int CvodeIntegrator::step(double t_end, double& t, double* y) {
  Impl& d = *impl_;
  if (!(d.stop_time == t_end)) {  // once per restart, not every step
    check_cvode_flag(CVodeSetStopTime(d.mem, t_end), "CVodeSetStopTime");
    d.stop_time = t_end;
  }
  realtype t_reached = t;
  const int flag = CVode(d.mem, t_end, d.y, &t_reached, CV_ONE_STEP);
  check_cvode_flag(flag, "CVode");
  t = t_reached;
  const double* yv = N_VGetArrayPointer(d.y);
  for (int i = 0; i < d.dimension; ++i) y[i] = yv[i];
  if (flag == CV_ROOT_RETURN) return 1;
  if (flag == CV_TSTOP_RETURN) return 2;
  return 0;
}

const int* CvodeIntegrator::roots_found() {
  check_cvode_flag(CVodeGetRootInfo(impl_->mem, impl_->roots.data()), "CVodeGetRootInfo");
  return impl_->roots.data();
}

IntegrationStats CvodeIntegrator::work_since_restart() const {
  long steps = 0, rhs = 0, lin_rhs = 0;
  check_cvode_flag(CVodeGetNumSteps(impl_->mem, &steps), "CVodeGetNumSteps");
  check_cvode_flag(CVodeGetNumRhsEvals(impl_->mem, &rhs), "CVodeGetNumRhsEvals");
  if (options_.method == CvodeMethod::bdf) {
    check_cvode_flag(CVodeGetNumLinRhsEvals(impl_->mem, &lin_rhs), "CVodeGetNumLinRhsEvals");
  }
  IntegrationStats s;
  s.steps = steps;
  s.rhs_evaluations = rhs + lin_rhs;
  return s;
}

}  // namespace hertzdash
