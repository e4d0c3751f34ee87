// `models --json` (simulation/reports/run_reports.hpp): one entry per registered damping law, its
// citation, formula, coefficients, validity and character.
#include "hertzdash/simulation/reports/run_reports.hpp"

#include <type_traits>

namespace hertzdash {

nlohmann::ordered_json registered_laws_json() {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for_each_damping_law([&]<class Law>(std::type_identity<Law>) {
    const LawInfo& l = Law::info;
    list.push_back({{"name", l.name},
                    {"citation", l.citation},
                    {"formula", l.formula},
                    {"coefficients", l.coefficients},
                    {"validity", l.validity},
                    {"force_continuous_at_onset", l.force_continuous_at_onset},
                    {"dissipative", !ConservativeLaw<Law>}});
  });
  return list;
}

}  // namespace hertzdash
