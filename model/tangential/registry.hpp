#pragma once
// The registered tangential contact models: a model is one header in model/tangential/ declaring
// its TangentialModelInfo (model/tangential/tangential_model.hpp) plus its line below. The rig
// `oblique` and every front end read this list.
#include "hertzdash/model/tangential/linear_spring.hpp"
#include "hertzdash/model/tangential/mindlin_no_slip.hpp"

#include <array>
#include <string_view>

namespace hertzdash {

inline constexpr std::array<const TangentialModelInfo*, 2> registered_tangential_models{
    &mindlin_no_slip,
    &linear_spring,
};

/// The model named `name`, or nullptr.
inline const TangentialModelInfo* find_tangential_model(std::string_view name) {
  for (const TangentialModelInfo* m : registered_tangential_models)
    if (m->name == name) return m;
  return nullptr;
}

}  // namespace hertzdash
