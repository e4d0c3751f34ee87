#pragma once
// The reference of every option, generated from the declarations (simulation/options/run_options.hpp, and each rig's, simulation/rigs/rig.hpp):
// `hertzdash parameters` prints it, docs/parameters.md is its Markdown, and a test compares the
// two, so the page cannot fall behind a new parameter.
#include <string>

namespace hertzdash {

/// docs/parameters.md: one table row per option (key and its three spellings, unit, valid
/// values, default and its source, what reads it, fittable, help), then each rig's own options.
std::string parameter_reference_markdown();

}  // namespace hertzdash
