#include "hertzdash/model/damping/registry.hpp"

#include "hertzdash/model/damping/registered_law_types.hpp"
#include "hertzdash/model/invalid_parameter.hpp"

#include <algorithm>
#include <array>
#include <type_traits>

namespace hertzdash {

static_assert(default_damping_law == HongoPaper::info.name, "the default law is the paper's");

namespace {

template <DampingLaw Law> RegisteredLaw registry_entry() {
  return {Law::info, law_parameters<Law>(), ConservativeLaw<Law>, MaterialTimeConstantLaw<Law>, RootPolynomialLaw<Law>};
}

}  // namespace

std::span<const RegisteredLaw> registered_law_table() {
  static const auto table = []<class... L>(LawList<L...>) {
    return std::array<RegisteredLaw, sizeof...(L)>{registry_entry<L>()...};
  }(RegisteredLaws{});
  return table;
}

const RegisteredLaw& registered_law(std::string_view name) {
  const std::span<const RegisteredLaw> table = registered_law_table();
  const auto it = std::find_if(table.begin(), table.end(), [&](const RegisteredLaw& l) { return l.info.name == name; });
  if (it == table.end()) throw_unknown_law(name);
  return *it;
}

void throw_unknown_law(std::string_view name) {
  throw InvalidParameter("damping", std::string(name), "one of: " + registered_law_names());
}

std::vector<LawInfo> registered_laws() {
  std::vector<LawInfo> infos;
  for (const RegisteredLaw& law : registered_law_table()) infos.push_back(law.info);
  return infos;
}

std::string registered_law_names() {
  std::string names;
  for (const RegisteredLaw& law : registered_law_table())
    names += (names.empty() ? "" : ", ") + std::string(law.info.name);
  return names;
}

}  // namespace hertzdash
