#pragma once
// Validation of physical input: every check names the parameter and its valid range.
#include <cmath>
#include <stdexcept>
#include <string>

namespace hertzdash {

/// Thrown for any physically invalid input. what() names the parameter, the
/// offending value and the valid range, e.g.
/// "invalid --mass = -1: must be a finite number > 0 (kg)".
class InvalidParameter : public std::invalid_argument {
 public:
  InvalidParameter(const std::string& name, const std::string& value, const std::string& range)
      : std::invalid_argument("invalid " + name + " = " + value + ": must be " + range),
        parameter(name),
        valid_range(range) {}
  std::string parameter;
  std::string valid_range;  ///< what the value must be (the message's "must be ...")
};

std::string format_value(double v);

/// Require a finite v > 0.
void require_positive(const std::string& name, double v, const std::string& unit);
/// Require a finite v >= 0.
void require_non_negative(const std::string& name, double v, const std::string& unit);
/// Require v in the open-closed interval (lo, hi].
void require_in_open_closed(const std::string& name, double v, double lo, double hi);
/// Require v in the open interval (lo, hi).
void require_in_open(const std::string& name, double v, double lo, double hi);
/// Require v > 0, allowing +infinity (a rigid body's modulus).
void require_positive_or_infinite(const std::string& name, double v, const std::string& unit);

}  // namespace hertzdash
