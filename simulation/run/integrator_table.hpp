#pragma once
// The integrator table: one row per integrator, read by the simulator (which integrator
// runs a given impact, and how it is called), the settings' validation, the run
// description, the step-resolution advice, the CLI (spellings, help) and the benchmark.
//
// Adding an integrator: write it in integrators/ (it knows only ode/), add its
// enumerator to IntegratorKind (simulation/run/solver_settings.hpp) and one row here: a
// struct with its traits (a method of method_table in physical or regularised variables)
// and a static integrate() that calls it, listed in IntegratorTable; a new method is one
// more entry of method_table. Nothing else changes.
//
// A row's integrate(sys, y, t0, t1, settings, workspace, observer) integrates any
// OdeSystem: the drop test in physical variables (model/drop_test.hpp) for rows with
// Variables::physical, the contact in regularising variables
// (model/contact_system.hpp, simulation/run/regularized_impact.hpp) for
// Variables::regularized.
#include "hertzdash/integrators/cvode_integrator.hpp"
#include "hertzdash/integrators/dormand_prince.hpp"
#include "hertzdash/integrators/explicit_euler.hpp"
#include "hertzdash/integrators/extrapolation.hpp"
#include "hertzdash/integrators/fixed_step.hpp"
#include "hertzdash/integrators/rk4.hpp"
#include "hertzdash/integrators/taylor.hpp"
#include "hertzdash/ode/ode_system.hpp"
#include "hertzdash/simulation/run/solver_settings.hpp"

#include <array>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

namespace hertzdash {

enum class StepControl {
  fixed_step,  ///< reads dt_s and locate_events
  adaptive,    ///< reads rtol, atol and (physical variables only) max_step_s
};

enum class Variables {
  physical,     ///< the whole drop in (x, x'), model/drop_test.hpp
  regularized,  ///< the fall in closed form, the contact in u = x^{1/2} (simulation/run/regularized_impact.hpp)
};

/// The numerical method of a row, whatever the variables it runs in (Variables): the method
/// decides the step control and which settings apply (cvode's --cvode-method, for one).
enum class IntegratorMethod { euler, rk4, cvode, dopri5, gbs8, taylor };

/// What a method is, apart from the variables it integrates.
struct MethodTraits {
  IntegratorMethod method;
  std::string_view name;
  StepControl step_control;
};

inline constexpr std::array<MethodTraits, 6> method_table{{
    {IntegratorMethod::euler, "euler", StepControl::fixed_step},
    {IntegratorMethod::rk4, "rk4", StepControl::fixed_step},
    {IntegratorMethod::cvode, "cvode", StepControl::adaptive},
    {IntegratorMethod::dopri5, "dopri5", StepControl::adaptive},
    {IntegratorMethod::gbs8, "gbs8", StepControl::adaptive},
    {IntegratorMethod::taylor, "taylor", StepControl::adaptive},
}};

static_assert(
    [] {
      for (std::size_t i = 0; i < method_table.size(); ++i)
        if (static_cast<std::size_t>(method_table[i].method) != i) return false;
      return true;
    }(),
    "method_table is indexed by IntegratorMethod");

constexpr const MethodTraits& method_traits(IntegratorMethod m) { return method_table[static_cast<std::size_t>(m)]; }

/// What the table says of one integrator: a method in a formulation (physical or regularised
/// variables).
struct IntegratorTraits {
  IntegratorKind kind;
  std::string_view name;  ///< the CLI spelling
  IntegratorMethod method;
  Variables variables;
  StepControl step_control = method_traits(method).step_control;  ///< the method's
  /// Runs only laws whose force is a polynomial in x^{1/2} (RootPolynomialLaw); others
  /// run `fallback_for_other_laws`.
  bool needs_root_polynomial = false;
  IntegratorKind fallback_for_other_laws = kind;
  /// The same method in the physical variables: what runs where the regularised contact
  /// does not apply (the tension clamp, whose contact ends where the force reaches zero, an
  /// event the regularised contact does not have; the elastic rod, a system of many bodies).
  IntegratorKind physical_counterpart = kind;
  /// Steps per contact time a fixed-step method needs for the step-resolution target
  /// (simulation/run/step_resolution.hpp), with and without event location; 0 if adaptive.
  long min_steps_per_contact_located = 0, min_steps_per_contact_unlocated = 0;
};

/// The CVODE integrators of a simulator, one per system size (and Jacobian band), created
/// on first use and reused for every later impact (CVodeReInit), so a sweep pays the set-up once.
class IntegratorWorkspace {
 public:
  CvodeIntegrator& cvode(int dimension, int event_count, const CvodeOptions& options) {
    for (const Entry& e : cvode_)
      if (e.dimension == dimension && e.event_count == event_count && e.band_half_width == options.band_half_width)
        return *e.integrator;
    cvode_.push_back({dimension, event_count, options.band_half_width,
                      std::make_unique<CvodeIntegrator>(dimension, event_count, options)});
    return *cvode_.back().integrator;
  }

 private:
  struct Entry {
    int dimension, event_count, band_half_width;
    std::unique_ptr<CvodeIntegrator> integrator;
  };
  std::vector<Entry> cvode_;
};

/// A system that is smooth where its events restart or land a step (the regularised
/// contact of a RootPolynomialLaw) declares `static constexpr bool smooth_at_events = true`;
/// dopri5 then trusts its embedded error estimate there.
template <class S>
constexpr bool smooth_at_events() {
  if constexpr (requires { S::smooth_at_events; }) return S::smooth_at_events;
  else return false;
}

namespace integrator_rows {

/// The traits of a row in the regularising variables that runs only the laws whose force is a
/// polynomial in x^{1/2}, the others falling back to dopri5-regularized; dopri5 in the physical ones.
constexpr IntegratorTraits root_polynomial_row(IntegratorKind kind, std::string_view name, IntegratorMethod method) {
  return {.kind = kind, .name = name, .method = method, .variables = Variables::regularized,
          .needs_root_polynomial = true, .fallback_for_other_laws = IntegratorKind::dopri5_regularized,
          .physical_counterpart = IntegratorKind::dopri5};
}

/// How the fixed-step rows call them: Method (explicit Euler, classical RK4) with events
/// located by regula falsi or handled at the end of the crossing step.
template <class Method>
struct CallFixedStep {
  template <OdeSystem S, class Observer>
  static IntegrationStats integrate(S& sys, typename S::State& y, double t0, double t1, const SolverSettings& s,
                                    IntegratorWorkspace&, Observer& observer) {
    return integrate_fixed_step<Method>(sys, y, t0, t1, FixedStepOptions{s.dt_s, s.locate_events}, observer);
  }
};

struct Euler : CallFixedStep<ExplicitEuler> {
  static constexpr IntegratorTraits traits{.kind = IntegratorKind::euler, .name = "euler",
                                           .method = IntegratorMethod::euler, .variables = Variables::physical,
                                           .min_steps_per_contact_located = 10240,
                                           .min_steps_per_contact_unlocated = 10240};
};

struct Rk4 : CallFixedStep<ClassicalRk4> {
  static constexpr IntegratorTraits traits{.kind = IntegratorKind::rk4, .name = "rk4",
                                           .method = IntegratorMethod::rk4, .variables = Variables::physical,
                                           .min_steps_per_contact_located = 10,
                                           .min_steps_per_contact_unlocated = 1280};
};

/// How the CVODE rows call it: SUNDIALS CVODE (Adams or BDF) with its root finder,
/// memory reused across impacts.
struct CallCvode {
  template <OdeSystem S, class Observer>
  static IntegrationStats integrate(S& sys, typename S::State& y, double t0, double t1, const SolverSettings& s,
                                    IntegratorWorkspace& w, Observer& observer) {
    CvodeOptions o;
    o.method = s.cvode_method;
    o.rtol = s.rtol;
    o.atol = s.atol;
    o.max_step = s.max_step_s;
    o.band_half_width = jacobian_half_bandwidth<S>();
    return w.cvode(static_cast<int>(y.size()), S::event_count, o).integrate(sys, y, t0, t1, observer);
  }
};

/// How the dopri5 rows call it: adaptive Dormand-Prince 5(4) with events landed on, with
/// singular-point checks unless the system is smooth at its events.
struct CallDopri5 {
  template <OdeSystem S, class Observer>
  static IntegrationStats integrate(S& sys, typename S::State& y, double t0, double t1, const SolverSettings& s,
                                    IntegratorWorkspace&, Observer& observer) {
    const DormandPrinceOptions o{
        .rtol = s.rtol, .atol = s.atol, .max_step = s.max_step_s, .singular_points = !smooth_at_events<S>()};
    return integrate_dormand_prince(sys, y, t0, t1, o, observer);
  }
};

struct Cvode : CallCvode {
  static constexpr IntegratorTraits traits{.kind = IntegratorKind::cvode, .name = "cvode",
                                           .method = IntegratorMethod::cvode, .variables = Variables::physical};
};

struct Dopri5 : CallDopri5 {
  static constexpr IntegratorTraits traits{.kind = IntegratorKind::dopri5, .name = "dopri5",
                                           .method = IntegratorMethod::dopri5, .variables = Variables::physical};
};

struct Dopri5Regularized : CallDopri5 {
  static constexpr IntegratorTraits traits{.kind = IntegratorKind::dopri5_regularized, .name = "dopri5-regularized",
                                           .method = IntegratorMethod::dopri5,
                                           .variables = Variables::regularized,
                                           .physical_counterpart = IntegratorKind::dopri5};
};

struct CvodeRegularized : CallCvode {
  static constexpr IntegratorTraits traits{.kind = IntegratorKind::cvode_regularized, .name = "cvode-regularized",
                                           .method = IntegratorMethod::cvode,
                                           .variables = Variables::regularized,
                                           .physical_counterpart = IntegratorKind::cvode};
};

/// Gragg-Bulirsch-Stoer extrapolation of order 8 on the regularised contact: the fastest
/// path, for laws smooth through onset and separation in u = x^{1/2}.
struct Gbs8Regularized {
  static constexpr IntegratorTraits traits =
      root_polynomial_row(IntegratorKind::gbs8_regularized, "gbs8-regularized", IntegratorMethod::gbs8);
  template <OdeSystem S, class Observer>
  static IntegrationStats integrate(S& sys, typename S::State& y, double t0, double t1, const SolverSettings& s,
                                    IntegratorWorkspace&, Observer& observer) {
    return integrate_extrapolation(sys, y, t0, t1, ExtrapolationOptions{.rtol = s.rtol, .atol = s.atol}, observer);
  }
};

/// Taylor series (orders from the tolerance, coefficients by recurrence from the law's
/// force_of_root) on the regularised contact, events located on the series: for laws
/// whose force is a polynomial in u = x^{1/2}.
struct TaylorRegularized {
  static constexpr IntegratorTraits traits =
      root_polynomial_row(IntegratorKind::taylor_regularized, "taylor-regularized", IntegratorMethod::taylor);
  template <OdeSystem S, class Observer>
  static IntegrationStats integrate(S& sys, typename S::State& y, double t0, double t1, const SolverSettings& s,
                                    IntegratorWorkspace&, Observer& observer) {
    if constexpr (PolynomialOdeSystem<S>) {
      return integrate_taylor(sys, y, t0, t1, TaylorOptions{.rtol = s.rtol, .atol = s.atol}, observer);
    } else {
      // Instantiated for every law by the run-time dispatch (with_integrator_row), never
      // reached: integrator_used sends a law without the polynomial form to the fall-back.
      throw std::logic_error("taylor-regularized needs a system with a polynomial right-hand side");
    }
  }
};

}  // namespace integrator_rows

/// The table, in the order of IntegratorKind.
using IntegratorTable = std::tuple<
    integrator_rows::Euler,
    integrator_rows::Rk4,
    integrator_rows::Cvode,
    integrator_rows::Dopri5,
    integrator_rows::Dopri5Regularized,
    integrator_rows::CvodeRegularized,
    integrator_rows::Gbs8Regularized,
    integrator_rows::TaylorRegularized>;

/// Every integrator, in table order.
inline constexpr auto all_integrator_kinds = []<class... Row>(std::type_identity<std::tuple<Row...>>) {
  return std::array<IntegratorKind, sizeof...(Row)>{Row::traits.kind...};
}(std::type_identity<IntegratorTable>{});

/// Every row's traits, in table order.
inline constexpr auto all_integrator_traits = []<class... Row>(std::type_identity<std::tuple<Row...>>) {
  return std::array<IntegratorTraits, sizeof...(Row)>{Row::traits...};
}(std::type_identity<IntegratorTable>{});

/// The row of `kind`.
constexpr const IntegratorTraits& integrator_traits(IntegratorKind kind) {
  return all_integrator_traits[static_cast<std::size_t>(kind)];
}
static_assert([] {
  for (std::size_t i = 0; i < all_integrator_kinds.size(); ++i)
    if (static_cast<std::size_t>(all_integrator_kinds[i]) != i) return false;
  return true;
}(), "IntegratorTable lists the rows in the order of IntegratorKind");
static_assert([] {
  for (const IntegratorTraits& row : all_integrator_traits) {
    const IntegratorTraits& clamp = all_integrator_traits[static_cast<std::size_t>(row.physical_counterpart)];
    const IntegratorTraits& other = all_integrator_traits[static_cast<std::size_t>(row.fallback_for_other_laws)];
    // The tension clamp needs the physical variables (their force-zero event); a
    // physical row runs itself.
    if (clamp.variables != Variables::physical) return false;
    if (row.variables == Variables::physical && row.physical_counterpart != row.kind) return false;
    // A row that needs a root-polynomial law falls back to one that does not, and only then.
    if (row.needs_root_polynomial == (row.fallback_for_other_laws == row.kind) || other.needs_root_polynomial)
      return false;
  }
  return true;
}(), "every fall-back of the integrator table ends on a row that runs: physical variables under the tension "
     "clamp, any law otherwise");

/// Call f(std::type_identity<Row>{}) with the row of `kind`, so the caller can
/// instantiate its code for that integrator.
template <class F>
void with_integrator_row(IntegratorKind kind, F&& f) {
  [&]<class... Row>(std::type_identity<std::tuple<Row...>>) {
    static_cast<void>(((kind == Row::traits.kind && (f(std::type_identity<Row>{}), true)) || ...));
  }(std::type_identity<IntegratorTable>{});
}

const char* to_string(IntegratorKind k);
/// The CLI spellings of every integrator (or of those whose row satisfies `which`),
/// comma-separated ("euler, rk4, ...").
std::string integrator_names(bool (*which)(const IntegratorTraits&) = nullptr);
/// The rows in regularising variables: those that take a time-dependent contact (the shaker's
/// and the two walls' moving wall is a forcing of the regularised contact only).
inline std::string regularising_integrator_names() {
  return integrator_names([](const IntegratorTraits& t) { return t.variables == Variables::regularized; });
}
/// The integrator spelled `name`; throws InvalidParameter(option, name, "one of: ...").
IntegratorKind parse_integrator(std::string_view name, const std::string& option = "integrator");

/// What an impact asks of an integrator beyond its law's force.
struct ImpactNeeds {
  bool tension_clamp = false;        ///< --no-tension: contact ends where the force reaches zero
  bool elastic_rod = false;          ///< --rod-model elastic: a many-body system in physical variables
  bool root_polynomial_law = true;   ///< the law declares force_of_root (RootPolynomialLaw)
};

/// Which integrator runs an impact asked of `asked`: the row's physical counterpart for the
/// tension clamp and the elastic rod, its fall-back for a law that is not a
/// RootPolynomialLaw. `why` (if given) receives the reason when it differs from `asked`,
/// empty otherwise.
IntegratorKind integrator_used(IntegratorKind asked, const ImpactNeeds& needs, std::string* why = nullptr);

}  // namespace hertzdash
