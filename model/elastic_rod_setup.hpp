#pragma once
// The experiment as it was built (--rod-model elastic): the rod as an elastic bar
// (model/elastic_bar.hpp) and the hemisphere on its load cell (model/load_cell.hpp), with
// the instrument that records the rod's acceleration. Constant for a run; the rod's mass,
// modulus and the contact come from the DropTestSetup that holds this.
#include <cmath>

namespace hertzdash {

/// Which end face of the rod carries the accelerometer.
enum class Accelerometer {
  top,     ///< the free end: where an accelerometer can be mounted on a rod that strikes with its other face
  bottom,  ///< the struck face itself
};
const char* to_string(Accelerometer a);

struct ElasticRodSetup {
  static constexpr int max_elements = 400;
  static constexpr int default_elements = 20;  ///< e_effective within 2e-6 of its N -> inf limit (tests/convergence/test_elastic_rod_convergence.cpp)
  double length_m = NAN;           ///< rod length L [m] > 0 (Table 1)
  double diameter_m = NAN;         ///< rod diameter d [m] > 0 (Table 1); rho = m / (pi d^2 / 4 L)
  int elements = default_elements;              ///< finite elements N, 1..max_elements (--rod-elements)
  double rod_damping_ratio = 0;    ///< zeta_1 of the first longitudinal mode, [0, 1) (--rod-damping-ratio)
  double hemisphere_mass_kg = NAN;      ///< m_h [kg] > 0 (Table 1; --hemisphere-mass)
  double cell_stiffness_N_per_m = NAN;  ///< k_cell [N/m] > 0 or +inf for a rigid base (--cell-stiffness)
  double cell_damping_ratio = 0;   ///< zeta_cell, [0, 1) (--cell-damping-ratio)
  Accelerometer accelerometer = Accelerometer::top;
};

/// Throws InvalidParameter naming the option and its valid range.
void validate(const ElasticRodSetup& s);

}  // namespace hertzdash
