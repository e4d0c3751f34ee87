#pragma once
// The DEM benchmark tests 1 and 2 of Chung & Ooi (2011) as drop tests, and their digitised
// reference curves (data/external/chung-ooi-2011/: parameters.csv, the four .dat files and
// README.md, which states where they come from).
//
// H. Chung, J. Y. Ooi, Granular Matter 13 (2011) 643-656: test 1 is the undamped normal
// impact of two identical glass spheres at a relative speed of 20 m/s, test 2 that of an
// aluminium alloy sphere on a rigid flat at 0.2 m/s. Along the line of centres each is one
// degree of freedom, the overlap x of the two bodies, with
//   m* x'' = -(4/3) E* sqrt(R*) x^{3/2},  x(0) = 0,  x'(0) = v,
// m* = m1 m2 / (m1 + m2), R* = R1 R2 / (R1 + R2), 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2:
// exactly the drop test's rigid-rod model (model/drop_test_setup.hpp) without gravity, once the
// benchmark's bodies are mapped onto the drop test's names:
//   benchmark                                  DropTestSetup
//   effective mass m*                          mass_kg (the moving "rod")
//   effective radius R*                        ball_radius_m (the "hemisphere")
//   the sphere's E, nu                         ball
//   what it strikes: the second sphere's E,    rod (the "rod's flat end": only its elastic
//     nu (test 1) or the rigid flat (test 2)     constants enter, through E*)
//   relative speed v                           impact_velocity_mps (height 0, gravity 0)
// hertz_stiffness() then gives K = (4/3) E* sqrt(R*), the benchmark's. The curves are read
// in SI units (the files hold um or us against kN).
#include "hertzdash/io/csv_table.hpp"
#include "hertzdash/io/decimal_number.hpp"
#include "hertzdash/model/drop_test_setup.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/paper/table_ranges.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <optional>
#include <numbers>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

namespace hertzdash {

/// The relative L1 error sum |run - reference| / sum |reference| by which Kratos's Chung_Ooi_class
/// compares its DEM with a digitised curve, accumulated point by point.
struct KratosL1Error {
  double difference = 0, reference = 0;
  void add(double run, double reference_value) {
    difference += std::abs(run - reference_value);
    reference += std::abs(reference_value);
  }
  double value() const { return difference / reference; }
};

/// One benchmark test, a row of parameters.csv (SI units).
struct ChungOoiTest {
  std::string name;             ///< test1, test2
  std::string description;
  Material sphere;              ///< the sphere's E [Pa] and nu
  double density_kgpm3;
  double radius_m;              ///< the sphere's radius
  bool rigid_flat;              ///< counterpart: rigid-flat (true) or identical-sphere (false)
  double relative_speed_mps;    ///< approach speed of the two bodies
  double effective_radius_m;    ///< R*
  double effective_mass_kg;     ///< m*
};

/// data/external/chung-ooi-2011 below the data directory.
inline std::filesystem::path chung_ooi_data_dir(const std::filesystem::path& data_dir = default_data_dir()) {
  return data_dir / "external" / "chung-ooi-2011";
}

/// The tests of parameters.csv in `dir`; throws DataError naming file, line and column of a
/// defect: a value out of its range (E, density, radii, speed, masses > 0, nu in (-1, 0.5)), an
/// unknown counterpart, or an effective radius or mass other than the one the sphere's radius,
/// density and counterpart give (R* = R/2, m* = m/2 for two identical spheres; R, m on a flat;
/// m = density (4/3) pi R^3), to 1e-12 relative.
inline std::vector<ChungOoiTest> load_chung_ooi_tests(const std::filesystem::path& dir = chung_ooi_data_dir()) {
  using namespace table_ranges;
  const CsvTable t = CsvTable::read(dir / "parameters.csv");
  t.require_columns({"test", "description", "E_Pa", "nu", "density_kgpm3", "radius_m", "counterpart",
                     "relative_speed_mps", "effective_radius_m", "effective_mass_kg", "source"});
  t.require_rows();
  t.require_unique("test");
  std::vector<ChungOoiTest> tests;
  for (std::size_t r = 0; r < t.rows(); ++r) {
    const std::string& counterpart = t.text(r, "counterpart");
    if (counterpart != "rigid-flat" && counterpart != "identical-sphere")
      throw DataError(t.row_location(r) + ": counterpart '" + counterpart + "' is neither rigid-flat nor identical-sphere");
    const ChungOoiTest test{t.text(r, "test"),
                            t.text(r, "description"),
                            Material{t.number(r, "E_Pa", positive), t.number(r, "nu", poisson_ratio)},
                            t.number(r, "density_kgpm3", positive),
                            t.number(r, "radius_m", positive),
                            counterpart == "rigid-flat",
                            t.number(r, "relative_speed_mps", positive),
                            t.number(r, "effective_radius_m", positive),
                            t.number(r, "effective_mass_kg", positive)};
    const double share = test.rigid_flat ? 1.0 : 0.5;  // of the sphere's radius and mass
    const double mass_kg = test.density_kgpm3 * 4.0 / 3.0 * std::numbers::pi * std::pow(test.radius_m, 3);
    for (const auto& [column, value, expected] : {std::tuple{"effective_radius_m", test.effective_radius_m, share * test.radius_m},
                                                  std::tuple{"effective_mass_kg", test.effective_mass_kg, share * mass_kg}})
      if (!(std::abs(value - expected) <= 1e-12 * expected))
        throw DataError(fmt::format("{}: {} is not {:.17g}, what radius_m, density_kgpm3 and the counterpart {} give",
                                    t.field_location(r, column), t.text(r, column), expected, counterpart));
    tests.push_back(test);
  }
  return tests;
}

/// parameters.csv's row `name`, the table read once.
inline const ChungOoiTest& chung_ooi_row(const std::string& name) {
  static const std::vector<ChungOoiTest> tests = load_chung_ooi_tests();
  for (const ChungOoiTest& t : tests)
    if (t.name == name) return t;
  throw DataError("data/external/chung-ooi-2011/parameters.csv has no row " + name);
}

/// The test as an undamped drop test (restitution 1; run it with the law "none"), mapped as above.
inline DropTestSetup chung_ooi_setup(const ChungOoiTest& test) {
  DropTestSetup s{};
  s.mass_kg = test.effective_mass_kg;
  s.ball_radius_m = test.effective_radius_m;
  s.ball = test.sphere;
  s.rod = test.rigid_flat ? Material{std::numeric_limits<double>::infinity(), test.sphere.nu} : test.sphere;
  s.restitution = 1.0;
  s.height_m = 0.0;
  s.impact_velocity_mps = test.relative_speed_mps;
  s.gravity_mps2 = 0.0;
  validate(s);
  return s;
}

/// A point of a curve: abscissa (overlap [m] or time [s]) and force [N].
struct CurvePoint {
  double abscissa;
  double force_N;
};

/// A digitised curve's points in the units of its file: two columns separated by blanks. Numbers
/// are decimal (io/decimal_number.hpp). Throws DataError naming FILE:LINE (and :COL for a field
/// that is not a decimal number or is out of the range of a double) on a line that is not two
/// numbers.
inline std::vector<std::array<double, 2>> read_two_columns(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw DataError("cannot read " + file.string());
  constexpr const char* blanks = " \t\r";
  std::vector<std::array<double, 2>> points;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    const std::string where = file.string() + ":" + std::to_string(n);
    std::vector<double> values;
    for (std::size_t begin = line.find_first_not_of(blanks); begin != std::string::npos;) {
      const std::size_t end = std::min(line.find_first_of(blanks, begin), line.size());
      const std::string_view field = std::string_view(line).substr(begin, end - begin);
      const std::optional<double> v = parse_decimal(field);
      if (!v) throw DataError(where + ":" + std::to_string(begin + 1) + ": " + decimal_refusal(field));
      values.push_back(*v);
      begin = line.find_first_not_of(blanks, end);
    }
    if (values.empty()) continue;
    if (values.size() != 2)
      throw DataError(where + ": expected two numbers, got " + std::to_string(values.size()) + ": '" + line + "'");
    points.push_back({values[0], values[1]});
  }
  if (points.empty()) throw DataError(file.string() + ": no points");
  return points;
}

/// A digitised force curve of tests 1 and 2: um or us against kN, returned in m or s against N
/// (read_two_columns).
inline std::vector<CurvePoint> read_digitised_curve(const std::filesystem::path& file) {
  std::vector<CurvePoint> points;
  for (const auto& [a, F] : read_two_columns(file)) points.push_back({a * 1e-6, F * 1e3});
  return points;
}

/// How far digitised points lie from a model curve F(a), in % of full scale (a_full, F_full):
///  - vertical: (F_i - F(a_i)) / F_full, the force error at the digitised abscissa;
///  - distance: the smallest max(|a - a_i| / a_full, |F(a) - F_i| / F_full) over the curve, how far
///    the point must move, in both columns at once, to lie on it. Digitisation errs in both
///    columns; where the curve is steep a small abscissa error is a large vertical one, so a point
///    is "within u % of full scale in both columns" exactly when its distance is <= u.
/// The distance is taken over `samples` + 1 points of the curve evenly spread over [a_lo, a_hi]
/// (error at most half their spacing, (a_hi - a_lo) / (2 samples a_full)).
struct CurveDeviation {
  int points = 0;
  double max_vertical_pct = 0, rms_vertical_pct = 0;
  double max_distance_pct = 0, rms_distance_pct = 0;
  int vertical_over = 0;  ///< points whose |vertical| exceeds the threshold given
  int distance_over = 0;  ///< points whose distance exceeds it
  std::vector<double> vertical_pct, distance_pct;  ///< per point
};

inline CurveDeviation curve_deviation(const std::vector<CurvePoint>& digitised, const std::function<double(double)>& model,
                                      double a_lo, double a_hi, double a_full, double force_full, double threshold_pct,
                                      int samples = 20000) {
  std::vector<CurvePoint> curve(samples + 1);
  for (int k = 0; k <= samples; ++k) {
    const double a = a_lo + (a_hi - a_lo) * k / samples;
    curve[k] = {a, model(a)};
  }
  CurveDeviation d;
  d.points = static_cast<int>(digitised.size());
  double sum_v = 0, sum_d = 0;
  for (const CurvePoint& p : digitised) {
    const double v = 100 * (p.force_N - model(p.abscissa)) / force_full;
    double dist = std::numeric_limits<double>::infinity();
    for (const CurvePoint& c : curve)
      dist = std::min(dist, 100 * std::max(std::abs(c.abscissa - p.abscissa) / a_full,
                                           std::abs(c.force_N - p.force_N) / force_full));
    d.vertical_pct.push_back(v);
    d.distance_pct.push_back(dist);
    d.max_vertical_pct = std::max(d.max_vertical_pct, std::abs(v));
    d.max_distance_pct = std::max(d.max_distance_pct, dist);
    sum_v += v * v;
    sum_d += dist * dist;
    d.vertical_over += std::abs(v) > threshold_pct;
    d.distance_over += dist > threshold_pct;
  }
  d.rms_vertical_pct = std::sqrt(sum_v / d.points);
  d.rms_distance_pct = std::sqrt(sum_d / d.points);
  return d;
}

}  // namespace hertzdash
