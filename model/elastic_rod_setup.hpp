#pragma once
// The experiment as it was built (--rod-model elastic): the rod as an elastic bar
// (model/elastic_bar.hpp) and the hemisphere on its load cell (model/load_cell.hpp), with
// the instrument that records the rod's acceleration. Constant for a run; the rod's mass,
// modulus and the contact come from the DropTestSetup that holds this.
#include "hertzdash/model/parameter.hpp"

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

/// Throws InvalidParameter naming the input and its valid range.
void validate(const ElasticRodSetup& s);

/// The inputs of the elastic rod and load cell (read only with the elastic rod).
namespace elastic_rod_parameters {
inline constexpr ParameterDecl elements{
    .key = "rod-elements", .range = NumberRange::integer(1, ElasticRodSetup::max_elements), .default_value = "20",
    .default_source = "converged: e_effective within 2e-6 of its limit (tests/convergence)",
    .help = "Finite elements of the elastic rod"};
inline constexpr ParameterDecl rod_damping_ratio{
    .key = "rod-damping-ratio", .range = NumberRange::closed_open(0, 1), .default_value = "assumed",
    .default_source = "data/assumptions.csv", .help = "Damping ratio of the elastic rod's first longitudinal mode",
    .fittable = true};
inline constexpr ParameterDecl cell_stiffness{
    .key = "cell-stiffness", .unit = "N/m", .column_unit = "N_per_m", .range = NumberRange::positive_or_infinite(),
    .default_value = "assumed", .default_source = "data/assumptions.csv",
    .help = "Load cell stiffness [N/m]; inf fixes the hemisphere on a rigid base", .fittable = true};
inline constexpr ParameterDecl cell_damping_ratio{
    .key = "cell-damping-ratio", .range = NumberRange::closed_open(0, 1), .default_value = "assumed",
    .default_source = "data/assumptions.csv", .help = "Damping ratio of the hemisphere on the load cell",
    .fittable = true};
inline constexpr ParameterDecl hemisphere_mass{
    .key = "hemisphere-mass", .unit = "kg", .column_unit = "kg", .range = NumberRange::positive(),
    .default_value = "Table 1", .default_source = "the paper's Table 1",
    .help = "Mass of the hemisphere on the load cell [kg]", .fittable = true};
inline constexpr ParameterDecl accelerometer{
    .key = "accelerometer", .type = ParameterType::text, .choices = "top, bottom", .default_value = "top",
    .default_source = "the free end, where an accelerometer can be mounted",
    .help = "End face carrying the accelerometer: top (the free end) or bottom (the struck face)"};
inline constexpr ParameterDecl all[] = {elements, rod_damping_ratio, cell_stiffness, cell_damping_ratio,
                                        hemisphere_mass, accelerometer};
}  // namespace elastic_rod_parameters

}  // namespace hertzdash
