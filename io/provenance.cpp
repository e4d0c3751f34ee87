#include "hertzdash/io/provenance.hpp"

namespace hertzdash {

const char* version() { return HERTZDASH_VERSION; }

std::string provenance_header(const std::string& what, const Parameters& parameters) {
  std::string h = "# contents: " + what + "\n# generator: hertzdash " HERTZDASH_VERSION "\n# git_revision: ";
  h += git_revision();
  h += "\n";
  for (const auto& [name, value] : parameters) h += "# " + name + ": " + value + "\n";
  return h;
}

}  // namespace hertzdash
