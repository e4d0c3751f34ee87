// The engines' contact models and their decks (simulation/export/engine_models.hpp).
#include "hertzdash/simulation/export/engine_models.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/gsl_root.hpp"

#include <fmt/format.h>

#include "hertzdash/model/restitution.hpp"

#include <cmath>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace hertzdash {

double lammps_tsuji_alpha(double e) {
  return 1.2728 + e * (-4.2783 + e * (11.087 + e * (-22.348 + e * (27.467 + e * (-18.022 + e * 4.8218)))));
}

double lammps_tsuji_restitution(double e_L) {
  const double zeta = lammps_tsuji_alpha(e_L) / std::sqrt(5.0);
  return zeta <= 0 ? 1.0 : zeta >= 1 ? 0.0 : std::exp(-std::numbers::pi * zeta / std::sqrt(1 - zeta * zeta));
}

double tsuji_engine_restitution_input(double e) {
  const double lowest = lammps_tsuji_restitution(0.0), highest = lammps_tsuji_restitution(1.0);
  if (!(e >= lowest && e <= highest))
    throw InvalidParameter("restitution", fmt::format("{:.6g}", e),
                           fmt::format("in [{:.6g}, {:.6g}] for LAMMPS's damping tsuji (its alpha(e) polynomial reaches no "
                                       "other e)",
                                       lowest, highest));
  return brent_root([e](double e_L) { return lammps_tsuji_restitution(e_L) - e; }, 0.0, 1.0, 1e-15, 0.0,
                    "LAMMPS tsuji coefficient");
}

double yade_thornton_beta(double e) {
  if (e == 1.0) return 0.0;
  constexpr double h[] = {-6.918798, -16.41105, 146.8049, -796.4559, 2928.711,
                          -7206.864, 11494.29,  -11342.18, 6276.757, -1489.915};
  double a = 0;
  for (auto it = std::rbegin(h); it != std::rend(h); ++it) a = a * e + *it;
  a *= e;
  return std::sqrt(1.0 / (1.0 - (1.0 + e) * (1.0 + e) * std::exp(a)) - 1.0);
}

namespace {

/// The zeta of tsuji-dem that YADE's beta_n(e_Y) is: sqrt(6/5) beta_n.
double yade_zeta(double e_Y) { return std::sqrt(6.0 / 5.0) * yade_thornton_beta(e_Y); }

/// The e_Y below which YADE's zeta is 1 or more (overdamped, outside clamped_restitution's range).
double yade_lowest_input() {
  return brent_root([](double e_Y) { return yade_zeta(e_Y) - (1 - 1e-9); }, 0.01, 0.99, 1e-15, 0.0,
                    "YADE's en at zeta = 1");
}

}  // namespace

double yade_mindlin_restitution(double e_Y) { return clamped_restitution(yade_zeta(e_Y)); }

double yade_mindlin_restitution_input(double e) {
  if (e == 1.0) return 1.0;
  // The fit's beta_n(1^-) is not 0: just below e_Y = 1 it gives its highest e.
  const double lo = yade_lowest_input(), lowest = yade_mindlin_restitution(lo),
               highest = yade_mindlin_restitution(std::nextafter(1.0, 0.0));
  if (!(e >= lowest && e <= highest))
    throw InvalidParameter("restitution", fmt::format("{:.6g}", e),
                           fmt::format("in [{:.6g}, {:.6g}] or 1 for YADE's Mindlin en (Thornton et al.'s fit reaches "
                                       "no other e below e_Y = 1)",
                                       lowest, highest));
  return brent_root([e](double e_Y) { return yade_mindlin_restitution(e_Y) - e; }, lo, std::nextafter(1.0, 0.0), 1e-15,
                    0.0, "YADE en");
}

namespace {

std::string number(double x) { return fmt::format("{}", x); }  // shortest round-trip

constexpr auto pair = EngineImpactKind::sphere_sphere;
constexpr auto wall = EngineImpactKind::sphere_wall;

/// LAMMPS's wall modulus for fix wall/gran granular hertz/material: E_eff = E_wall / (2 (1 - nu_wall)).
double lammps_wall_modulus(const EngineContact& c) { return 2 * (1 - c.sphere.nu) * c.effective_modulus_Pa(wall); }

/// Kuwabara-Kono's dashpot K A x^{1/2} xdot per unit of m* sqrt(R* x) xdot: 4 E* A / (3 m*) [1/(m s)],
/// with K = (4/3) E* sqrt(R*). LAMMPS's viscoelastic eta_n0 (eta_n = eta_n0 a m*, a = sqrt(R* x))
/// and gran/hertz/history's gamma_n (m* gamma_n sqrt(R* x)) both.
double kuwabara_kono_damping_per_mass(const EngineContact& c, EngineImpactKind k) {
  return 4 * c.effective_modulus_Pa(k) * c.material_constant / (3 * c.reduced_mass_kg(k));
}

/// pair_style granular's lines: hertz/material with `damping` and its coefficient, no friction.
std::string lammps_granular(double E, double damp, double nu, std::string_view damping) {
  return fmt::format("hertz/material {} {} {} damping {} tangential linear_nohistory 0 0", number(E), number(damp),
                     number(nu), damping);
}
std::string lammps_granular_pair(const EngineContact& c, double damp, std::string_view damping) {
  return "pair_style granular\npair_coeff * * " + lammps_granular(c.sphere.E_Pa, damp, c.sphere.nu, damping) + "\n";
}
std::string lammps_granular_wall(const EngineContact& c, double damp, std::string_view damping) {
  return "fix wall all wall/gran granular " + lammps_granular(lammps_wall_modulus(c), damp, c.sphere.nu, damping) +
         " zplane 0.0 NULL\n";
}

std::string lammps_viscoelastic_pair(const EngineContact& c) {
  return lammps_granular_pair(c, kuwabara_kono_damping_per_mass(c, pair), "viscoelastic");
}
std::string lammps_viscoelastic_wall(const EngineContact& c) {
  return lammps_granular_wall(c, kuwabara_kono_damping_per_mass(c, wall), "viscoelastic");
}
/// lee-herrmann's dashpot m* gamma xdot: damping mass_velocity takes eta_n0 = gamma for every contact,
/// damping velocity eta_n0 = gamma m* [N s/m], one value per pair of masses (the pair's and the wall's).
std::string lammps_mass_velocity_pair(const EngineContact& c) {
  return lammps_granular_pair(c, c.material_constant, "mass_velocity");
}
std::string lammps_mass_velocity_wall(const EngineContact& c) {
  return lammps_granular_wall(c, c.material_constant, "mass_velocity");
}
std::string lammps_velocity_pair(const EngineContact& c) {
  return lammps_granular_pair(c, c.material_constant * c.reduced_mass_kg(pair), "velocity");
}
std::string lammps_velocity_wall(const EngineContact& c) {
  return lammps_granular_wall(c, c.material_constant * c.reduced_mass_kg(wall), "velocity");
}

std::string lammps_tsuji_pair(const EngineContact& c) {
  return lammps_granular_pair(c, tsuji_engine_restitution_input(c.restitution), "tsuji");
}
std::string lammps_tsuji_wall(const EngineContact& c) {
  return lammps_granular_wall(c, tsuji_engine_restitution_input(c.restitution), "tsuji");
}

/// gran/hertz/history: F = sqrt(R* x) (kn x - m* gamma_n xdot), so kn = (4/3) E* and gamma_n is
/// kuwabara_kono_damping_per_mass. kn is the pair style's (one value for every pair), the wall's its
/// fix's; no friction (xmu 0), tangential stiffness and damping 0.
std::string hertz_history_coefficients(const EngineContact& c, EngineImpactKind k) {
  return fmt::format("{} 0 {} 0 0 0", number(4 * c.effective_modulus_Pa(k) / 3), number(kuwabara_kono_damping_per_mass(c, k)));
}
std::string hertz_history_pair(const EngineContact& c) {
  return "pair_style gran/hertz/history " + hertz_history_coefficients(c, pair) + "\npair_coeff * *\n";
}
std::string hertz_history_wall(const EngineContact& c) {
  return "fix wall all wall/gran hertz/history " + hertz_history_coefficients(c, wall) + " zplane 0.0 NULL\n";
}

/// An engine whose wall is a material of its own needs its modulus finite.
void require_finite_wall(const EngineContact& c, std::string_view engine) {
  if (!std::isfinite(c.wall.E_Pa))
    throw InvalidParameter("rod-E", "inf", fmt::format("a finite modulus for {} (its walls are of a material of their own)", engine));
}

/// LIGGGHTS: type 1 the spheres, type 2 the wall's material.
std::string liggghts_materials(const EngineContact& c) {
  require_finite_wall(c, "LIGGGHTS");
  const std::string e = number(c.restitution);
  return fmt::format(
      "fix m1 all property/global youngsModulus peratomtype {} {}\n"
      "fix m2 all property/global poissonsRatio peratomtype {} {}\n"
      "fix m3 all property/global coefficientRestitution peratomtypepair 2 {} {} {} {}\n"
      "fix m4 all property/global coefficientFriction peratomtypepair 2 0 0 0 0\n",
      number(c.sphere.E_Pa), number(c.wall.E_Pa), number(c.sphere.nu), number(c.wall.nu), e, e, e, e);
}
std::string liggghts_hertz_pair(const EngineContact& c) {
  return liggghts_materials(c) + "pair_style gran model hertz tangential history\npair_coeff * *\n";
}
std::string liggghts_hertz_wall(const EngineContact&) {
  return "fix wall all wall/gran model hertz tangential history primitive type 2 zplane 0.0\n";
}

/// YADE: the spheres' material, the contact physics (Mindlin with en) and law as Python names.
std::string yade_mindlin_pair(const EngineContact& c) {
  return fmt::format(
      "O.materials.append(FrictMat(young={}, poisson={}, density={}, frictionAngle=0, label='sphere'))\n"
      "contact_physics = Ip2_FrictMat_FrictMat_MindlinPhys(en=MatchMaker(algo='val', val={}))\n"
      "contact_law = Law2_ScGeom_MindlinPhys_Mindlin()\n",
      number(c.sphere.E_Pa), number(c.sphere.nu), number(c.density_kg_per_m3()),
      number(yade_mindlin_restitution_input(c.restitution)));
}
/// YADE's wall: a fixed sphere of radius 10^6 R whose top is z = 0 (its wall() gives R* = R/2).
std::string yade_mindlin_wall(const EngineContact& c) {
  require_finite_wall(c, "YADE");
  const double radius = 1e6 * c.radius_m;
  return fmt::format(
      "# the wall z = 0: a fixed sphere of radius 1e6 R (YADE's Mindlin takes R* = R/2 on a wall() or a box())\n"
      "O.materials.append(FrictMat(young={}, poisson={}, density={}, frictionAngle=0, label='wall'))\n"
      "O.bodies.append(sphere((0, 0, {}), {}, material='wall', fixed=True))\n",
      number(c.wall.E_Pa), number(c.wall.nu), number(c.density_kg_per_m3()), number(-radius), number(radius));
}

EngineCoefficient viscoelastic_input(const EngineContact& c, EngineImpactKind k) {
  return {"eta_n0 [1/(m s)]", kuwabara_kono_damping_per_mass(c, k)};
}
EngineCoefficient mass_velocity_input(const EngineContact& c, EngineImpactKind) {
  return {"eta_n0 [1/s] (damping mass_velocity)", c.material_constant};
}
EngineCoefficient velocity_input(const EngineContact& c, EngineImpactKind k) {
  return {"eta_n0 [N s/m] (damping velocity)", c.material_constant * c.reduced_mass_kg(k)};
}
EngineCoefficient tsuji_input(const EngineContact& c, EngineImpactKind) {
  return {"e_L (damping tsuji)", tsuji_engine_restitution_input(c.restitution)};
}
EngineCoefficient hertz_history_input(const EngineContact& c, EngineImpactKind k) {
  return {"gamma_n [1/(m s)]", kuwabara_kono_damping_per_mass(c, k)};
}
EngineCoefficient liggghts_input(const EngineContact& c, EngineImpactKind) { return {"coefficientRestitution", c.restitution}; }
EngineCoefficient yade_input(const EngineContact& c, EngineImpactKind) {
  return {"en (Ip2_FrictMat_FrictMat_MindlinPhys)", yade_mindlin_restitution_input(c.restitution)};
}
double same_restitution(double e) { return e; }

constexpr EngineModel models[] = {
    {Engine::lammps, "granular-viscoelastic", "pair_style granular, hertz/material, damping viscoelastic",
     "kuwabara-kono", "equal: eta_n0 = 4 E* A / (3 m*) (A kuwabara-kono's material time constant)",
     lammps_viscoelastic_pair, lammps_viscoelastic_wall, viscoelastic_input, nullptr},
    {Engine::lammps, "gran-hertz-history", "pair_style gran/hertz/history", "kuwabara-kono",
     "equal: kn = (4/3) E*, gamma_n = 4 E* A / (3 m*) (A kuwabara-kono's material time constant)", hertz_history_pair,
     hertz_history_wall, hertz_history_input, nullptr},
    {Engine::lammps, "granular-mass-velocity", "pair_style granular, hertz/material, damping mass_velocity",
     "lee-herrmann", "equal: eta_n0 = gamma (lee-herrmann's damping rate)", lammps_mass_velocity_pair,
     lammps_mass_velocity_wall, mass_velocity_input, nullptr},
    {Engine::lammps, "granular-velocity", "pair_style granular, hertz/material, damping velocity", "lee-herrmann",
     "equal contact by contact: eta_n0 = gamma m* (one value per pair of masses: the wall's is its own)",
     lammps_velocity_pair, lammps_velocity_wall, velocity_input, nullptr},
    {Engine::lammps, "granular-tsuji", "pair_style granular, hertz/material, damping tsuji", "tsuji-dem",
     "equal: the engine's alpha(e_L) = sqrt(5) zeta(e); e_L is not e (the engine's polynomial fit)",
     lammps_tsuji_pair, lammps_tsuji_wall, tsuji_input, lammps_tsuji_restitution},
    {Engine::liggghts, "hertz", "pair_style gran model hertz (coefficientRestitution)", "tsuji-dem",
     "equal: coefficientRestitution = e", liggghts_hertz_pair, liggghts_hertz_wall, liggghts_input, same_restitution},
    {Engine::yade, "mindlin", "Law2_ScGeom_MindlinPhys_Mindlin, Ip2_FrictMat_FrictMat_MindlinPhys(en)", "tsuji-dem",
     "equal under the tension clamp: zeta = sqrt(6/5) beta_n(en), beta_n Thornton et al.'s fit; en is not e",
     yade_mindlin_pair, yade_mindlin_wall, yade_input, yade_mindlin_restitution, true},
};

std::string engine_laws(Engine engine) {
  std::string out;
  for (const EngineModel& m : models)
    if (m.engine == engine) out += (out.empty() ? "" : ", ") + std::string(m.law) + " (" + std::string(m.key) + ")";
  return out;
}

/// The deck of LAMMPS and LIGGGHTS (one syntax): the spheres as atoms in a fixed box, velocity
/// Verlet (nve/sphere), the force of every step printed to the force file.
std::string lammps_deck_text(const EngineModel& model, const EngineContact& c, EngineImpactKind k, const EngineDeck& d) {
  const bool lammps = model.engine == Engine::lammps;
  const double R = c.radius_m, v = c.speed_mps, L = 8 * R;
  std::string s = "units si\n";
  s += lammps ? "atom_style sphere\n" : "atom_style granular\n";
  s += "atom_modify map array\nboundary f f f\n";
  s += lammps ? "comm_modify vel yes\n" : "newton off\ncommunicate single vel yes\nhard_particles yes\n";
  s += fmt::format("region box block {0} {1} {0} {1} {0} {1} units box\n", number(-L), number(L));
  s += fmt::format("create_box {} box\n", lammps ? 1 : 2);
  const std::string units = " units box";
  if (k == pair) {
    s += fmt::format("create_atoms 1 single {} 0 0{}\ncreate_atoms 1 single {} 0 0{}\n", number(-R), units, number(R), units);
  } else {
    s += fmt::format("create_atoms 1 single 0 0 {}{}\n", number(R), units);
  }
  s += fmt::format("set atom * diameter {}\nset atom * density {}\n", number(2 * R), number(c.density_kg_per_m3()));
  if (k == pair) {
    s += fmt::format("group left id 1\ngroup right id 2\nvelocity left set {} 0 0{}\nvelocity right set {} 0 0{}\n",
                     number(v / 2), units, number(-v / 2), units);
  } else {
    s += fmt::format("velocity all set 0 0 {}{}\n", number(-v), units);
  }
  s += model.pair_lines(c);
  if (k == wall) s += model.wall_lines(c);
  s += fmt::format("neighbor {} bin\nneigh_modify delay 0\nfix integrate all nve/sphere\ntimestep {}\n", number(R / 2),
                   number(d.timestep_s));
  s += k == pair ? "variable force equal fx[2]\nvariable rebound equal vx[2]-vx[1]\n"
                 : "variable force equal fz[1]\nvariable rebound equal vz[1]\n";
  s += fmt::format("fix record all print 1 \"${{force}}\" file {} screen no\n", d.force_file);
  s += fmt::format("thermo {}\nrun {}\nprint \"hertzdash_result ${{rebound}}\"\n", d.steps, d.steps);
  return s;
}

/// YADE's deck, a Python script for `yade -n -x`: the model's lines name the materials, then
/// contact_physics and contact_law; no gravity, no numerical damping (NewtonIntegrator's damping = 0).
std::string yade_deck_text(const EngineModel& model, const EngineContact& c, EngineImpactKind k, const EngineDeck& d) {
  const double R = c.radius_m, v = c.speed_mps;
  std::string s = fmt::format("R = {}\n", number(R));
  s += model.pair_lines(c);
  if (k == pair) {
    s += "O.bodies.append([sphere((-R, 0, 0), R, material='sphere'), sphere((R, 0, 0), R, material='sphere')])\n";
    s += fmt::format("O.bodies[0].state.vel = Vector3({}, 0, 0)\nO.bodies[1].state.vel = Vector3({}, 0, 0)\n", number(v / 2),
                     number(-v / 2));
  } else {
    s += "O.bodies.append(sphere((0, 0, R), R, material='sphere'))\n";
    s += fmt::format("O.bodies[0].state.vel = Vector3(0, 0, {})\n", number(-v));
    s += model.wall_lines(c);
  }
  s += "O.engines = [ForceResetter(), InsertionSortCollider([Bo1_Sphere_Aabb()], verletDist=R / 2),\n"
       "             InteractionLoop([Ig2_Sphere_Sphere_ScGeom()], [contact_physics], [contact_law]),\n"
       "             NewtonIntegrator(damping=0, gravity=(0, 0, 0))]\n";
  s += fmt::format("O.dt = {}\n", number(d.timestep_s));
  s += fmt::format("with open('{}', 'w') as force:\n    for step in range({}):\n        O.step()\n", d.force_file, d.steps);
  s += k == pair ? "        force.write('%r\\n' % O.forces.f(1)[0])\n"
                   "print('hertzdash_result %r' % (O.bodies[1].state.vel[0] - O.bodies[0].state.vel[0]))\n"
                 : "        force.write('%r\\n' % O.forces.f(0)[2])\nprint('hertzdash_result %r' % O.bodies[0].state.vel[2])\n";
  return s;
}

/// LAMMPS and LIGGGHTS read the deck as their input and write no log file; YADE runs it without a
/// window (-n) and exits at its end (-x).
std::vector<std::string> lammps_arguments(const std::string& deck) { return {"-in", deck, "-log", "none"}; }
std::vector<std::string> yade_arguments(const std::string& deck) { return {"-n", "-x", deck}; }

constexpr EngineProgram programs[] = {
    {Engine::lammps, "lammps", "lmp", ".in", lammps_arguments, lammps_deck_text},
    {Engine::liggghts, "liggghts", "liggghts", ".in", lammps_arguments, lammps_deck_text},
    {Engine::yade, "yade", "yade", ".py", yade_arguments, yade_deck_text},
};

}  // namespace

std::vector<std::string> EngineProgram::command(const std::string& deck) const {
  std::vector<std::string> line{std::string(program)};
  for (std::string& a : arguments(deck)) line.push_back(std::move(a));
  return line;
}

std::span<const EngineProgram> engines() { return programs; }

const EngineProgram& engine_program(Engine e) {
  for (const EngineProgram& p : programs)
    if (p.engine == e) return p;
  throw std::logic_error("an engine without a program");
}

const char* to_string(Engine e) { return engine_program(e).name.data(); }

std::string engine_names() {
  std::string out;
  for (std::size_t i = 0; i < std::size(programs); ++i)
    out += (i == 0 ? "" : i + 1 == std::size(programs) ? " or " : ", ") + std::string(programs[i].name);
  return out;
}

Engine parse_engine(std::string_view name) {
  if (name.empty()) throw InvalidParameter("engine", "none", "given: " + engine_names());
  for (const EngineProgram& p : programs)
    if (p.name == name) return p.engine;
  throw InvalidParameter("engine", std::string(name), engine_names());
}

std::span<const EngineModel> engine_models() { return models; }

const EngineModel& engine_model(Engine engine, std::string_view key, std::string_view law) {
  for (const EngineModel& m : models)
    if (m.engine == engine && (key.empty() ? m.law == law : m.key == key)) {
      if (m.law != law)
        throw InvalidParameter("damping", std::string(law),
                               fmt::format("{} for {}'s model {} (the law it equals)", m.law, to_string(engine), m.key));
      return m;
    }
  if (!key.empty())
    throw InvalidParameter("engine-model", std::string(key), fmt::format("one of {}'s: {}", to_string(engine), engine_laws(engine)));
  throw InvalidParameter("damping", std::string(law),
                         fmt::format("a law one of {}'s models equals: {}", to_string(engine), engine_laws(engine)));
}

std::string engine_contact_lines(const EngineModel& model, const EngineContact& c) {
  return model.pair_lines(c) + model.wall_lines(c);
}

EngineDeck engine_deck(const EngineModel& model, const EngineContact& c, EngineImpactKind k, int steps_per_contact,
                       const std::string& header) {
  EngineDeck d;
  d.timestep_s = c.predicted(k).contact_time_s / steps_per_contact;
  d.steps = static_cast<long>(std::ceil(1.5 * steps_per_contact));
  d.force_file = std::string(to_string(k)) + "_force.txt";
  d.text = header + engine_program(model.engine).deck_text(model, c, k, d);
  return d;
}

}  // namespace hertzdash
