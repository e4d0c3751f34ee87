#include "hertzdash/model/damping/registry.hpp"

#include "hertzdash/model/invalid_parameter.hpp"

namespace hertzdash {

std::string registered_law_names() {
  std::string names;
  for (const LawInfo& info : registered_laws()) names += (names.empty() ? "" : ", ") + std::string(info.name);
  return names;
}

void throw_unknown_law(std::string_view name) {
  throw InvalidParameter("damping", std::string(name), "one of: " + registered_law_names());
}

}  // namespace hertzdash
