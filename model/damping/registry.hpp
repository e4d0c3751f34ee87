#pragma once
// The registry of damping laws as data: each registered law's description, its declared inputs
// and the concepts it meets, by name and in registration order, without the law's type. Most code
// needs only this and includes no law; code that instantiates a template for each law includes
// model/damping/registered_law_types.hpp instead. Adding a law: its header in model/damping/laws/
// and its line in model/damping/registered_laws.cmake (model/README.md).
#include "hertzdash/model/damping/damping_law.hpp"

#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace hertzdash {

/// What the registry knows of one law.
struct RegisteredLaw {
  LawInfo info;
  ParameterDecls parameters;    ///< law_parameters<Law>(): the inputs it reads besides (e, v0, K, m)
  bool conservative;            ///< ConservativeLaw: returns all the energy it stores
  bool material_time_constant;  ///< MaterialTimeConstantLaw: damping by a material constant (parameters[0]), not by e
  bool root_polynomial;         ///< RootPolynomialLaw: offers force_of_root (the regularised integrators)
  /// The declaration of its material constant (its first input: kuwabara-kono's
  /// viscous-time-constant, lee-herrmann's damping-rate), or nullptr for a law without one.
  const ParameterDecl* material_constant() const { return material_time_constant ? &parameters.front() : nullptr; }
};

/// Every registered law, in registration order.
std::span<const RegisteredLaw> registered_law_table();

/// The registered law named `name`; InvalidParameter("damping", ...) naming the laws otherwise.
const RegisteredLaw& registered_law(std::string_view name);

/// Throws InvalidParameter("damping", name, ...) naming the registered laws.
[[noreturn]] void throw_unknown_law(std::string_view name);

/// Every registered law's description, in registration order.
std::vector<LawInfo> registered_laws();

/// Comma-separated names of the registered laws.
std::string registered_law_names();

/// The law used when none is named: the paper's (HongoPaper::info.name, checked where the table is
/// built, model/damping/registry.cpp).
inline constexpr std::string_view default_damping_law = "hongo";

}  // namespace hertzdash
