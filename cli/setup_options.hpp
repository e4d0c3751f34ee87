#pragma once
// Command-line options shared by the subcommands: the physical set-up (paper
// defaults with overrides), the damping law, and the solver. Parsing only: the
// values are validated by the library (validate()), which names the option.
#include "model/drop_test_setup.hpp"
#include "simulation/paper_parameters.hpp"
#include "simulation/impact_simulator.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace hertzdash::cli {

/// --rod, --height, --impact-velocity, --mass, --restitution, --ball-E, --ball-nu,
/// --ball-radius, --rod-E, --rod-nu, --gravity, --no-tension, --zeta, --omega-n, --damping.
class SetupOptions {
 public:
  void add_to(CLI::App& app);
  /// The paper's set-up for the chosen rod, with every given override applied; validated.
  DropTestSetup resolve(const PaperParameters& paper) const;
  const std::string& damping() const { return damping_; }

 private:
  std::string rod_ = "steel";
  std::string damping_;
  std::string zeta_ = "paper";
  std::string omega_n_ = "paper";
  double height_m_ = 0.02;
  double impact_velocity_mps_ = 0, mass_kg_ = 0, restitution_ = 0, ball_E_ = 0, ball_nu_ = 0, ball_radius_ = 0,
         rod_E_ = 0, rod_nu_ = 0, gravity_ = 0;
  bool no_tension_ = false;
  CLI::Option *impact_velocity_opt_ = nullptr, *mass_opt_ = nullptr, *restitution_opt_ = nullptr,
              *ball_E_opt_ = nullptr, *ball_nu_opt_ = nullptr, *ball_radius_opt_ = nullptr, *rod_E_opt_ = nullptr,
              *rod_nu_opt_ = nullptr, *gravity_opt_ = nullptr, *omega_n_opt_ = nullptr;
};

/// --integrator, --dt, --no-event-location, --rtol, --atol, --cvode-method, --max-step.
/// The integrator that runs `law` on `setup` (the integrator table's fall-backs); when it is
/// not the one asked for, says so and why on stderr.
IntegratorKind report_integrator_used(const SolverSettings& solver, const DropTestSetup& setup, const std::string& law);

class SolverOptions {
 public:
  void add_to(CLI::App& app);
  SolverSettings resolve() const;  ///< validated

 private:
  std::string integrator_ = "cvode";
  std::string cvode_method_ = "adams";
  double dt_s_ = 1e-6;
  double rtol_ = 1e-8, atol_ = 1e-12, max_step_s_ = 0;
  bool no_event_location_ = false;
};

}  // namespace hertzdash::cli
