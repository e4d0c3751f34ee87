// A granular gas run by LAMMPS against Haff's law (simulation/export/granular_gas.hpp).
#include "hertzdash/simulation/export/granular_gas.hpp"

#include "hertzdash/simulation/export/engine_run.hpp"

#include "hertzdash/model/hertz.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/model/two_spheres.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace hertzdash {

namespace {

constexpr double boltzmann_J_per_K = 1.380649e-23;  // LAMMPS's si units take temperatures in K
constexpr double pi = std::numbers::pi;

/// The undamped contact time of two of the spheres colliding at relative speed v_rel.
double pair_contact_time_s(const GranularGas& g, double relative_speed_mps) {
  const double K = hertz_stiffness(g.diameter_m / 4, g.material, g.material);  // R* = R/2
  return undamped_hertz_impact(K, g.mass_kg() / 2, relative_speed_mps).contact_time_s;
}

/// The deck's time step: the undamped contact time at the typical relative speed over steps_per_contact.
double gas_timestep_s(const GranularGas& g) {
  return pair_contact_time_s(g, g.reference_speed_mps()) / g.steps_per_contact;
}

}  // namespace

double GranularGas::mass_kg() const { return sphere_mass_kg(diameter_m / 2, density_kg_per_m3); }

double GranularGas::box_side_m() const {
  return particles_per_side * diameter_m * std::cbrt(pi / (6 * volume_fraction));
}

double GranularGas::number_density_per_m3() const { return particles() / std::pow(box_side_m(), 3); }

double GranularGas::contact_correlation() const {
  const double phi = volume_fraction;
  return (1 - phi / 2) / std::pow(1 - phi, 3);
}

double GranularGas::cooling_coefficient() const {
  return 4.0 / 3.0 * std::sqrt(pi / mass_kg()) * number_density_per_m3() * diameter_m * diameter_m * contact_correlation() *
         (1 - restitution * restitution);
}

double GranularGas::haff_time_s(double temperature_J) const { return 2 / (cooling_coefficient() * std::sqrt(temperature_J)); }

double GranularGas::initial_temperature_J() const { return mass_kg() * thermal_speed_mps * thermal_speed_mps; }

double GranularGas::reference_speed_mps() const { return std::sqrt(6.0) * thermal_speed_mps; }

double GranularGas::collision_frequency_per_s(double temperature_J) const {
  return 4 * std::sqrt(pi) * number_density_per_m3() * diameter_m * diameter_m * contact_correlation() *
         std::sqrt(temperature_J / mass_kg());
}

double GranularGas::homogeneous_dispersion() const {
  return std::pow(1 - volume_fraction, 4) / std::pow(1 + 2 * volume_fraction, 2);
}

EngineContact gas_contact(const GranularGas& g) {
  DropTestSetup s{};
  s.mass_kg = g.mass_kg();
  s.ball_radius_m = g.diameter_m / 2;
  s.ball = g.material;
  s.ball_yield_stress_Pa = INFINITY;
  s.rod = g.material;  // the engine's wall, which the gas has not
  s.restitution = g.restitution;
  s.height_m = 0;
  s.impact_velocity_mps = g.reference_speed_mps();
  s.gravity_mps2 = 0;
  validate(s);
  return make_engine_contact(s, g.law);
}

std::string granular_gas_deck(const GranularGas& g) {
  const double spacing = g.diameter_m * std::cbrt(pi / (6 * g.volume_fraction));
  const double dt = gas_timestep_s(g);
  const long steps = std::lround(g.duration_haff_times * g.haff_time_s(g.initial_temperature_J()) / dt);
  const auto n = [](double x) { return fmt::format("{}", x); };
  std::string s;
  s += "units si\natom_style sphere\natom_modify map array\nboundary p p p\ncomm_modify vel yes\n";
  s += fmt::format("lattice custom {} a1 1 0 0 a2 0 1 0 a3 0 0 1 basis 0.5 0.5 0.5\n", n(spacing));
  s += fmt::format("region box block 0 {0} 0 {0} 0 {0}\ncreate_box 1 box\ncreate_atoms 1 box\n", g.particles_per_side);
  s += fmt::format("set atom * diameter {}\nset atom * density {}\n", n(g.diameter_m), n(g.density_kg_per_m3));
  s += fmt::format("velocity all create {} {} dist gaussian mom yes\n", n(g.initial_temperature_J() / boltzmann_J_per_K), g.seed);
  s += engine_model(Engine::lammps, "", g.law).pair_lines(gas_contact(g));
  s += fmt::format("neighbor {} bin\nneigh_modify delay 0 every 1 check yes\nfix integrate all nve/sphere\n", n(g.diameter_m / 2));
  const long every = std::max(1L, steps / 300);
  if (g.cells_per_side > 0)
    s += fmt::format("compute cells all chunk/atom bin/3d x lower {0} y lower {0} z lower {0} units reduced\n"
                     "fix cells all ave/chunk {1} 1 {1} cells density/number file cells.txt\n",
                     n(1.0 / g.cells_per_side), every);
  s += fmt::format("timestep {}\nthermo_style custom step time ke\nthermo_modify norm no\nthermo {}\nrun {}\n", n(dt), every,
                   steps);
  return s;
}

GasRun run_granular_gas(const GranularGas& gas, int ranks, const std::filesystem::path& directory) {
  write_deck(directory / "in.gas", granular_gas_deck(gas));
  const std::filesystem::path screen = directory / "gas.out";
  std::vector<std::string> args;
  if (ranks > 1) args = {"mpirun", "--allow-run-as-root", "--oversubscribe", "-n", std::to_string(ranks)};
  for (const char* a : {"lmp", "-in", "in.gas", "-log", "none"}) args.emplace_back(a);
  run_in_directory(args, directory, screen, "`make deps-engines` installs LAMMPS (debian-packages-engines.txt)");
  std::ifstream in(screen);
  GasRun out;
  bool thermo = false;
  for (std::string line; std::getline(in, line);) {
    std::istringstream words(line);
    std::string first;
    words >> first;
    if (first == "Step") thermo = true;
    else if (first == "Loop") {
      thermo = false;
      std::string time_word, of;
      words >> time_word >> of >> out.loop_seconds;  // "Loop time of X on N procs for S steps ..."
    } else if (thermo) {
      double t = 0, ke = 0;
      if (words >> t >> ke) out.temperature.push_back({t, 2 * ke / (3.0 * gas.particles())});
    }
  }
  if (out.temperature.size() < 10) throw std::runtime_error("LAMMPS printed no temperature history: see " + screen.string());
  if (gas.cells_per_side > 0) {
    // fix ave/chunk: "# ..." lines, then per output "Timestep Nchunks Total" and Nchunks rows
    // "Chunk Coord1 Coord2 Coord3 Ncount density/number".
    std::ifstream cells(directory / "cells.txt");
    const double timestep_s = gas_timestep_s(gas);
    for (std::string line; std::getline(cells, line);) {
      if (line.empty() || line[0] == '#') continue;
      std::istringstream head(line);
      long step = 0, chunks = 0;
      if (!(head >> step >> chunks)) continue;
      double sum = 0, sum2 = 0;
      for (long c = 0; c < chunks && std::getline(cells, line); ++c) {
        std::istringstream row(line);
        double chunk = 0, x = 0, y = 0, z = 0, count = 0;
        row >> chunk >> x >> y >> z >> count;
        sum += count;
        sum2 += count * count;
      }
      const double k = static_cast<double>(chunks), mean = sum / k, var = (sum2 - k * mean * mean) / (k - 1);
      out.dispersion.push_back({static_cast<double>(step) * timestep_s, var / mean});
    }
    if (out.dispersion.empty()) throw std::runtime_error("LAMMPS wrote no cell counts: see " + (directory / "cells.txt").string());
  }
  return out;
}

double clustering_onset_s(const GranularGas& gas, const std::vector<DispersionSample>& dispersion, double from_s) {
  constexpr std::size_t window = 5;
  for (std::size_t i = 0; i + window <= dispersion.size(); ++i) {
    if (dispersion[i].time_s < from_s) continue;
    double sum = 0;
    for (std::size_t j = i; j < i + window; ++j) sum += dispersion[j].dispersion;
    if (sum / window > 2 * gas.homogeneous_dispersion()) return dispersion[i + window / 2].time_s;  // its centre
  }
  return INFINITY;
}

double enskog_collisions(const GranularGas& gas, const std::vector<TemperatureSample>& T) {
  double integral = 0;
  for (std::size_t i = 1; i < T.size(); ++i)
    integral += 0.5 * (gas.collision_frequency_per_s(T[i - 1].temperature_J) + gas.collision_frequency_per_s(T[i].temperature_J)) *
                (T[i].time_s - T[i - 1].time_s);
  return gas.particles() / 2.0 * integral;
}

std::size_t first_sample_after_start(const GranularGas& gas, const std::vector<TemperatureSample>& samples) {
  const double t_start = 0.5 * gas.haff_time_s(gas.initial_temperature_J());
  std::size_t i1 = 0;
  while (i1 < samples.size() && samples[i1].time_s < t_start) ++i1;
  if (i1 + 2 >= samples.size()) throw std::runtime_error("the granular gas ran for less than half a Haff time");
  return i1;
}

std::vector<CoolingSample> predicted_from(const GranularGas& gas, const RestitutionCurve& e,
                                          const std::vector<TemperatureSample>& samples, std::size_t from) {
  // The thermo output is evenly spaced in steps, so in time: predicted_cooling's samples fall on it.
  return predicted_cooling(samples[from].temperature_J, samples[from].time_s, samples.back().time_s,
                           static_cast<int>(samples.size() - from), gas.mass_kg(), gas.diameter_m,
                           gas.number_density_per_m3(), gas.contact_correlation(), e);
}

HaffFit fit_haff_exponent(const GranularGas& gas, const std::vector<TemperatureSample>& samples) {
  const std::size_t i1 = first_sample_after_start(gas, samples);
  HaffFit f{samples[i1].time_s, samples[i1].temperature_J, gas.haff_time_s(samples[i1].temperature_J), 0};
  // log(T/T1) = -a log(1 + (t - t1)/tau): a line through the origin.
  double xy = 0, xx = 0;
  for (std::size_t i = i1; i < samples.size(); ++i) {
    const double x = std::log1p((samples[i].time_s - f.t1_s) / f.tau_s), y = std::log(samples[i].temperature_J / f.T1_J);
    xy += x * y;
    xx += x * x;
  }
  f.exponent = -xy / xx;
  return f;
}

}  // namespace hertzdash
