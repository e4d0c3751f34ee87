#pragma once
// Each subcommand registers itself on the app; main() lists the registrations.
#include "hertzdash/simulation/rigs/rig.hpp"

#include <CLI/CLI.hpp>

#include <functional>

namespace hertzdash::cli {

/// A registered subcommand and what it runs once its options are parsed
/// (returns the exit code; throws InvalidParameter for bad input).
struct Command {
  CLI::App* subcommand;
  std::function<int()> run;
};

/// `hertzdash simulate`: one drop test, summary as text or JSON, optional trace CSV.
Command add_simulate_command(CLI::App& app);

/// `hertzdash models`: the registered damping laws with their citations.
Command add_models_command(CLI::App& app);

/// `hertzdash parameters`: every option from its declaration (docs/parameters.md).
Command add_parameters_command(CLI::App& app);

/// `hertzdash restitution`: a law's effective restitution (contact phase, no gravity), or calibration.
Command add_restitution_command(CLI::App& app);

/// `hertzdash bounce`: a drop and its bounces; restitution from impact intervals and velocities.
Command add_bounce_command(CLI::App& app);

/// `hertzdash fit`: parameters from a measured trace by weighted least squares.
Command add_fit_command(CLI::App& app);

/// `hertzdash RIG` for a registered rig (simulation/rigs/rig.hpp): `shaker`, `walls`, ...
Command add_rig_command(CLI::App& app, const Rig& rig);

/// `hertzdash orbit RIG`: a rig's periodic orbit and its Floquet multipliers.
Command add_orbit_command(CLI::App& app);

/// `hertzdash continue RIG`: the branches of a rig's periodic orbits in a parameter.
Command add_continue_command(CLI::App& app);

/// `hertzdash lyapunov RIG`: the Lyapunov exponents of a rig's attractor.
Command add_lyapunov_command(CLI::App& app);

/// `hertzdash basins RIG`: which attractor each start at a rig's section reaches.
Command add_basins_command(CLI::App& app);

/// `hertzdash export`: a contact's input decks for a discrete-element engine (docs/engines.md).
Command add_export_command(CLI::App& app);

/// `hertzdash conformance`: an installed engine's models against the laws they equal.
Command add_conformance_command(CLI::App& app);

/// `hertzdash sweep`: the runs of a case file, one CSV row each; threads, or MPI processes.
Command add_sweep_command(CLI::App& app);

}  // namespace hertzdash::cli
