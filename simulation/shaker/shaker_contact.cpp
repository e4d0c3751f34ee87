// The shaker's contact by law name (simulation/shaker/shaker_contact.hpp): one look-up; each
// registered law's contact is compiled in its own generated translation unit.
#include "hertzdash/simulation/shaker/shaker_contact.hpp"

#include "hertzdash/model/damping/registered_law_types.hpp"

#include <type_traits>

namespace hertzdash {

std::unique_ptr<ShakerContact> make_shaker_contact(std::string_view law, const DropTestSetup& setup,
                                                   const SolverSettings& solver, const HarmonicWallMotion& wall) {
  std::unique_ptr<ShakerContact> out;
  with_damping_law(law, [&]<class Law>(std::type_identity<Law>) { out = make_shaker_contact_of<Law>(setup, solver, wall); });
  return out;
}

}  // namespace hertzdash
