// The table of the registered laws' runs (simulation/run/law_runs.hpp): one look-up by name;
// each law's entry is compiled in its own generated translation unit.
#include "hertzdash/simulation/run/law_runs.hpp"

#include "hertzdash/model/damping/registered_law_types.hpp"

#include <type_traits>

namespace hertzdash {

const LawRuns& law_runs(std::string_view law) {
  const LawRuns* runs = nullptr;
  with_damping_law(law, [&]<class Law>(std::type_identity<Law>) { runs = &law_runs_of<Law>(); });
  return *runs;
}

}  // namespace hertzdash
