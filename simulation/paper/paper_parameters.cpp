#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/model/invalid_parameter.hpp"
#include "hertzdash/simulation/paper/table_ranges.hpp"

#include <dlfcn.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace hertzdash {

const RodData& PaperParameters::rod(const std::string& name) const {
  std::string names;
  for (const auto& r : rods) {
    if (r.name == name) return r;
    names += (names.empty() ? "" : ", ") + r.name;
  }
  throw InvalidParameter("rod", name, "one of: " + names);
}

const UncertainInput& PaperParameters::uncertain_input(const std::string& parameter) const {
  for (const auto& in : uncertain_inputs)
    if (in.parameter == parameter) return in;
  throw DataError("assumptions.csv: parameter " + parameter + " has no distribution (distribution = fixed or no row)");
}

namespace {

// The file this code was loaded from: the shared library libhertzdash_paper_data.so (or,
// linked statically, the program).
std::filesystem::path this_library() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&default_data_dir), &info) == 0 || !info.dli_fname) return {};
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::canonical(info.dli_fname, ec);
  return ec ? std::filesystem::path{} : p;
}

}  // namespace

std::filesystem::path default_data_dir() {
  namespace fs = std::filesystem;
  if (const char* env = std::getenv("HERTZDASH_DATA_DIR"); env && *env) return env;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const fs::path lib = this_library();
  // PREFIX/lib/libhertzdash_paper_data.so, PREFIX/bin/hertzdash and build/lib/<library> look
  // one level up, build/hertzdash in its own directory; no further, so no other
  // installation's tables are picked up.
  std::vector<fs::path> dirs;
  // An installation's library directory may be deeper (lib/x86_64-linux-gnu): the way from it
  // to the tables is configured by CMake (HERTZDASH_LIBDIR_TO_DATADIR: ".." or "../..", to PREFIX).
  if (!lib.empty()) dirs.push_back((lib.parent_path() / HERTZDASH_LIBDIR_TO_DATADIR).lexically_normal());
  for (const fs::path& file : {lib, ec ? fs::path{} : exe})
    if (!file.empty()) dirs.insert(dirs.end(), {file.parent_path(), file.parent_path().parent_path()});
  for (const fs::path& dir : dirs) {
    const fs::path data = dir / data_dir_below_prefix;
    if (fs::is_regular_file(data / "table1_dimensions.csv")) {
      std::error_code real_ec;
      const fs::path real = fs::canonical(data, real_ec);  // the source tree's data/ behind a build tree's link
      return real_ec ? data : real;
    }
  }
  throw std::runtime_error(std::string("the data tables (table1_dimensions.csv, ...) are not in ") +
                           data_dir_below_prefix + " in the directory of the hertzdash library " + lib.string() +
                           " or of the program " + exe.string() + ", or the one above either" +
                           "; set HERTZDASH_DATA_DIR to the directory that holds them (the source tree's data/)");
}

PaperParameters load_paper_parameters(const std::filesystem::path& dir) {
  using namespace table_ranges;
  const CsvTable t1 = CsvTable::read(dir / "table1_dimensions.csv");
  const CsvTable t2 = CsvTable::read(dir / "table2_restitution.csv");
  const CsvTable t3 = CsvTable::read(dir / "table3_properties.csv");
  const CsvTable as = CsvTable::read(dir / "assumptions.csv");
  t1.require_columns({"body", "diameter_m", "length_m", "mass_kg", "provenance"});
  t2.require_columns({"rod", "e", "e_second", "zeta_printed", "provenance"});
  t3.require_columns({"body", "natural_frequency_hz", "E_Pa", "E_min_Pa", "E_max_Pa", "provenance"});
  as.require_columns({"parameter", "value", "unit", "provenance"});
  for (const auto& [table, key] : {std::pair{&t1, "body"}, {&t2, "rod"}, {&t3, "body"}, {&as, "parameter"}}) {
    table->require_rows();
    table->require_unique(key);
  }
  auto assumed = [&](const std::string& name, const ValueRange& range) {
    return as.number(as.find_row("parameter", name), "value", range);
  };

  PaperParameters p;
  p.gravity_mps2 = assumed("gravity_mps2", non_negative);
  p.rig = RigAssumptions{assumed("load_cell_stiffness_N_per_m", positive), assumed("load_cell_damping_ratio", damping_ratio),
                         assumed("rod_damping_ratio", damping_ratio)};
  const std::size_t b1 = t1.find_row("body", "nylon-ball"), b3 = t3.find_row("body", "nylon-ball");
  p.ball = BallData{t1.number(b1, "diameter_m", positive),
                    t1.number(b1, "length_m", positive),
                    t1.number(b1, "mass_kg", positive),
                    assumed("nylon_E_Pa", positive),
                    t3.number(b3, "E_min_Pa", positive),
                    t3.number(b3, "E_max_Pa", positive),
                    assumed("nylon_nu", poisson_ratio),
                    assumed("ball_radius_m", positive),
                    assumed("nylon_yield_stress_Pa", positive),
                    assumed("nylon_yield_stress_min_Pa", positive),
                    assumed("nylon_yield_stress_max_Pa", positive)};
  for (std::size_t r = 0; r < t2.rows(); ++r) {
    const std::string& name = t2.text(r, "rod");
    const std::size_t r1 = t1.find_row("body", name), r3 = t3.find_row("body", name);
    const bool steel = name.rfind("steel", 0) == 0;
    p.rods.push_back(RodData{name,
                             t1.number(r1, "diameter_m", positive),
                             t1.number(r1, "length_m", positive),
                             t1.number(r1, "mass_kg", positive),
                             t2.number(r, "e", restitution),
                             t2.number_or(r, "e_second", NAN, restitution),
                             t2.number(r, "zeta_printed", non_negative),
                             t3.number(r3, "natural_frequency_hz", positive),
                             t3.number(r3, "E_Pa", positive),
                             assumed(steel ? "steel_nu" : "duralumin_nu", poisson_ratio)});
  }
  p.uncertain_inputs = read_uncertain_inputs(as);  // after the values' own ranges, which say more
  return p;
}

DropTestSetup paper_setup(const PaperParameters& p, const std::string& rod_name, double height_m) {
  const RodData& rod = p.rod(rod_name);
  DropTestSetup s{};
  s.mass_kg = rod.mass_kg;
  s.ball_radius_m = p.ball.radius_m;
  s.ball = Material{p.ball.E_Pa, p.ball.nu};
  s.ball_yield_stress_Pa = p.ball.yield_stress_Pa;
  s.rod = Material{rod.E_Pa, rod.nu};
  s.restitution = rod.restitution;
  s.height_m = height_m;
  s.gravity_mps2 = p.gravity_mps2;
  s.rod_preset = rod_name;
  return s;
}

}  // namespace hertzdash
