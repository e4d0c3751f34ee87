#pragma once
// The rig `shaker` (simulation/shaker/shaker.hpp, docs/shaker.md): a body bouncing on a
// harmonically vibrating wall s(t) = A sin(2 pi f t), the drop test's body, contact, law and e,
// soft or instantaneous impacts, exact flights. Its inputs are model/shaker_parameters.hpp's.
#include "hertzdash/simulation/rigs/rig.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"

namespace hertzdash {

/// The integrator `shaker` and `walls` run their soft contacts with unless told otherwise: their
/// wall motion is a forcing of the regularised contact only (simulation/shaker/shaker_contact.hpp).
inline constexpr const char* shaker_default_integrator = "gbs8-regularized";

/// What `integrator` means in `shaker` and `walls`.
inline constexpr RigOptionNote shaker_integrator_note{
    "integrator", "Integrator of the soft contacts, one in regularising variables (docs/shaker.md): dopri5-regularized, "
                  "cvode-regularized, gbs8-regularized, taylor-regularized (default: gbs8-regularized)"};

/// A shaker run: its resolved set-up, law, solver and options, its inputs and its outcome.
struct ShakerCommandRun {
  DropTestSetup setup;
  std::string law;
  SolverSettings solver;
  ShakerOptions options;
  Parameters inputs;  ///< describe_run() and the shaker's options
  ShakerRun run;
};

/// Resolve and validate, without running (`run` left empty). InvalidParameter for bad options:
/// `amplitude` with `gamma`, a non-integer count, a contact option with instantaneous impacts.
ShakerCommandRun resolve_shaker_command(const RunOptions& options, const PaperParameters& paper,
                                        const RigInputs& inputs);

/// The rig `shaker`: inputs frequency, amplitude or gamma, impacts, transient, impact-model,
/// start-phase and every run option but impact-velocity (`height` is the start's height above the
/// wall's mean position); results gamma, frequency_Hz, amplitude_m, impact_model, damping,
/// integrator_used (soft), period, impacts_per_period, e_effective, sticking_episodes, impacts_run,
/// work; one table row per kept impact: impact_time_s, impact_phase, impact_speed_mps,
/// rebound_speed_mps, contact_time_s, peak_force_N.
const Rig& shaker_rig();

}  // namespace hertzdash
