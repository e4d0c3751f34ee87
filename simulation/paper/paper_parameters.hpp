#pragma once
// The paper's Tables 1-3 and the stated assumptions, read from data/*.csv.
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/uncertainty/uncertain_inputs.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace hertzdash {

/// One rod of Tables 1-3.
struct RodData {
  std::string name;              ///< steel, duralumin-a, duralumin-b, duralumin-c
  double diameter_m;             ///< Table 1
  double length_m;               ///< Table 1
  double mass_kg;                ///< Table 1
  double restitution;            ///< Table 2, against the nylon ball
  double restitution_second;     ///< Table 2's second printed value (rod A only), else NaN
  double zeta_printed;           ///< Table 2, in brackets
  double natural_frequency_hz;   ///< Table 3
  double E_Pa;                   ///< Table 3
  double nu;                     ///< assumption (data/assumptions.csv)
};

/// The nylon hemisphere.
struct BallData {
  double diameter_m, height_m, mass_kg;  ///< Table 1
  double E_Pa;                           ///< assumption inside the catalogue range
  double E_min_Pa, E_max_Pa;             ///< Table 3 catalogue range
  double nu;                             ///< assumption
  double radius_m;                       ///< assumption: diameter / 2
  double yield_stress_Pa;                ///< assumption: nylon yield stress Y (the elasticity check)
  double yield_stress_min_Pa, yield_stress_max_Pa;  ///< assumption: its plausible range
};

/// The test rig's parameters the paper does not state (data/assumptions.csv), for the
/// elastic rod on the load cell (--rod-model elastic).
struct RigAssumptions {
  double cell_stiffness_N_per_m;  ///< piezoelectric load cell stiffness
  double cell_damping_ratio;      ///< the hemisphere's damping ratio on the cell
  double rod_damping_ratio;       ///< material damping of the rod's first longitudinal mode
};

struct PaperParameters {
  std::vector<RodData> rods;
  BallData ball;
  RigAssumptions rig;
  double gravity_mps2;
  /// The inputs data/assumptions.csv gives a distribution (the joint uncertainty study).
  std::vector<UncertainInput> uncertain_inputs;
  const RodData& rod(const std::string& name) const;  ///< throws InvalidParameter("rod", ...)
  /// The uncertain input `parameter`; throws DataError if assumptions.csv gives it none.
  const UncertainInput& uncertain_input(const std::string& parameter) const;
};

/// Where the data tables sit below an installation prefix or a build tree.
inline constexpr const char* data_dir_below_prefix = "share/hertzdash/data";

/// The directory of the data tables, found at run time: $HERTZDASH_DATA_DIR if set, else
/// share/hertzdash/data in the directory of the hertzdash library, or of the running
/// program, or the one above either (PREFIX/lib/libhertzdash_paper_data.so and
/// PREFIX/bin/hertzdash find PREFIX/share/hertzdash/data, and so does a program of yours
/// linked to an installed hertzdash; in a build tree, build/share/hertzdash/data links to the
/// source tree's data/). Throws std::runtime_error saying how to set it if none holds the tables.
std::filesystem::path default_data_dir();

/// Read the tables; throws DataError naming the file, line and column of any defect.
PaperParameters load_paper_parameters(const std::filesystem::path& data_dir = default_data_dir());

/// The paper's drop test for a rod at height h [m]: Table values plus assumptions.
DropTestSetup paper_setup(const PaperParameters& p, const std::string& rod, double height_m);

}  // namespace hertzdash
