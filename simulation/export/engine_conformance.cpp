// The engines' conformance with the laws they equal (simulation/export/engine_conformance.hpp).
#include "hertzdash/simulation/export/engine_conformance.hpp"

#include "hertzdash/io/temporary_directory.hpp"

#include <cmath>
#include <string>

namespace hertzdash {

std::vector<ConformanceRow> engine_conformance(Engine engine, const DropTestSetup& setup, int steps_per_contact) {
  const TemporaryDirectory dir("engine decks");
  std::vector<ConformanceRow> rows;
  const std::string extension(engine_program(engine).deck_extension);
  for (const EngineModel& model : engine_models()) {
    if (model.engine != engine) continue;
    const EngineContact calibrated = make_engine_contact(setup, std::string(model.law), model.tension_clamped);
    for (double factor : {0.25, 1.0, 4.0}) {
      const EngineContact c = at_speed(calibrated, factor * calibrated.speed_mps);
      for (EngineImpactKind k : {EngineImpactKind::sphere_sphere, EngineImpactKind::sphere_wall}) {
        ConformanceRow row;
        row.engine_model = model.key;
        row.hertzdash_law = model.law;
        row.impact = k;
        row.speed_mps = c.speed_mps;
        row.e_asked = c.restitution;
        row.engine_input = model.damping_input(c, k);
        row.hertzdash = c.predicted(k);
        const EngineDeck fine = engine_deck(model, c, k, steps_per_contact, "");
        const EngineDeck coarse = engine_deck(model, c, k, steps_per_contact / 2, "");
        row.engine = run_engine_deck(engine, fine, dir.path, "fine" + extension, c.speed_mps);
        row.e_engine_half_steps = run_engine_deck(engine, coarse, dir.path, "coarse" + extension, c.speed_mps).restitution;
        row.observed_order = std::log2(std::abs(row.e_engine_half_steps - row.hertzdash.restitution) /
                                       std::abs(row.engine.restitution - row.hertzdash.restitution));
        row.timestep_s = fine.timestep_s;
        if (model.restitution_given_input) {
          // The contact whose deck carries e_asked as the engine's input: the law at the e it then gives.
          EngineContact typed = c;
          typed.restitution = model.restitution_given_input(c.restitution);
          row.e_hertzdash_given_e_asked = typed.restitution;
          row.e_engine_given_e_asked =
              run_engine_deck(engine, engine_deck(model, typed, k, steps_per_contact, ""), dir.path, "typed" + extension, c.speed_mps)
                  .restitution;
        }
        rows.push_back(row);
      }
    }
  }
  return rows;
}

}  // namespace hertzdash
