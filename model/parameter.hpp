#pragma once
// One declaration per input (docs/parameters.md): its key, unit, valid range, default and where
// the default comes from, whether it can be fitted, and its help text. The model declares the
// inputs it reads (the drop test's below in drop_test_parameters.hpp, the elastic rod's in
// elastic_rod_setup.hpp, a damping law's in its own header); simulation/options/run_options.cpp binds
// each to the option a front end sets, and the command line, Python, case files, the fit's
// bounds, the refusals and docs/parameters.md are all generated from these declarations.
#include "hertzdash/model/invalid_parameter.hpp"

#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <string_view>

namespace hertzdash {

/// The valid values of a numeric input.
struct NumberRange {
  enum class Kind {
    positive,              ///< finite v > 0
    non_negative,          ///< finite v >= 0
    positive_or_infinite,  ///< v > 0, +inf allowed (a rigid body)
    open,                  ///< lo < v < hi
    open_closed,           ///< lo < v <= hi
    closed_open,           ///< lo <= v < hi
    integer,               ///< an integer in [lo, hi]
  };
  Kind kind = Kind::positive;
  double lo = 0;
  double hi = std::numeric_limits<double>::infinity();

  static constexpr NumberRange positive() { return {Kind::positive}; }
  static constexpr NumberRange non_negative() { return {Kind::non_negative}; }
  static constexpr NumberRange positive_or_infinite() { return {Kind::positive_or_infinite}; }
  static constexpr NumberRange open(double lo, double hi) { return {Kind::open, lo, hi}; }
  static constexpr NumberRange open_closed(double lo, double hi) { return {Kind::open_closed, lo, hi}; }
  static constexpr NumberRange closed_open(double lo, double hi) { return {Kind::closed_open, lo, hi}; }
  static constexpr NumberRange integer(double lo, double hi) { return {Kind::integer, lo, hi}; }

  /// Whether v is valid (NaN never is).
  bool contains(double v) const;
  /// What a value must be, as a refusal says it: "a finite number > 0 (kg)", "in (0, 1]".
  std::string text(std::string_view unit) const;
};

/// What kind of value an input takes.
enum class ParameterType {
  number,  ///< a decimal number within `range`
  text,    ///< one of `choices`
  flag,    ///< present or absent (a command-line flag, a boolean keyword or case key)
};

/// One input of the model or of a run.
struct ParameterDecl {
  std::string_view key{};             ///< the case-file spelling: "ball-E" (--ball-E, ball_E)
  ParameterType type = ParameterType::number;
  std::string_view unit{};            ///< SI unit as text ("m/s", "N/m^1.5"); empty: dimensionless or text
  std::string_view column_unit{};     ///< the unit in a column name ("mps" gives "impact_velocity_mps")
  NumberRange range{};                ///< valid values of a number (unused for a text input)
  std::string_view choices{};         ///< a text input's valid values, "a, b, c"; empty for a number
  std::string_view default_value{};   ///< the default as a user reads it ("0.02", "Table 2", "unset")
  /// The default of a number a law reads through DampingSettings::number() (NaN: none; the
  /// other inputs take theirs from the paper's tables, simulation/paper/paper_parameters.hpp).
  double default_number = std::numeric_limits<double>::quiet_NaN();
  std::string_view default_source{};  ///< where it comes from ("the paper", "data/assumptions.csv", "computed: ...")
  std::string_view help{};            ///< one sentence, units in brackets
  bool fittable = false;            ///< a continuous input `fit --fit` may estimate
};

/// `d` with another default, for an input two rigs share with different defaults.
constexpr ParameterDecl with_default(ParameterDecl d, std::string_view value, double number, std::string_view source) {
  d.default_value = value, d.default_number = number, d.default_source = source;
  return d;
}

/// Throws InvalidParameter{p.key, v, p.range} unless p.range contains v.
void require_in_range(const ParameterDecl& p, double v);

/// A declaration list (a law's, a rig's).
using ParameterDecls = std::span<const ParameterDecl>;

}  // namespace hertzdash
