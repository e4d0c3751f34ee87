// `models --json` (simulation/reports/run_reports.hpp): one entry per registered damping law, its
// citation, formula, coefficients, validity and character.
#include "hertzdash/simulation/reports/run_reports.hpp"

#include "hertzdash/model/damping/registry.hpp"

namespace hertzdash {

nlohmann::ordered_json registered_laws_json() {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const RegisteredLaw& law : registered_law_table()) {
    const LawInfo& l = law.info;
    list.push_back({{"name", l.name},
                    {"citation", l.citation},
                    {"formula", l.formula},
                    {"coefficients", l.coefficients},
                    {"validity", l.validity},
                    {"force_continuous_at_onset", l.force_continuous_at_onset},
                    {"dissipative", !law.conservative}});
  }
  return list;
}

}  // namespace hertzdash
