#pragma once
// One drop test, end to end: validated set-up -> system (model) -> integrator ->
// trajectory and events -> summary. The integrator is one setting, so comparing
// integrators on the same model is one flag.
#include "integrators/cvode_integrator.hpp"
#include "integrators/dormand_prince.hpp"
#include "integrators/explicit_euler.hpp"
#include "integrators/extrapolation.hpp"
#include "integrators/fixed_step.hpp"
#include "integrators/rk4.hpp"
#include "model/damping/registry.hpp"
#include "model/drop_test.hpp"
#include "model/hertz.hpp"
#include "io/provenance.hpp"
#include "simulation/regularized_impact.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

/// dopri5_regularized ("dopri5-regularized"), cvode_regularized ("cvode-regularized"),
/// gbs8_regularized ("gbs8-regularized"): the fall in closed form and the contact in
/// regularising variables (simulation/regularized_impact.hpp) with dopri5, CVODE
/// or the order-8 extrapolation method (integrators/extrapolation.hpp; the fastest
/// path). With the tension clamp they run dopri5 (for gbs8: with its tolerances) or
/// CVODE in the physical variables; gbs8 needs a smooth contact, so for a law that does
/// not declare RootPolynomialLaw it runs dopri5-regularized with its checks on.
enum class IntegratorKind { euler, rk4, cvode, dopri5, dopri5_regularized, cvode_regularized, gbs8_regularized };
inline constexpr IntegratorKind all_integrator_kinds[] = {
    IntegratorKind::euler,  IntegratorKind::rk4,           IntegratorKind::cvode,           IntegratorKind::dopri5,
    IntegratorKind::dopri5_regularized, IntegratorKind::cvode_regularized, IntegratorKind::gbs8_regularized};

/// The CLI spellings of every integrator, comma-separated ("euler, rk4, ...").
std::string integrator_names();
/// The integrator spelled `name`; throws InvalidParameter(option, name, "one of: ...").
IntegratorKind parse_integrator(std::string_view name, const std::string& option = "--integrator");

/// True for the kinds that integrate the contact in regularising variables.
inline bool is_regularized(IntegratorKind k) {
  return k == IntegratorKind::dopri5_regularized || k == IntegratorKind::cvode_regularized ||
         k == IntegratorKind::gbs8_regularized;
}
const char* to_string(IntegratorKind k);

struct SolverSettings {
  IntegratorKind integrator = IntegratorKind::cvode;
  FixedStepOptions fixed_step;  ///< euler, rk4
  CvodeOptions cvode;           ///< cvode and cvode_regularized
  DormandPrinceOptions dopri5;  ///< dopri5 and dopri5_regularized (adaptive Dormand-Prince 5(4), events landed on)
  ExtrapolationOptions gbs8;    ///< gbs8_regularized (Gragg-Bulirsch-Stoer order 8, events landed on)

  /// dopri5's options with gbs8's tolerances, for gbs8_regularized's fall-backs.
  DormandPrinceOptions dopri5_with_gbs8_tolerances() const {
    DormandPrinceOptions o;
    o.rtol = gbs8.rtol;
    o.atol = gbs8.atol;
    return o;
  }
};

/// Throws InvalidParameter for a non-positive step or tolerance.
void validate(const SolverSettings& s);

/// The result of one impact. Velocities are speeds (>= 0).
struct ImpactSummary {
  double K = 0;                        ///< Hertz stiffness [N/m^{3/2}]
  double impact_velocity_mps = 0;      ///< approach speed at contact onset
  double rebound_velocity_mps = 0;     ///< rebound speed at separation (0 if none)
  double e_effective = 0;              ///< rebound / approach speed
  double peak_force_N = 0;             ///< largest contact force
  double max_deformation_m = 0;        ///< largest x
  double contact_time_s = 0;           ///< separation minus onset time
  double t_onset_s = 0, t_separation_s = 0;
  bool separated = false;              ///< false if the rod came to rest on the ball
  IntegrationStats work;               ///< steps and right-hand-side evaluations, whole run
  std::vector<NamedValue> law_coefficients;
};

/// One sample of the contact phase (the --trace columns).
struct TraceSample {
  double t_s, x_m, xdot_mps, force_N, accel_mps2, rod_displacement_m, rod_velocity_mps;
};
std::vector<std::string> trace_columns();

/// Runs impacts; keeps its CVODE memory across runs (CVodeReInit), so a sweep pays
/// the solver set-up once. One per thread.
class ImpactSimulator {
 public:
  explicit ImpactSimulator(const SolverSettings& settings);
  ~ImpactSimulator();
  const SolverSettings& settings() const { return settings_; }

  /// Run the drop test with the registered law `law` (validated set-up required).
  ImpactSummary run(const DropTestSetup& setup, std::string_view law, std::vector<TraceSample>* trace = nullptr);

  /// The same for a law known at compile time: the force inlines into the integrator.
  template <DampingLaw Law>
  ImpactSummary run(const DropTestSetup& setup, std::vector<TraceSample>* trace = nullptr);

 private:
  SolverSettings settings_;
  std::unique_ptr<CvodeIntegrator> cvode_;
  std::unique_ptr<CvodeIntegrator> cvode_regularized_;  ///< the regularised contact's size (3 components)
};

/// The inputs of a run as name = value pairs (units in the names), for headers and JSON.
Parameters describe_run(const DropTestSetup& setup, std::string_view law, const SolverSettings& solver);

// ---------------------------------------------------------------------------

namespace detail {

/// Builds the summary (and the optional trace) from the steps and events.
template <class System>
class ImpactObserver {
 public:
  ImpactObserver(const System& sys, ImpactSummary& summary, std::vector<TraceSample>* trace)
      : sys_(sys), s_(summary), trace_(trace) {}

  void on_step(double t, const typename System::State& y) {
    if (sys_.in_contact()) sample(t, y);
  }
  void on_event(int which, double t, const typename System::State& y, EventAction action) {
    if (which == contact_event && action == EventAction::restart) begin(t, y);
    if (action == EventAction::stop) {
      s_.separated = true;
      s_.t_separation_s = t;
      s_.rebound_velocity_mps = std::max(-y[1], 0.0);
    }
  }
  void begin(double t, const typename System::State& y) {
    s_.t_onset_s = t;
    s_.impact_velocity_mps = y[1];
    s_.law_coefficients = sys_.law().coefficients();
    sample(t, y);
  }

 private:
  void sample(double t, const typename System::State& y) {
    const double F = sys_.contact_force(y);
    s_.peak_force_N = std::max(s_.peak_force_N, F);
    s_.max_deformation_m = std::max(s_.max_deformation_m, y[0]);
    if (trace_) {
      const auto& m = sys_.model();
      trace_->push_back({t, y[0], y[1], F, m.gravity_mps2 - F / m.mass_kg, y[0] + m.setup.height_m, y[1]});
    }
  }
  const System& sys_;
  ImpactSummary& s_;
  std::vector<TraceSample>* trace_;
};

}  // namespace detail

template <DampingLaw Law>
ImpactSummary ImpactSimulator::run(const DropTestSetup& setup, std::vector<TraceSample>* trace) {
  if (is_regularized(settings_.integrator) && !setup.no_tension) {
    ImpactSummary s;
    if (settings_.integrator == IntegratorKind::gbs8_regularized && RootPolynomialLaw<Law>) {
      run_regularized_impact<Law>(
          setup, [&](auto& sys, auto& y, double t0, double t1, auto& obs) { return integrate_extrapolation(sys, y, t0, t1, settings_.gbs8, obs); },
          s, trace);
    } else if (settings_.integrator != IntegratorKind::cvode_regularized) {
      const DormandPrinceOptions opt = dopri5_options_for<Law>(
          settings_.integrator == IntegratorKind::gbs8_regularized ? settings_.dopri5_with_gbs8_tolerances() : settings_.dopri5);
      run_regularized_impact<Law>(
          setup, [&](auto& sys, auto& y, double t0, double t1, auto& obs) { return integrate_dormand_prince(sys, y, t0, t1, opt, obs); },
          s, trace);
    } else {
      using Contact = detail::ContactUntil<Law>;
      if (!cvode_regularized_)
        cvode_regularized_ = std::make_unique<CvodeIntegrator>(Contact::dimension, Contact::event_count, settings_.cvode);
      run_regularized_impact<Law>(
          setup, [&](auto& sys, auto& y, double t0, double t1, auto& obs) { return cvode_regularized_->integrate(sys, y, t0, t1, obs); },
          s, trace);
    }
    return s;
  }
  const DropTestModel model(setup);
  DropTest<Law> sys(model);
  ImpactSummary s;
  s.K = model.K;
  detail::ImpactObserver<DropTest<Law>> observer(sys, s, trace);
  auto y = sys.initial_state();
  if (sys.in_contact()) observer.begin(0.0, y);

  // Long enough for any impact to end: the fall, then 20 undamped contact times.
  const double v0 = approach_speed(setup);
  const double fall_s = setup.impact_velocity_mps ? 0.0 : v0 / setup.gravity_mps2;
  const double t_end = fall_s + 20.0 * undamped_hertz_impact(model.K, model.mass_kg, v0).contact_time_s;

  switch (settings_.integrator) {
    case IntegratorKind::euler:
      s.work = integrate_fixed_step<ExplicitEuler>(sys, y, 0.0, t_end, settings_.fixed_step, observer);
      break;
    case IntegratorKind::rk4:
      s.work = integrate_fixed_step<ClassicalRk4>(sys, y, 0.0, t_end, settings_.fixed_step, observer);
      break;
    case IntegratorKind::cvode:
    case IntegratorKind::cvode_regularized:  // with the tension clamp (see above)
      if (!cvode_) cvode_ = std::make_unique<CvodeIntegrator>(DropTest<Law>::dimension, DropTest<Law>::event_count, settings_.cvode);
      s.work = cvode_->integrate(sys, y, 0.0, t_end, observer);
      break;
    case IntegratorKind::dopri5:
    case IntegratorKind::dopri5_regularized:  // with the tension clamp (see above)
      s.work = integrate_dormand_prince(sys, y, 0.0, t_end, settings_.dopri5, observer);
      break;
    case IntegratorKind::gbs8_regularized:  // with the tension clamp (see above)
      s.work = integrate_dormand_prince(sys, y, 0.0, t_end, settings_.dopri5_with_gbs8_tolerances(), observer);
      break;
  }
  if (s.separated) {
    s.contact_time_s = s.t_separation_s - s.t_onset_s;
    s.e_effective = s.rebound_velocity_mps / s.impact_velocity_mps;
  }
  return s;
}

}  // namespace hertzdash
