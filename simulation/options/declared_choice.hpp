#pragma once
// Whether a text is one of a declaration's choices: the one check of a text option's value,
// shared by the options every run is resolved from and the case file read before any run.
#include "hertzdash/model/parameter.hpp"

#include <string>

namespace hertzdash {

/// Whether `value` is one of `d.choices` (comma-separated, blanks after a comma ignored); a
/// declaration without choices takes any text.
bool is_declared_choice(const ParameterDecl& d, const std::string& value);

}  // namespace hertzdash
