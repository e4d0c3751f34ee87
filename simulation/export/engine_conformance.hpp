#pragma once
// `hertzdash conformance --engine E` (docs/engines.md): every contact model of an installed
// engine run on its decks at three approach speeds, a quarter of, at and four times the
// reference speed at which the law is calibrated to the asked e, and at N and N/2 steps per
// contact, beside hertzdash's prediction for the law the model equals: "e asked" against "e the
// engine gives", and the engine's error falling with its time step. Where the engine's damping
// input is itself a restitution, also what the engine gives when the asked e is typed in as it.
#include "hertzdash/simulation/export/engine_run.hpp"

#include <cmath>
#include <vector>

namespace hertzdash {

struct ConformanceRow {
  std::string_view engine_model;     ///< the engine's model (EngineModel::key)
  std::string_view hertzdash_law;    ///< the law it equals
  EngineImpactKind impact = EngineImpactKind::sphere_sphere;
  double speed_mps = 0;              ///< approach speed (relative for the pair)
  double e_asked = 0;                ///< the e the law was calibrated to, at the reference speed
  EngineCoefficient engine_input{};  ///< the engine's damping input of the deck
  EngineImpactResult hertzdash;      ///< the law's impact at this speed
  EngineImpactResult engine;         ///< the engine's, at steps_per_contact
  double e_engine_half_steps = 0;    ///< the engine's e at steps_per_contact / 2
  /// log2 of the e error at N/2 over that at N: the error's order in the time step.
  double observed_order = 0;
  double timestep_s = 0;             ///< the deck's at steps_per_contact
  /// For a model whose damping input is a restitution (EngineModel::restitution_given_input):
  /// the engine's e with e_asked typed in as that input, and what the law predicts for it; NaN
  /// for the others.
  double e_engine_given_e_asked = NAN, e_hertzdash_given_e_asked = NAN;
};

/// Runs the engine on every model it has (simulation/export/engine_models.hpp), the contact of
/// `setup` calibrated per model's law at its approach speed; scratch decks in a temporary
/// directory, removed. Throws what make_engine_contact and run_engine_deck throw.
std::vector<ConformanceRow> engine_conformance(Engine engine, const DropTestSetup& setup, int steps_per_contact);

}  // namespace hertzdash
