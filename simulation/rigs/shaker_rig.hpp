#pragma once
// The rig `shaker` (simulation/shaker/shaker.hpp, docs/shaker.md): a body bouncing on a
// harmonically vibrating wall s(t) = A sin(2 pi f t), the drop test's body, contact, law and e,
// soft or instantaneous impacts, exact flights. Its inputs are model/shaker_parameters.hpp's.
#include "hertzdash/simulation/rigs/rig.hpp"
#include "hertzdash/simulation/run/integrator_table.hpp"
#include "hertzdash/simulation/shaker/shaker.hpp"

#include <fmt/format.h>

namespace hertzdash {

/// The integrator `shaker` and `walls` run their soft contacts with unless told otherwise: their
/// wall motion is a forcing of the regularised contact only (simulation/run/soft_contact.hpp).
inline constexpr const char* shaker_default_integrator = "gbs8-regularized";

/// What `integrator` means in `shaker` and `walls`.
inline constexpr RigOptionNote shaker_integrator_note{
    "integrator", "Integrator of the soft contacts, one in regularising variables (docs/shaker.md): dopri5-regularized, "
                  "cvode-regularized, gbs8-regularized, taylor-regularized (default: gbs8-regularized)"};

/// The per-impact table of a rig with one wall, the shaker's and the impact oscillator's.
inline constexpr RigColumnOf<SequenceImpact> one_wall_impact_table[] = {
    {{"impact_time_s", "s", "impact (contact onset) time from the start"}, [](const SequenceImpact& i) { return i.time_s; }},
    {{"impact_phase", "1", "phase of the drive (the wall's A sin(2 pi f t), the oscillator's F cos(2 pi f t)) in [0, 1)"},
     [](const SequenceImpact& i) { return i.phase; }},
    {{"impact_speed_mps", "m/s", "impact speed relative to the wall"},
     [](const SequenceImpact& i) { return i.impact_speed_mps; }},
    {{"rebound_speed_mps", "m/s", "rebound speed relative to the wall"},
     [](const SequenceImpact& i) { return i.rebound_speed_mps; }},
    {{"contact_time_s", "s", "contact duration (0: instantaneous)"}, [](const SequenceImpact& i) { return i.contact_time_s; }},
    {{"peak_force_N", "N", "largest contact force (0: instantaneous)"}, [](const SequenceImpact& i) { return i.peak_force_N; }},
};

/// What a rig on the impact-sequence driver reports besides its fields: the heading "[prefix]soft
/// impacts, damping law 'L', integrator I" or "[prefix]instantaneous impacts, e = E", its
/// warnings, end reason, work (soft impacts) and inputs. `Run` has setup, law, inputs and run.
template <class Run>
RigResult sequence_outcome(const Run& r, std::string_view prefix = "") {
  const bool soft = r.run.impact_model == ShakerImpactModel::soft;
  return {.heading = fmt::format("{}{} impacts{}", prefix, to_string(r.run.impact_model),
                                 soft ? fmt::format(", damping law '{}', integrator {}", r.law, to_string(r.run.integrator_used))
                                      : fmt::format(", e = {}", r.setup.restitution)),
          .scalars = {}, .rows = {}, .warnings = r.run.warnings, .end_reason = r.run.end_reason,
          .work = soft ? std::optional(r.run.work) : std::nullopt, .inputs = r.inputs};
}

/// Fields every rig on the impact-sequence driver reports, for its `Run` (with law and run).
template <class Run>
struct SequenceFields {
  static RigValue text(const char* t) { return std::string(t); }
  static constexpr RigFieldOf<Run> impact_model{{"impact_model", "", "soft or instantaneous", false, false, false},
                                                [](const Run& r) { return text(to_string(r.run.impact_model)); }};
  static constexpr RigFieldOf<Run> damping{{"damping", "", "the damping law", false, false, false},
                                           [](const Run& r) -> RigValue { return r.law; }};
  static constexpr RigFieldOf<Run> integrator_used{
      {"integrator_used", "", "the integrator of the soft contacts (soft impacts only)", false, false, false},
      [](const Run& r) {
        return r.run.impact_model == ShakerImpactModel::soft ? text(to_string(r.run.integrator_used)) : RigValue();
      }};
  static constexpr RigFieldOf<Run> impacts_per_period{
      {"impacts_per_period", "", "kept impacts per period"},
      [](const Run& r) -> RigValue { return long{r.run.pattern.impacts_per_period}; }};
  static constexpr RigFieldOf<Run> impacts_run{{"impacts_run", "", "impacts run, transient and kept", false, true},
                                               [](const Run& r) -> RigValue { return r.run.impacts_run; }};
};

/// A wall's amplitude A = gamma g / (2 pi f)^2 (model/wall_motion.hpp), refused naming `frequency`
/// where double precision cannot hold it (f = 1e300 Hz: A underflows; 1e-300 Hz: A overflows).
double amplitude_from_gamma(double gamma, double frequency_Hz, double gravity_mps2);

/// The rig `shaker`: inputs frequency, amplitude or gamma, impacts, transient, impact-model,
/// start-phase and every run option but impact-velocity (`height` is the start's height above the
/// wall's mean position); results gamma, frequency_Hz, amplitude_m, impact_model, damping,
/// integrator_used (soft), period, impacts_per_period, e_effective, sticking_episodes, impacts_run,
/// work; one table row per kept impact: impact_time_s, impact_phase, impact_speed_mps,
/// rebound_speed_mps, contact_time_s, peak_force_N.
const Rig& shaker_rig();

}  // namespace hertzdash
