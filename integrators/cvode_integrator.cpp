#include "hertzdash/integrators/cvode_integrator.hpp"

#include <cvodes/cvodes.h>
#include <nvector/nvector_serial.h>
#include <sunlinsol/sunlinsol_band.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_band.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace hertzdash {

const char* to_string(CvodeMethod m) { return m == CvodeMethod::adams ? "adams" : "bdf"; }

namespace {

// Every SUNDIALS return code is checked; failures name the call and CVODE's flag.
void check(int flag, const char* call) {
  if (flag < 0) {
    char* name = CVodeGetReturnFlagName(flag);  // malloc'ed by SUNDIALS: ours to free
    const std::string text = std::string("CVODE: ") + call + " failed with " + (name ? name : "?");
    std::free(name);
    throw std::runtime_error(text);
  }
}
template <class T> T* check_ptr(T* p, const char* call) {
  if (p == nullptr) throw std::runtime_error(std::string("CVODE: ") + call + " returned NULL");
  return p;
}

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
  check(SUNContext_Create(nullptr, &d.ctx), "SUNContext_Create");
  d.y = check_ptr(N_VNew_Serial(dimension, d.ctx), "N_VNew_Serial");
  N_VConst(0.0, d.y);
  d.atol = check_ptr(N_VClone(d.y), "N_VClone");
  N_VConst(options.atol, d.atol);
  d.mem = check_ptr(CVodeCreate(options.method == CvodeMethod::adams ? CV_ADAMS : CV_BDF, d.ctx), "CVodeCreate");
  check(CVodeInit(d.mem, rhs_thunk, 0.0, d.y), "CVodeInit");
  check(CVodeSetUserData(d.mem, &callbacks_), "CVodeSetUserData");
  check(CVodeSVtolerances(d.mem, options.rtol, d.atol), "CVodeSVtolerances");
  check(CVodeSetMaxNumSteps(d.mem, options.max_num_steps), "CVodeSetMaxNumSteps");
  if (options.max_step > 0) check(CVodeSetMaxStep(d.mem, options.max_step), "CVodeSetMaxStep");
  if (options.method == CvodeMethod::adams) {
    // Non-stiff: a fixed-point corrector needs no Jacobian.
    d.NLS = check_ptr(SUNNonlinSol_FixedPoint(d.y, 0, d.ctx), "SUNNonlinSol_FixedPoint");
    check(CVodeSetNonlinearSolver(d.mem, d.NLS), "CVodeSetNonlinearSolver");
  } else {
    if (options.band_half_width >= 0 && options.band_half_width < dimension - 1) {
      const int w = options.band_half_width;
      d.A = check_ptr(SUNBandMatrix(dimension, w, w, d.ctx), "SUNBandMatrix");
      d.LS = check_ptr(SUNLinSol_Band(d.y, d.A, d.ctx), "SUNLinSol_Band");
    } else {
      d.A = check_ptr(SUNDenseMatrix(dimension, dimension, d.ctx), "SUNDenseMatrix");
      d.LS = check_ptr(SUNLinSol_Dense(d.y, d.A, d.ctx), "SUNLinSol_Dense");
    }
    check(CVodeSetLinearSolver(d.mem, d.LS, d.A), "CVodeSetLinearSolver");
  }
  d.direction.assign(static_cast<std::size_t>(event_count), -1);
  if (event_count > 0) {
    check(CVodeRootInit(d.mem, event_count, events_thunk), "CVodeRootInit");
    check(CVodeSetRootDirection(d.mem, d.direction.data()), "CVodeSetRootDirection");
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
  check(CVodeReInit(d.mem, t, d.y), "CVodeReInit");
  check(CVodeSVtolerances(d.mem, options_.rtol, d.atol), "CVodeSVtolerances");  // copies d.atol
  d.stop_time = NAN;
}

int CvodeIntegrator::step(double t_end, double& t, double* y) {
  Impl& d = *impl_;
  if (!(d.stop_time == t_end)) {  // once per restart, not every step
    check(CVodeSetStopTime(d.mem, t_end), "CVodeSetStopTime");
    d.stop_time = t_end;
  }
  realtype t_reached = t;
  const int flag = CVode(d.mem, t_end, d.y, &t_reached, CV_ONE_STEP);
  check(flag, "CVode");
  t = t_reached;
  const double* yv = N_VGetArrayPointer(d.y);
  for (int i = 0; i < d.dimension; ++i) y[i] = yv[i];
  if (flag == CV_ROOT_RETURN) return 1;
  if (flag == CV_TSTOP_RETURN) return 2;
  return 0;
}

const int* CvodeIntegrator::roots_found() {
  check(CVodeGetRootInfo(impl_->mem, impl_->roots.data()), "CVodeGetRootInfo");
  return impl_->roots.data();
}

IntegrationStats CvodeIntegrator::work_since_restart() const {
  long steps = 0, rhs = 0, lin_rhs = 0;
  check(CVodeGetNumSteps(impl_->mem, &steps), "CVodeGetNumSteps");
  check(CVodeGetNumRhsEvals(impl_->mem, &rhs), "CVodeGetNumRhsEvals");
  if (options_.method == CvodeMethod::bdf) {
    check(CVodeGetNumLinRhsEvals(impl_->mem, &lin_rhs), "CVodeGetNumLinRhsEvals");
  }
  IntegrationStats s;
  s.steps = steps;
  s.rhs_evaluations = rhs + lin_rhs;
  return s;
}

}  // namespace hertzdash
