#pragma once
// A homogeneous granular gas cooling in a periodic box, run by LAMMPS (under mpirun) with the
// contact hertzdash exports (simulation/export/engine_models.hpp), against Haff's law.
//
// Haff's law (P. K. Haff, J. Fluid Mech. 134 (1983) 401; N. V. Brilliantov and T. Poeschel,
// Kinetic Theory of Granular Gases, Oxford 2004, ch. 7). Identical spheres of diameter sigma and
// mass m at number density n, granular temperature T = m <v_x^2> (energy per degree of freedom),
// a Maxwellian velocity distribution, a constant e. A collision at normal relative speed g_n loses
// (m/4) (1 - e^2) g_n^2; collisions at relative velocity g occur per unit volume at
// (1/2) n^2 sigma^2 chi int_{g.k > 0} (g.k) dk, chi the pair correlation at contact. With
// int_{g.k > 0} (g.k)^3 dk = pi g^3 / 2 and <g^3> = 32 (T/m)^{3/2} / sqrt(pi) (g Maxwellian of
// variance 2T/m per component) the energy density (3/2) n T falls as
//   dT/dt = -B T^{3/2},   B = (4/3) sqrt(pi/m) n sigma^2 chi (1 - e^2),
// so T(t) = T1 / (1 + (t - t1)/tau)^2 from any T1 = T(t1), tau = 2 / (B sqrt(T1)).
// chi = (1 - phi/2) / (1 - phi)^3 (Carnahan and Starling) at volume fraction phi.
// The contact is tsuji-dem (LAMMPS's damping tsuji at the e_L that gives e), whose e does not
// depend on the impact speed: the law above holds at every temperature; or kuwabara-kono (LAMMPS's
// damping viscoelastic), whose e rises as the gas cools (simulation/export/gas_cooling.hpp predicts
// its cooling from hertzdash's e(g)).
//
// Clustering: a cooling gas large enough against its mean free path (and inelastic enough) loses
// its homogeneity (Goldhirsch and Zanetti 1993). The deck can count the particles in each of c^3
// cells; their index of dispersion D = var/mean is S(0) = (1 - phi)^4 / (1 + 2 phi)^2 for a
// homogeneous hard-sphere gas (Carnahan-Starling's compressibility; 1 for an ideal gas), and grows
// as clusters form.
#include "hertzdash/simulation/export/engine_contact.hpp"
#include "hertzdash/simulation/export/engine_models.hpp"
#include "hertzdash/simulation/export/gas_cooling.hpp"

#include <filesystem>
#include <vector>

namespace hertzdash {

struct GranularGas {
  double diameter_m = 1e-3;
  double density_kg_per_m3 = 2500;
  Material material{63e6, 0.22};   ///< soft: the contact lasts ~3 % of the free flight time
  double restitution = 0.8;        ///< e of tsuji-dem, constant
  double volume_fraction = 0.05;   ///< phi
  int particles_per_side = 6;      ///< N = side^3 on a simple cubic lattice at the start
  double thermal_speed_mps = 1.0;  ///< sqrt(T0/m) at the start
  int steps_per_contact = 20;      ///< the time step: the contact time at the start over this
  double duration_haff_times = 6;  ///< the run, in units of tau at the start
  int seed = 4928459;              ///< LAMMPS's velocity create seed
  std::string law = "tsuji-dem";   ///< tsuji-dem (e constant), or kuwabara-kono (e at reference_speed_mps)
  int cells_per_side = 0;          ///< > 0: the deck counts the particles in cells_per_side^3 cells
  /// The typical relative speed at the start, sqrt(6) v_th [m/s] (sqrt(2) v_th per component over
  /// three): where kuwabara-kono's e is `restitution`, and the time step's contact.
  double reference_speed_mps() const;
  double mass_kg() const;
  int particles() const { return particles_per_side * particles_per_side * particles_per_side; }
  double box_side_m() const;
  double number_density_per_m3() const;
  /// chi = (1 - phi/2)/(1 - phi)^3.
  double contact_correlation() const;
  /// B of dT/dt = -B T^{3/2} [1/(J^{1/2} s)].
  double cooling_coefficient() const;
  /// tau = 2/(B sqrt(T)) at the temperature T [J].
  double haff_time_s(double temperature_J) const;
  /// T0 = m v_th^2 [J].
  double initial_temperature_J() const;
  /// Enskog's collision frequency of one particle, 4 sqrt(pi) n sigma^2 chi sqrt(T/m) [1/s].
  double collision_frequency_per_s(double temperature_J) const;
  /// S(0) = (1 - phi)^4 / (1 + 2 phi)^2: the cells' index of dispersion in a homogeneous gas.
  double homogeneous_dispersion() const;
};

/// The contact of two of the gas's spheres as exported (kuwabara-kono's A calibrated on the pair
/// at reference_speed_mps).
EngineContact gas_contact(const GranularGas& gas);

/// The LAMMPS deck of the gas: lattice start, Gaussian velocities of zero total momentum, the
/// LAMMPS model equal to the gas's law (engine_models.hpp), the thermo output (time, total kinetic
/// energy) about 300 times over the run, and with cells_per_side the cells' counts as often.
std::string granular_gas_deck(const GranularGas& gas);

struct TemperatureSample {
  double time_s, temperature_J;  ///< T = (2/3) KE / N
};

struct DispersionSample {
  double time_s, dispersion;  ///< the cells' var/mean of their particle counts
};

struct GasRun {
  std::vector<TemperatureSample> temperature;
  std::vector<DispersionSample> dispersion;  ///< empty without cells_per_side
  double loop_seconds = 0;                   ///< LAMMPS's loop time (wall clock of the run's steps)
};

/// Runs `mpirun -n ranks lmp` (ranks 1: lmp alone) on the deck in `directory` and reads T(t), the
/// cells' dispersion and the loop time.
GasRun run_granular_gas(const GranularGas& gas, int ranks, const std::filesystem::path& directory);

/// The centre of the first window of five successive samples from `from_s` on whose mean cells'
/// dispersion exceeds twice the homogeneous gas's (the gas has begun to cluster: with c^3 cells, one
/// sample of D scatters by S(0) sqrt(2/(c^3 - 1)), 10 % at c = 6 and 28 % at c = 3, the average of
/// five by sqrt(5) less), or +inf if it never does.
double clustering_onset_s(const GranularGas& gas, const std::vector<DispersionSample>& dispersion, double from_s);

/// The index of the first sample from half a Haff time of the start on (the lattice start
/// forgotten), where the comparisons with kinetic theory begin; std::runtime_error if the run is
/// shorter than that and two more samples.
std::size_t first_sample_after_start(const GranularGas& gas, const std::vector<TemperatureSample>& samples);

/// Kinetic theory's T (gas_cooling.hpp) at the times of samples[from...], from samples[from]'s T.
std::vector<CoolingSample> predicted_from(const GranularGas& gas, const RestitutionCurve& e,
                                          const std::vector<TemperatureSample>& samples, std::size_t from);

/// Enskog's count of collisions over the run, (N/2) int omega(T(t)) dt, from the measured T(t).
double enskog_collisions(const GranularGas& gas, const std::vector<TemperatureSample>& temperature);

struct HaffFit {
  double t1_s = 0, T1_J = 0;  ///< where the fit starts: half a Haff time in, the lattice forgotten
  double tau_s = 0;           ///< Haff's tau at T1 (predicted, not fitted)
  double exponent = 0;        ///< a of T = T1 (1 + (t - t1)/tau)^-a, least squares in log T
};

/// The cooling exponent with Haff's predicted tau, from half a Haff time on.
HaffFit fit_haff_exponent(const GranularGas& gas, const std::vector<TemperatureSample>& samples);

}  // namespace hertzdash
