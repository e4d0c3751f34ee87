// The damper's soft contact by law name (simulation/shaker/damper_soft_contact.hpp): one look-up;
// each registered law's is compiled in its own generated translation unit.
#include "hertzdash/simulation/shaker/damper_soft_contact.hpp"

#include "hertzdash/model/damping/registered_law_types.hpp"

#include <type_traits>

namespace hertzdash {

std::unique_ptr<DamperSoftContact> make_damper_soft_contact(std::string_view law, const DropTestSetup& setup,
                                                            const SolverSettings& solver,
                                                            const ForcedOscillator& primary) {
  std::unique_ptr<DamperSoftContact> out;
  with_damping_law(law, [&]<class Law>(std::type_identity<Law>) {
    out = make_damper_soft_contact_of<Law>(setup, solver, primary);
  });
  return out;
}

}  // namespace hertzdash
