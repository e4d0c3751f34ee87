#include "cli/setup_options.hpp"

#include "model/damping/registry.hpp"
#include "model/invalid_parameter.hpp"

#include <fmt/format.h>

#include <iostream>

namespace hertzdash::cli {

void SetupOptions::add_to(CLI::App& app) {
  damping_ = std::string(default_damping_law);
  app.add_option("--rod", rod_, "Rod of Tables 1-3: steel, duralumin-a, duralumin-b, duralumin-c")->capture_default_str();
  app.add_option("--height", height_m_, "Drop height h [m], free fall from rest")->capture_default_str();
  impact_velocity_opt_ = app.add_option("--impact-velocity", impact_velocity_mps_,
                                        "Approach speed at contact onset [m/s]; overrides --height");
  mass_opt_ = app.add_option("--mass", mass_kg_, "Rod mass [kg] (default: Table 1)");
  restitution_opt_ = app.add_option("--restitution", restitution_,
                                    "Input coefficient of restitution e in (0,1] (default: Table 2; 1 = undamped)");
  ball_E_opt_ = app.add_option("--ball-E", ball_E_, "Hemisphere Young's modulus [Pa] (default: 2.0e9, assumed)");
  ball_nu_opt_ = app.add_option("--ball-nu", ball_nu_, "Hemisphere Poisson ratio (default: 0.40, assumed)");
  ball_radius_opt_ = app.add_option("--ball-radius", ball_radius_, "Hemisphere radius R [m] (default: 0.0127)");
  rod_E_opt_ = app.add_option("--rod-E", rod_E_, "Rod Young's modulus [Pa]; inf for a rigid flat (default: Table 3)");
  rod_nu_opt_ = app.add_option("--rod-nu", rod_nu_, "Rod Poisson ratio (default: 0.30 steel, 0.33 duralumin, assumed)");
  gravity_opt_ = app.add_option("--gravity", gravity_, "Gravity g [m/s^2], 0 allowed (default: 9.80665)");
  app.add_flag("--no-tension", no_tension_, "Clamp the contact force at >= 0; contact ends where it reaches zero");
  app.add_option("--zeta", zeta_, "Damping ratio from e: paper (eq. 6) or exact (linear oscillator)")
      ->capture_default_str();
  omega_n_opt_ = app.add_option("--omega-n", omega_n_,
                                "Natural frequency assumption of the paper's law (hongo only): paper (eq. 11), "
                                "impact-energy, rebound-energy, self-consistent, contact-time (both iterated to a "
                                "fixed point), as-printed (the eq. 9 erratum)")
                     ->capture_default_str();
  app.add_option("--damping", damping_, "Damping law (see `hertzdash models`): " + registered_law_names())
      ->capture_default_str();
}

DropTestSetup SetupOptions::resolve(const PaperParameters& paper) const {
  DropTestSetup s = paper_setup(paper, rod_, height_m_);
  if (impact_velocity_opt_->count()) s.impact_velocity_mps = impact_velocity_mps_;
  if (mass_opt_->count()) s.mass_kg = mass_kg_;
  if (restitution_opt_->count()) s.restitution = restitution_;
  if (ball_E_opt_->count()) s.ball.E_Pa = ball_E_;
  if (ball_nu_opt_->count()) s.ball.nu = ball_nu_;
  if (ball_radius_opt_->count()) s.ball_radius_m = ball_radius_;
  if (rod_E_opt_->count()) s.rod.E_Pa = rod_E_;
  if (rod_nu_opt_->count()) s.rod.nu = rod_nu_;
  if (gravity_opt_->count()) s.gravity_mps2 = gravity_;
  s.no_tension = no_tension_;
  if (zeta_ == "paper") s.damping.zeta_form = ZetaForm::paper;
  else if (zeta_ == "exact") s.damping.zeta_form = ZetaForm::exact;
  else throw InvalidParameter("--zeta", zeta_, "one of: paper, exact");
  s.damping.omega_n = parse_omega_n_variant(omega_n_);
  validate(s);
  with_damping_law(damping_, [](auto) {});  // rejects an unknown law before any work
  if (omega_n_opt_->count() && damping_ != HongoPaper::info.name)
    throw InvalidParameter("--omega-n", omega_n_,
                           "given only with --damping " + std::string(HongoPaper::info.name) +
                               " (the omega_n assumption belongs to the paper's law; --damping is " + damping_ + ")");
  return s;
}

IntegratorKind report_integrator_used(const SolverSettings& solver, const DropTestSetup& setup, const std::string& law) {
  std::string why;
  const IntegratorKind used = integrator_used(solver, setup, law, &why);
  if (used != solver.integrator)
    std::cerr << fmt::format("hertzdash: note: --integrator {} fell back to {}: {}\n", to_string(solver.integrator),
                             to_string(used), why);
  return used;
}

void SolverOptions::add_to(CLI::App& app) {
  // Which integrators read which setting: the integrator table.
  const std::string fixed = integrator_names([](const IntegratorTraits& r) { return r.step_control == StepControl::fixed_step; });
  const std::string adaptive = integrator_names([](const IntegratorTraits& r) { return r.step_control == StepControl::adaptive; });
  const std::string timed = integrator_names([](const IntegratorTraits& r) {
    return r.step_control == StepControl::adaptive && r.variables == Variables::physical;
  });
  const std::string cvode = integrator_names([](const IntegratorTraits& r) { return r.reads_cvode_method; });
  app.add_option("--integrator", integrator_, "One of: " + integrator_names())->capture_default_str();
  app.add_option("--dt", dt_s_, "Fixed step [s] (" + fixed + ")")->capture_default_str();
  app.add_flag("--no-event-location", no_event_location_,
               "Handle events at the end of the step that crosses them (" + fixed + "; convergence studies)");
  app.add_option("--rtol", rtol_, "Relative tolerance (" + adaptive + ")")->capture_default_str();
  app.add_option("--atol", atol_, "Absolute tolerance [m, m/s] (" + adaptive + ")")->capture_default_str();
  app.add_option("--cvode-method", cvode_method_, "CVODE method: adams or bdf (" + cvode + ")")->capture_default_str();
  app.add_option("--max-step", max_step_s_, "Largest step [s]; 0 = no limit (" + timed + ")")->capture_default_str();
}

SolverSettings SolverOptions::resolve() const {
  SolverSettings s;
  s.integrator = parse_integrator(integrator_);
  s.dt_s = dt_s_;
  s.locate_events = !no_event_location_;
  s.rtol = rtol_;
  s.atol = atol_;
  s.max_step_s = max_step_s_;
  if (cvode_method_ == "adams") s.cvode_method = CvodeMethod::adams;
  else if (cvode_method_ == "bdf") s.cvode_method = CvodeMethod::bdf;
  else throw InvalidParameter("--cvode-method", cvode_method_, "one of: adams, bdf");
  validate(s);
  return s;
}

}  // namespace hertzdash::cli
