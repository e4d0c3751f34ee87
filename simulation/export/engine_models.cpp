// The engines' contact models and their decks (simulation/export/engine_models.hpp).
#include "hertzdash/simulation/export/engine_models.hpp"

#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/run/gsl_root.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>

namespace hertzdash {

const char* to_string(Engine e) { return e == Engine::lammps ? "lammps" : "liggghts"; }

Engine parse_engine(std::string_view name) {
  if (name.empty()) throw InvalidParameter("engine", "none", "given: lammps or liggghts");
  if (name == "lammps") return Engine::lammps;
  if (name == "liggghts") return Engine::liggghts;
  throw InvalidParameter("engine", std::string(name), "lammps or liggghts");
}

const char* engine_program(Engine e) { return e == Engine::lammps ? "lmp" : "liggghts"; }

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
  return 4 * c.effective_modulus_Pa(k) * c.time_constant_s / (3 * c.reduced_mass_kg(k));
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

/// LIGGGHTS: type 1 the spheres, type 2 the wall's material.
std::string liggghts_materials(const EngineContact& c) {
  if (!std::isfinite(c.wall.E_Pa))
    throw InvalidParameter("rod-E", "inf", "a finite modulus for LIGGGHTS (its walls are of a material of their own)");
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

EngineCoefficient viscoelastic_input(const EngineContact& c, EngineImpactKind k) {
  return {"eta_n0 [1/(m s)]", kuwabara_kono_damping_per_mass(c, k)};
}
EngineCoefficient tsuji_input(const EngineContact& c, EngineImpactKind) {
  return {"e_L (damping tsuji)", tsuji_engine_restitution_input(c.restitution)};
}
EngineCoefficient hertz_history_input(const EngineContact& c, EngineImpactKind k) {
  return {"gamma_n [1/(m s)]", kuwabara_kono_damping_per_mass(c, k)};
}
EngineCoefficient liggghts_input(const EngineContact& c, EngineImpactKind) { return {"coefficientRestitution", c.restitution}; }
double same_restitution(double e) { return e; }

constexpr EngineModel models[] = {
    {Engine::lammps, "granular-viscoelastic", "pair_style granular, hertz/material, damping viscoelastic",
     "kuwabara-kono", "equal: eta_n0 = 4 E* A / (3 m*) (A kuwabara-kono's material time constant)",
     lammps_viscoelastic_pair, lammps_viscoelastic_wall, viscoelastic_input, nullptr},
    {Engine::lammps, "gran-hertz-history", "pair_style gran/hertz/history", "kuwabara-kono",
     "equal: kn = (4/3) E*, gamma_n = 4 E* A / (3 m*) (A kuwabara-kono's material time constant)", hertz_history_pair,
     hertz_history_wall, hertz_history_input, nullptr},
    {Engine::lammps, "granular-tsuji", "pair_style granular, hertz/material, damping tsuji", "tsuji-dem",
     "equal: the engine's alpha(e_L) = sqrt(5) zeta(e); e_L is not e (the engine's polynomial fit)",
     lammps_tsuji_pair, lammps_tsuji_wall, tsuji_input, lammps_tsuji_restitution},
    {Engine::liggghts, "hertz", "pair_style gran model hertz (coefficientRestitution)", "tsuji-dem",
     "equal: coefficientRestitution = e", liggghts_hertz_pair, liggghts_hertz_wall, liggghts_input, same_restitution},
};

std::string engine_laws(Engine engine) {
  std::string out;
  for (const EngineModel& m : models)
    if (m.engine == engine) out += (out.empty() ? "" : ", ") + std::string(m.law) + " (" + std::string(m.key) + ")";
  return out;
}

}  // namespace

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
  const bool lammps = model.engine == Engine::lammps;
  const double R = c.radius_m, v = c.speed_mps, L = 8 * R;
  std::string s = header;
  s += "units si\n";
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
  d.text = s;
  return d;
}

}  // namespace hertzdash
