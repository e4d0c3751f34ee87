#pragma once
// The measurements of the convergence study, shared by the study program
// (validation/convergence/convergence.cpp) and the convergence tests
// (tests/convergence/): one impact, solved by every integrator at a given
// resolution, its five observed quantities, and their errors against a reference.
//
// The impact: the paper's steel rod at h = 20 mm (approach speed v0 = sqrt(2 g h)),
// with gravity switched off so that the undamped Hertz closed forms of
// model/hertz.hpp and model/undamped_hertz_trajectory.hpp are exact. The rod starts
// in flight a gap time before contact (x = -v0 t_gap), so the onset is a real event
// that a fixed step can straddle; in flight x'' = 0, which every method integrates
// exactly, so onset happens at t_gap with speed v0 exactly.
//
// Quantities (all errors relative): effective restitution, peak force, maximum
// deformation, contact time, and the state at t* = onset + 0.3 tc (compression
// phase) as max(|dx|/X, |dv|/v0), X the undamped maximum deformation. The state at t* is read
// by integrating a second time with t_end = t_gap + t*: every integrator shortens
// its last step (or sets CVODE's stop time) to land on t_end, so reading the state
// adds no interpolation error.
#include "hertzdash/integrators/cvode_integrator.hpp"
#include "hertzdash/integrators/explicit_euler.hpp"
#include "hertzdash/integrators/fixed_step.hpp"
#include "hertzdash/integrators/rk4.hpp"
#include "hertzdash/model/damping/laws/hongo_paper.hpp"
#include "hertzdash/model/damping/laws/undamped.hpp"
#include "hertzdash/model/drop_test.hpp"
#include "hertzdash/model/contact_environments.hpp"
#include "hertzdash/model/contact_system.hpp"
#include "hertzdash/model/undamped_hertz_trajectory.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"
#include "hertzdash/simulation/run/physical_impact.hpp"

#include <algorithm>
#include <array>
#include <ctime>
#include <limits>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace hertzdash::convergence {

/// The five quantities, in table order.
enum Quantity : int { e_effective_q, peak_force_q, max_deformation_q, contact_time_q, state_q, quantity_count };
inline const char* quantity_name(int q) {
  static const char* names[] = {"e_effective", "peak_force", "max_deformation", "contact_time", "state_at_t_star"};
  return names[q];
}

/// What one run measures.
struct ImpactQuantities {
  double e_effective = 0;
  double peak_force_N = 0;
  double max_deformation_m = 0;
  double contact_time_s = 0;
  ContactState at_t_star{0, 0};  ///< state at t* after onset
};

/// One measured run: its quantities and its cost.
struct Measurement {
  ImpactQuantities q;
  long rhs_evaluations = 0;  ///< the full impact run (not the second run to t*)
  double cpu_time_s = 0;     ///< the full impact run (detail::cpu_time_per_call)
};

/// The convergence problem: one impact, constant for the whole study.
struct ConvergenceProblem {
  DropTestSetup setup;        ///< steel rod, impact_velocity = v0, gravity 0
  double K = 0;               ///< Hertz stiffness [N/m^{3/2}]
  double v0_mps = 0;          ///< approach speed [m/s]
  double tc_scale_s = 0;      ///< undamped contact time: sets the steps, t* and the run length [s]
  double X_scale_m = 0;       ///< undamped maximum deformation: scales the state error [m]
  double t_star_s = 0;        ///< observation time after onset, 0.3 tc_scale [s]
};

inline constexpr double t_star_fraction = 0.3;  ///< t* / tc: inside compression for both laws

inline ConvergenceProblem make_problem(const PaperParameters& paper) {
  ConvergenceProblem p;
  p.setup = paper_setup(paper, "steel", 0.02);
  p.v0_mps = std::sqrt(2.0 * paper.gravity_mps2 * 0.02);
  p.setup.impact_velocity_mps = p.v0_mps;
  p.setup.gravity_mps2 = 0.0;
  validate(p.setup);
  p.K = hertz_stiffness(p.setup);
  const UndampedHertzImpact u = undamped_hertz_impact(p.K, p.setup.mass_kg, p.v0_mps);
  p.tc_scale_s = u.contact_time_s;
  p.X_scale_m = u.max_deformation_m;
  p.t_star_s = t_star_fraction * u.contact_time_s;
  return p;
}

/// Relative errors of q against ref, in Quantity order.
inline std::array<double, quantity_count> relative_errors(const ConvergenceProblem& p, const ImpactQuantities& q,
                                                          const ImpactQuantities& ref) {
  auto rel = [](double a, double b) { return std::abs(a - b) / std::abs(b); };
  const double state = std::max(std::abs(q.at_t_star.x_m - ref.at_t_star.x_m) / p.X_scale_m,
                                std::abs(q.at_t_star.xdot_mps - ref.at_t_star.xdot_mps) / p.v0_mps);
  return {rel(q.e_effective, ref.e_effective), rel(q.peak_force_N, ref.peak_force_N),
          rel(q.max_deformation_m, ref.max_deformation_m), rel(q.contact_time_s, ref.contact_time_s), state};
}

// ---------------------------------------------------------------------------
// References.

/// Closed-form reference for a law, where one exists.
///
/// HOOK for closed-form references: this is the one place to add them. The
/// undamped law is exact here. The Hunt-Crossley family F = K x^{3/2}(1 + chi x')
/// has a first integral m v dv/(1 + chi v) = -K x^{3/2} dx, which gives
/// the maximum deformation and the restitution in closed form; add an
/// `if constexpr (std::is_same_v<Law, ...>)` branch returning them, with the
/// quantities that have no closed form (contact time, state at t*) taken from
/// numerical_reference<Law>(p).q below, since every quantity needs a reference.
template <DampingLaw Law>
std::optional<ImpactQuantities> closed_form_reference(const ConvergenceProblem& p) {
  if constexpr (std::is_same_v<Law, Undamped>) {
    const UndampedHertzImpact u = undamped_hertz_impact(p.K, p.setup.mass_kg, p.v0_mps);
    return ImpactQuantities{1.0, u.peak_force_N, u.max_deformation_m, u.contact_time_s,
                            undamped_hertz_state_at(p.K, p.setup.mass_kg, p.v0_mps, p.t_star_s)};
  }
  return std::nullopt;
}

// ---------------------------------------------------------------------------
// Runs in the physical variables (x, x'): DropTest, as `hertzdash simulate` runs it.

namespace detail {

/// CPU time of one call of `body` [s]: the thread's CPU clock (other processes on a
/// shared machine do not count), calls batched to >= 0.2 ms, and the fastest batch of
/// those filling min_timing_s kept (the least disturbed one). min_timing_s = 0: one call.
template <class Body> double cpu_time_per_call(double min_timing_s, Body&& body) {
  auto now = [] {
    timespec ts{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
  };
  const double start = now();
  double best = std::numeric_limits<double>::infinity();
  do {
    const double batch_start = now();
    long calls = 0;
    do {
      body();
      ++calls;
    } while (now() - batch_start < std::min(2e-4, min_timing_s));
    best = std::min(best, (now() - batch_start) / static_cast<double>(calls));
  } while (now() - start < min_timing_s);
  return best;
}

}  // namespace detail

/// Solve the impact with `integrate(sys, y, t0, t_end, observer) -> IntegrationStats`
/// from a gap of gap_s seconds of flight. min_timing_s: repeat the run at least this
/// long to time it (0: run once).
template <DampingLaw Law, class Integrate>
Measurement measure_physical(const ConvergenceProblem& p, double gap_s, Integrate&& integrate,
                             double min_timing_s = 0) {
  const DropTestModel model(p.setup);
  using System = DropTest<Law>;
  const typename System::State start{-p.v0_mps * gap_s, p.v0_mps};
  Measurement m;
  ImpactSummary s;
  m.cpu_time_s = detail::cpu_time_per_call(min_timing_s, [&] {
    System sys(model);
    s = ImpactSummary{};
    hertzdash::detail::ImpactObserver<System> observer(sys, s, nullptr);
    auto y = start;
    s.work = integrate(sys, y, 0.0, gap_s + 2.0 * p.tc_scale_s, observer);
  });
  m.rhs_evaluations = s.work.rhs_evaluations;
  m.q.e_effective = s.separated ? s.rebound_velocity_mps / s.impact_velocity_mps : 0.0;
  m.q.peak_force_N = s.peak_force_N;
  m.q.max_deformation_m = s.max_deformation_m;
  m.q.contact_time_s = s.separated ? s.t_separation_s - s.t_onset_s : 0.0;

  System sys(model);
  NullObserver none;
  auto y = start;
  integrate(sys, y, 0.0, gap_s + p.t_star_s, none);
  m.q.at_t_star = {y[0], y[1]};
  return m;
}

/// Fixed-step method (ExplicitEuler, ClassicalRk4) at step dt_s.
template <class Method, DampingLaw Law>
Measurement measure_fixed_step(const ConvergenceProblem& p, double dt_s, bool locate_events, double gap_s,
                               double min_timing_s = 0) {
  const FixedStepOptions opt{dt_s, locate_events};
  return measure_physical<Law>(
      p, gap_s,
      [&](auto& sys, auto& y, double t0, double t1, auto& obs) {
        return integrate_fixed_step<Method>(sys, y, t0, t1, opt, obs);
      },
      min_timing_s);
}

/// CVODE (Adams or BDF) at relative tolerance rtol and absolute tolerance rtol of the
/// impact's scales (X_scale for x, v0 for x': DropTest::state_scale), the same relative
/// accuracy for a deformation of the size of the maximum and a speed of the size of v0.
inline CvodeOptions cvode_options(CvodeMethod method, double rtol) {
  CvodeOptions o;
  o.method = method;
  o.rtol = rtol;
  o.atol = rtol;
  return o;
}

template <DampingLaw Law>
Measurement measure_cvode(const ConvergenceProblem& p, CvodeMethod method, double rtol, double min_timing_s = 0) {
  CvodeIntegrator cvode(DropTest<Law>::dimension, DropTest<Law>::event_count, cvode_options(method, rtol));
  // CVODE locates the onset whatever the gap: a fixed 1 % of the contact time.
  return measure_physical<Law>(
      p, 0.01 * p.tc_scale_s,
      [&](auto& sys, auto& y, double t0, double t1, auto& obs) { return cvode.integrate(sys, y, t0, t1, obs); },
      min_timing_s);
}

// ---------------------------------------------------------------------------
// Runs in the regularised variables (u = x^{1/2}, tau): model/contact_system.hpp.

namespace detail {

template <class System> struct RegularizedObserver {
  const System* sys;
  double v0;
  ImpactQuantities* q;
  void on_step(double, const typename System::State& y) {
    q->peak_force_N = std::max(q->peak_force_N, sys->force(y));
    q->max_deformation_m = std::max(q->max_deformation_m, y[0] * y[0]);
  }
  void on_event(int which, double, const typename System::State& y, EventAction) {
    if (which == event_index(ContactEvent::separation)) {
      q->e_effective = -y[1] / v0;
      q->contact_time_s = y[2];
    }
    if (which == event_index(ContactEvent::observation_time)) q->at_t_star = {y[0] * y[0], y[1]};
  }
};

}  // namespace detail

/// The contact's extent in tau [s/m^{1/2}], from a located RK4 run at 2000 steps of
/// the tau scale (the step only has to resolve the contact; the study's steps are
/// then tau_c / N).
template <DampingLaw Law> double regularized_contact_tau(const ConvergenceProblem& p) {
  const ImpactConditions c{p.K, p.setup.mass_kg, p.v0_mps, p.setup.restitution};
  ContactSystem<Law, FixedWall> sys(c, p.setup.damping, FixedWall{p.setup.gravity_mps2});
  auto y = sys.initial_state();
  NullObserver none;
  // The undamped contact lasts ~1.5 tau_scale; 10 leaves room for any law of the family.
  const double tau_scale = p.tc_scale_s / (2.0 * std::sqrt(p.X_scale_m));
  const IntegrationStats s =
      integrate_fixed_step<ClassicalRk4>(sys, y, 0.0, 10.0 * tau_scale, FixedStepOptions{tau_scale / 2000, true}, none);
  if (!s.stopped_by_event) throw std::runtime_error("regularized_contact_tau: no separation within 10 tau scales");
  return s.t_final;
}

/// Fixed-step `Method` in tau with step dtau, events located (in tau).
template <class Method, DampingLaw Law>
Measurement measure_regularized(const ConvergenceProblem& p, double dtau, double min_timing_s = 0) {
  const ImpactConditions c{p.K, p.setup.mass_kg, p.v0_mps, p.setup.restitution};
  using System = ContactSystem<Law, FixedWall>;
  System sys(c, p.setup.damping, FixedWall{p.setup.gravity_mps2}, p.t_star_s);
  Measurement m;
  IntegrationStats stats;
  m.cpu_time_s = detail::cpu_time_per_call(min_timing_s, [&] {
    m.q = ImpactQuantities{};
    detail::RegularizedObserver<System> observer{&sys, p.v0_mps, &m.q};
    auto y = sys.initial_state();
    stats = integrate_fixed_step<Method>(sys, y, 0.0, 1e6 * dtau, FixedStepOptions{dtau, true}, observer);
  });
  m.rhs_evaluations = stats.rhs_evaluations;
  return m;
}

/// The numerical reference for a law without closed forms: RK4 in regularising
/// variables at 40000 steps per contact, and how well it is verified (largest
/// relative differences over the five quantities).
struct NumericalReference {
  ImpactQuantities q;
  double self_difference;    ///< 20000 vs 40000 steps
  double adams_difference;   ///< CVODE Adams, rtol 1e-13
  double bdf_difference;     ///< CVODE BDF, rtol 1e-13
};

template <DampingLaw Law> NumericalReference numerical_reference(const ConvergenceProblem& p) {
  const double tau_c = regularized_contact_tau<Law>(p);
  NumericalReference r;
  r.q = measure_regularized<ClassicalRk4, Law>(p, tau_c / 40000).q;
  auto largest = [&](const ImpactQuantities& other) {
    const auto e = relative_errors(p, other, r.q);
    return *std::max_element(e.begin(), e.end());
  };
  r.self_difference = largest(measure_regularized<ClassicalRk4, Law>(p, tau_c / 20000).q);
  r.adams_difference = largest(measure_cvode<Law>(p, CvodeMethod::adams, 1e-13).q);
  r.bdf_difference = largest(measure_cvode<Law>(p, CvodeMethod::bdf, 1e-13).q);
  return r;
}

// ---------------------------------------------------------------------------
// Series and observed orders.

/// The four positions of onset inside a step at which fixed-step runs are made; the
/// error at a step is the largest of the four, so an unlocated kink's error is not
/// flattered by a lucky alignment. (With located events the step is cut at onset and
/// the grid restarts there, so the phase does not matter; separation then falls where
/// tc/h puts it.)
inline constexpr std::array<double, 4> step_phases{0.1, 0.35, 0.6, 0.85};

/// The fixed step for N steps per contact: tc / (N + 1/2), so that separation falls
/// half a step after onset's position in its step (for the undamped law; near it for
/// the others). With tc / N, onset and separation would sit at the same position in
/// their steps and an unlocated contact time would be exact by coincidence.
inline double fixed_step_for(const ConvergenceProblem& p, long steps_per_contact) {
  return p.tc_scale_s / (static_cast<double>(steps_per_contact) + 0.5);
}

/// Fixed-step run at N steps per (undamped) contact time: errors are the largest over
/// the phases, the cost the mean.
template <class Method, DampingLaw Law>
std::pair<std::array<double, quantity_count>, Measurement> worst_over_phases(
    const ConvergenceProblem& p, const ImpactQuantities& ref, long steps_per_contact, bool locate_events,
    double min_timing_s = 0) {
  const double dt = fixed_step_for(p, steps_per_contact);
  std::array<double, quantity_count> worst{};
  Measurement mean;
  for (double phase : step_phases) {
    const Measurement m = measure_fixed_step<Method, Law>(p, dt, locate_events, phase * dt, min_timing_s);
    const auto err = relative_errors(p, m.q, ref);
    for (int q = 0; q < quantity_count; ++q) worst[q] = std::max(worst[q], err[q]);
    mean.rhs_evaluations += m.rhs_evaluations / static_cast<long>(step_phases.size());
    mean.cpu_time_s += m.cpu_time_s / static_cast<double>(step_phases.size());
  }
  return {worst, mean};
}

/// Observed order between two resolutions: log(e_coarse/e_fine) / log(s_coarse/s_fine)
/// (= log2 of the error ratio when the step halves). NaN where either error is at or
/// below `floor` (roundoff or reference accuracy: the ratio means nothing there).
inline double observed_order(double step_coarse, double err_coarse, double step_fine, double err_fine,
                             double floor) {
  if (!(err_coarse > floor && err_fine > floor)) return std::nan("");
  return std::log(err_coarse / err_fine) / std::log(step_coarse / step_fine);
}

/// Least-squares slope of log(error) against log(step): the order over a sweep.
inline double fitted_slope(const std::vector<double>& steps, const std::vector<double>& errors) {
  const double n = static_cast<double>(steps.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) mx += std::log(steps[i]) / n, my += std::log(errors[i]) / n;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const double dx = std::log(steps[i]) - mx;
    sxy += dx * (std::log(errors[i]) - my), sxx += dx * dx;
  }
  return sxy / sxx;
}

}  // namespace hertzdash::convergence
