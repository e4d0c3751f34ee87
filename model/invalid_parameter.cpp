#include "hertzdash/model/invalid_parameter.hpp"

#include <fmt/format.h>

namespace hertzdash {

std::string format_value(double v) { return fmt::format("{}", v); }

void require_positive(const std::string& name, double v, const std::string& unit) {
  if (!(std::isfinite(v) && v > 0)) throw InvalidParameter(name, format_value(v), "a finite number > 0 (" + unit + ")");
}

void require_non_negative(const std::string& name, double v, const std::string& unit) {
  if (!(std::isfinite(v) && v >= 0)) throw InvalidParameter(name, format_value(v), "a finite number >= 0 (" + unit + ")");
}

void require_in_open_closed(const std::string& name, double v, double lo, double hi) {
  if (!(v > lo && v <= hi)) throw InvalidParameter(name, format_value(v), fmt::format("in ({}, {}]", lo, hi));
}

void require_in_open(const std::string& name, double v, double lo, double hi) {
  if (!(v > lo && v < hi)) throw InvalidParameter(name, format_value(v), fmt::format("in ({}, {})", lo, hi));
}

void require_positive_or_infinite(const std::string& name, double v, const std::string& unit) {
  if (!(v > 0)) throw InvalidParameter(name, format_value(v), "a number > 0 or inf (" + unit + ")");
}

}  // namespace hertzdash
