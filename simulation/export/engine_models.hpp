#pragma once
// The contact models of the discrete-element engines hertzdash exports to (docs/engines.md), each
// registered once with the hertzdash law it equals and how the law's constants become the engine's,
// and the input deck of one impact for each. Checked by running the installed engines
// (tests/test_engine_export.cpp).
//
// LAMMPS (29 Sep 2021, Debian 12's `lammps`), pair_style granular with hertz/material, whose normal
// force is F = (4/3) E_eff a x + eta_n xdot, a = sqrt(R* x), so its spring is eq. (3) with K = (4/3) E* sqrt(R*):
//   - damping viscoelastic, eta_n = eta_n0 a m*: F = K x^{3/2} + eta_n0 m* sqrt(R*) x^{1/2} xdot, which is
//     kuwabara-kono's F = K (x^{3/2} + A x^{1/2} xdot) with eta_n0 = 4 E* A / (3 m*): equal;
//   - damping tsuji, eta_n = alpha(e_L) sqrt(m* k_n), k_n = (4/3) E_eff a, alpha the engine's polynomial
//     fit of Tsuji et al.'s graph: F = K x^{3/2} + alpha sqrt(K m*) x^{1/4} xdot, which is tsuji-dem's
//     form with sqrt(5) zeta = alpha: equal to tsuji-dem at the e whose exact zeta is alpha(e_L)/sqrt(5).
//     The deck takes the e_L that gives the law's e (tsuji_engine_restitution_input).
//   - damping mass_velocity, eta_n = eta_n0 m*: F = K x^{3/2} + eta_n0 m* xdot, lee-herrmann's
//     K x^{3/2} + m* gamma xdot with gamma = eta_n0: equal; damping velocity, eta_n = eta_n0: the
//     same law contact by contact, eta_n0 = gamma m* (the deck gives the wall its own value).
//   pair_style gran/hertz/history, F = sqrt(R* x) (kn x - m* gamma_n xdot): kuwabara-kono with
//   kn = (4/3) E* and gamma_n = 4 E* A / (3 m*), its wall's kn given to its fix.
//   The spheres' E_eff is E / (2 (1 - nu^2)) for one material (eq. 3). fix wall/gran takes its wall's
//   as E_wall / (2 (1 - nu_wall)) (measured: the peak force and contact time of the engine's sphere on
//   its wall give that E*; tests/test_engine_export.cpp), so the deck's wall modulus is 2 (1 - nu) E*.
// LIGGGHTS (3.8.0, Debian's `liggghts`), pair_style gran model hertz: the damping
//   gamma_n = -2 sqrt(5/6) beta sqrt(S_n m*), S_n = 2 E* sqrt(R* x), beta = ln e / sqrt(ln^2 e + pi^2), so
//   F = K x^{3/2} - sqrt(5) beta sqrt(K m*) x^{1/4} xdot: tsuji-dem at the same e, equal. Its walls are a
//   material of their own (a finite modulus) mixed by eq. (3).
// YADE (2023.02a, Debian's `yade`), Law2_ScGeom_MindlinPhys_Mindlin with Ip2_FrictMat_FrictMat_MindlinPhys(en):
//   F = max(0, K x^{3/2} + 2 beta_n sqrt(m* k_n) xdot), K = (4/3) E* sqrt(R*), k_n = (3/2) K x^{1/2}, so
//   the dashpot is sqrt(6) beta_n sqrt(K m*) x^{1/4} xdot: tsuji-dem with zeta = sqrt(6/5) beta_n under
//   the tension clamp, whose e is clamped_restitution(zeta) (model/restitution.hpp). beta_n(e_Y) is
//   Thornton et al.'s fit, so e_Y is not quite e: the deck takes the e_Y that gives the law's e. The
//   engine's wall() and box() give R* = R/2 to this law (measured: kno is 1/sqrt(2) of eq. 3's); the
//   deck's wall is a fixed sphere of radius 10^6 R, whose R* is R (1 - 10^-6).
#include "hertzdash/simulation/export/engine_contact.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

enum class Engine { lammps, liggghts, yade };

struct EngineDeck;
struct EngineModel;

/// An engine: how hertzdash runs it and writes its decks. Registered once (engine_models.cpp).
struct EngineProgram {
  Engine engine;
  std::string_view name;            ///< --engine: "lammps"
  std::string_view program;         ///< looked up on PATH: "lmp"
  std::string_view deck_extension;  ///< ".in", ".py"
  /// The program's arguments that run the deck `deck` in its directory.
  std::vector<std::string> (*arguments)(const std::string& deck);
  /// The text of an impact's deck (after its header), given its time step, steps and force file.
  std::string (*deck_text)(const EngineModel&, const EngineContact&, EngineImpactKind, const EngineDeck&);
  /// The command line that runs the deck `deck`: the program, then its arguments.
  std::vector<std::string> command(const std::string& deck) const;
};

/// Every registered engine.
std::span<const EngineProgram> engines();
const EngineProgram& engine_program(Engine e);
const char* to_string(Engine e);
/// The engine spelled `name`; InvalidParameter("engine", ...) otherwise (an empty name: none given).
Engine parse_engine(std::string_view name);
/// "lammps, liggghts or yade".
std::string engine_names();

/// The engine's damping input of one impact: its name in the engine and its value.
struct EngineCoefficient {
  std::string_view name;
  double value;
};

struct EngineModel {
  Engine engine;
  std::string_view key;       ///< --engine-model: "granular-viscoelastic"
  std::string_view syntax;    ///< the engine's own words for it
  std::string_view law;       ///< the registered hertzdash law it equals
  std::string_view relation;  ///< how the law's constants become the engine's
  /// The deck's lines of the model for the spheres (pair) and for the wall at z = 0.
  std::string (*pair_lines)(const EngineContact&);
  std::string (*wall_lines)(const EngineContact&);
  /// The damping input the deck gives the engine for the impact (the inverse calibration: what
  /// gives the law's e at the contact's speed).
  EngineCoefficient (*damping_input)(const EngineContact&, EngineImpactKind);
  /// For a model whose damping input is a restitution: the law's e when that input is set to e
  /// itself (what a user who types their e in gets); nullptr for a model whose input is not one.
  double (*restitution_given_input)(double e);
  /// The engine clamps the contact force at zero (no attraction): the law it equals is run with
  /// the tension clamp (EngineContact::tension_clamped).
  bool tension_clamped = false;
};

/// Every registered engine model, engine by engine.
std::span<const EngineModel> engine_models();

/// The model `key` of `engine`, or, with `key` empty, the engine's model that equals `law`;
/// InvalidParameter naming `engine-model` or `damping` (with the laws the engine has) otherwise.
const EngineModel& engine_model(Engine engine, std::string_view key, std::string_view law);

/// LAMMPS's damping tsuji: alpha(e_L) = 1.2728 - 4.2783 e_L + 11.087 e_L^2 - 22.348 e_L^3
/// + 27.467 e_L^4 - 18.022 e_L^5 + 4.8218 e_L^6.
double lammps_tsuji_alpha(double e_L);
/// The restitution LAMMPS's damping tsuji gives with coefficient e_L: tsuji-dem's exact e at
/// zeta = alpha(e_L)/sqrt(5), e = exp(-pi zeta / sqrt(1 - zeta^2)).
double lammps_tsuji_restitution(double e_L);
/// The e_L whose restitution is e (Brent on [0, 1]); InvalidParameter naming `restitution` with
/// the range the polynomial reaches.
double tsuji_engine_restitution_input(double e);

/// YADE's Ip2_FrictMat_FrictMat_MindlinPhys with `en`: Thornton et al. (2013)'s fit, beta_n(e_Y) =
/// sqrt(1 / (1 - (1 + e_Y)^2 exp(a(e_Y))) - 1), a the tenth-degree polynomial of their Table 2
/// (0 at e_Y = 1, as YADE sets it).
double yade_thornton_beta(double e_Y);
/// The restitution YADE's Mindlin gives with `en` = e_Y: its dashpot 2 beta_n sqrt(m* k_n) xdot,
/// k_n = (3/2) K x^{1/2}, is tsuji-dem's c x^{1/4} xdot with zeta = sqrt(6/5) beta_n, clamped at
/// zero force: clamped_restitution(sqrt(6/5) beta_n(e_Y)).
double yade_mindlin_restitution(double e_Y);
/// The e_Y whose restitution is e (Brent); InvalidParameter naming `restitution` with the range
/// the fit reaches (below 1 it reaches no e above yade_mindlin_restitution(1^-) = 0.9846).
double yade_mindlin_restitution_input(double e);

struct EngineDeck {
  std::string text;            ///< the deck
  double timestep_s = 0;       ///< predicted contact time / steps_per_contact
  long steps = 0;              ///< 1.5 contact times
  std::string force_file;      ///< the per-step contact force the deck writes (relative to its directory)
};

/// The deck of one impact: the spheres (pair: at -R and R on x, at -v/2 and v/2; wall: at z = R
/// falling at v), the model's lines, the time step (the predicted contact time over
/// steps_per_contact) and 1.5 contact times of steps; it prints `hertzdash_result V`, V the
/// rebound speed (relative for the pair), and writes the contact force of every step to `force_file`.
/// `header` is prepended (provenance comment lines).
EngineDeck engine_deck(const EngineModel& model, const EngineContact& c, EngineImpactKind k, int steps_per_contact,
                       const std::string& header);

/// The lines a user pastes into an input of their own: the model's pair and wall lines.
std::string engine_contact_lines(const EngineModel& model, const EngineContact& c);

}  // namespace hertzdash
