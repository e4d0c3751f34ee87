#pragma once
// The registered tangential contact models: a model is one header in model/tangential/ declaring
// its TangentialModelInfo (model/tangential/tangential_model.hpp) plus its line below. The rig
// `oblique` and every front end read this list.
#include "hertzdash/model/tangential/cattaneo_mindlin_mdr.hpp"
#include "hertzdash/model/tangential/linear_spring.hpp"
#include "hertzdash/model/tangential/mindlin_deresiewicz.hpp"
#include "hertzdash/model/tangential/mindlin_no_slip.hpp"
#include "hertzdash/model/tangential/mindlin_rescale.hpp"

#include <array>
#include <string>
#include <string_view>

namespace hertzdash {

inline constexpr std::array<const TangentialModelInfo*, 5> registered_tangential_models{
    &mindlin_no_slip,
    &mindlin_rescale,
    &mindlin_deresiewicz,
    &linear_spring,
    &cattaneo_mindlin_mdr,
};

/// The registered models' names, as a text input's choices ("a, b"); checked against the list
/// at compile time.
inline constexpr std::string_view tangential_model_choices = "mindlin-no-slip, mindlin-rescale, mindlin-deresiewicz, linear-spring, cattaneo-mindlin-mdr";

namespace detail {
consteval bool tangential_choices_match() {
  std::string_view rest = tangential_model_choices;
  for (std::size_t i = 0; i < registered_tangential_models.size(); ++i) {
    const std::string_view name = registered_tangential_models[i]->name;
    if (rest.substr(0, name.size()) != name) return false;
    rest.remove_prefix(name.size());
    if (i + 1 < registered_tangential_models.size()) {
      if (rest.substr(0, 2) != ", ") return false;
      rest.remove_prefix(2);
    }
  }
  return rest.empty();
}
static_assert(tangential_choices_match(), "tangential_model_choices must list registered_tangential_models in order");
}  // namespace detail

/// The registered models' names joined by `separator` (", " for a message, " " for gnuplot's
/// `for [m in models]`).
inline std::string registered_tangential_model_names(std::string_view separator) {
  std::string names;
  for (const TangentialModelInfo* m : registered_tangential_models) {
    if (!names.empty()) names += separator;
    names += m->name;
  }
  return names;
}

/// The model named `name`, or nullptr.
inline const TangentialModelInfo* find_tangential_model(std::string_view name) {
  for (const TangentialModelInfo* m : registered_tangential_models)
    if (m->name == name) return m;
  return nullptr;
}

}  // namespace hertzdash
