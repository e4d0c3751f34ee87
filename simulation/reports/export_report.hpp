#pragma once
// `hertzdash export --engine E`: the decks of a contact for a discrete-element engine
// (simulation/export/engine_models.hpp), with what hertzdash predicts each impact gives; its text
// and JSON for every front end (docs/engines.md, docs/json-output.md).
#include "hertzdash/io/provenance.hpp"
#include "hertzdash/simulation/export/engine_conformance.hpp"
#include "hertzdash/simulation/export/engine_models.hpp"
#include "hertzdash/simulation/options/run_options.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace hertzdash {

/// `steps-per-contact` of `command` (export, conformance): the given value or its declared
/// default, within its declared range; InvalidParameter naming it otherwise.
int steps_per_contact_option(std::string_view command, std::optional<double> given);

/// The files `hertzdash export` writes into its directory: the two decks, then the lines to paste
/// (sphere_sphere.in, sphere_wall.in, contact_lines.in; .py for YADE).
std::array<std::string, 3> engine_deck_files(Engine engine);

struct EngineExport {
  const EngineModel* model = nullptr;
  EngineContact contact;
  int steps_per_contact = 0;
  EngineDeck pair_deck, wall_deck;
  std::string contact_lines;  ///< the lines to paste, with their provenance header
  /// The files to write into the output directory (engine_deck_files): (name, content).
  std::vector<std::pair<std::string, std::string>> files() const;
};

/// Resolve the run options, find the engine's model equal to the law, calibrate, predict and
/// write the decks' text. Throws InvalidParameter naming the option at fault.
EngineExport export_engine_decks(const RunOptions& options, const PaperParameters& paper, Engine engine,
                                 const std::string& model_key, int steps_per_contact);

std::string export_text(const EngineExport& e);
nlohmann::ordered_json to_json(const EngineExport& e);

/// `hertzdash conformance --engine E`: every model of the engine against the law it equals.
struct EngineConformance {
  Engine engine = Engine::lammps;
  double reference_speed_mps = 0;  ///< where each law is calibrated to the asked e
  int steps_per_contact = 0;
  std::vector<ConformanceRow> rows;
};

/// Resolve the run options (the bodies, e and the reference speed; `damping` is refused: every
/// model runs with the law it equals) and run the engine.
EngineConformance run_engine_conformance(const RunOptions& options, const PaperParameters& paper, Engine engine,
                                         int steps_per_contact);
std::string conformance_text(const EngineConformance& c);
nlohmann::ordered_json to_json(const EngineConformance& c);

}  // namespace hertzdash
