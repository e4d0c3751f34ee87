#include "hertzdash/model/parameter.hpp"

#include <fmt/format.h>

namespace hertzdash {

bool NumberRange::contains(double v) const {
  switch (kind) {
    case Kind::positive: return std::isfinite(v) && v > 0;
    case Kind::non_negative: return std::isfinite(v) && v >= 0;
    case Kind::positive_or_infinite: return v > 0;
    case Kind::open: return v > lo && v < hi;
    case Kind::open_closed: return v > lo && v <= hi;
    case Kind::closed_open: return v >= lo && v < hi;
    case Kind::integer: return v >= lo && v <= hi && v == std::floor(v);
  }
  return false;
}

std::string NumberRange::text(std::string_view unit) const {
  const std::string u = unit.empty() ? "" : fmt::format(" ({})", unit);
  switch (kind) {
    case Kind::positive: return "a finite number > 0" + u;
    case Kind::non_negative: return "a finite number >= 0" + u;
    case Kind::positive_or_infinite: return "a number > 0 or inf" + u;
    case Kind::open: return fmt::format("in ({}, {})", lo, hi);
    case Kind::open_closed: return fmt::format("in ({}, {}]", lo, hi);
    case Kind::closed_open: return fmt::format("in [{}, {})", lo, hi);
    case Kind::integer: return fmt::format("an integer in [{}, {}]", lo, hi);
  }
  return {};
}

void require_in_range(const ParameterDecl& p, double v) {
  if (!p.range.contains(v)) throw InvalidParameter(std::string(p.key), format_value(v), p.range.text(p.unit));
}

}  // namespace hertzdash
