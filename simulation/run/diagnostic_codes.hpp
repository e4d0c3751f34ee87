#pragma once
// The notes and warnings a result can carry, as codes: one bit each in a DiagnosticSet that
// every ImpactSummary holds (set by ImpactSimulator::run, simulation/run/result_checks.hpp), so a
// sweep of millions of impacts keeps them at no allocation; the messages are built only when a
// front end prints them (simulation/reports/diagnostic_messages.hpp). docs/json-output.md lists them.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace hertzdash {

enum class Diagnostic : std::uint8_t {
  integrator_fallback,  ///< note: the integrator asked for cannot run this law or set-up; its fall-back ran
  stability_limit,      ///< note: the elastic rod's stability limit shortened the fixed step below --dt
  under_resolved,       ///< warning: a fixed step gave fewer steps per contact than the convergence study needs
  loose_tolerance,      ///< warning: --rtol above loose_rtol_limit (simulation/run/result_checks.hpp)
  yield_onset,          ///< warning: the Hertz peak pressure exceeds the onset of yield
  large_deformation,    ///< warning: the deformation is not small against the ball radius
  not_separated,        ///< warning: the rod did not separate (e_effective, contact time undefined)
  no_rebound,           ///< warning: the elastic rod separated still moving down (e_effective 0, no bounce)
  preset_restitution,   ///< note: the input e is the preset rod's, measured on a pair the run changed
  rig_warning,          ///< warning: a rig's run warned (its text: `hertzdash RIG` with the run's inputs)
};

struct DiagnosticInfo {
  Diagnostic code;
  std::string_view name;  ///< as in JSON "code", the sweep's warnings column and Python
  std::string_view kind;  ///< "note" (how the run was made) or "warning" (a result to distrust)
};

/// Every code, in enumerator order (the order front ends report them in).
inline constexpr std::array<DiagnosticInfo, 10> diagnostic_table{{
    {Diagnostic::integrator_fallback, "integrator_fallback", "note"},
    {Diagnostic::stability_limit, "stability_limit", "note"},
    {Diagnostic::under_resolved, "under_resolved", "warning"},
    {Diagnostic::loose_tolerance, "loose_tolerance", "warning"},
    {Diagnostic::yield_onset, "yield_onset", "warning"},
    {Diagnostic::large_deformation, "large_deformation", "warning"},
    {Diagnostic::not_separated, "not_separated", "warning"},
    {Diagnostic::no_rebound, "no_rebound", "warning"},
    {Diagnostic::preset_restitution, "preset_restitution", "note"},
    {Diagnostic::rig_warning, "rig_warning", "warning"},
}};

constexpr const DiagnosticInfo& diagnostic_info(Diagnostic d) { return diagnostic_table[static_cast<std::size_t>(d)]; }

/// A set of codes, one bit each.
class DiagnosticSet {
 public:
  constexpr void add(Diagnostic d) noexcept { bits_ = static_cast<std::uint16_t>(bits_ | bit(d)); }
  constexpr bool has(Diagnostic d) const noexcept { return (bits_ & bit(d)) != 0; }
  constexpr bool empty() const noexcept { return bits_ == 0; }
  constexpr std::uint16_t bits() const noexcept { return bits_; }
  static constexpr DiagnosticSet from_bits(std::uint16_t bits) noexcept {
    DiagnosticSet s;
    s.bits_ = bits;
    return s;
  }
  friend constexpr bool operator==(DiagnosticSet, DiagnosticSet) = default;

 private:
  static constexpr std::uint16_t bit(Diagnostic d) noexcept {
    return static_cast<std::uint16_t>(1u << static_cast<unsigned>(d));
  }
  std::uint16_t bits_ = 0;
};

/// The names of the codes of `s` in table order, separated by spaces ("" for none): the
/// sweep's warnings column.
inline std::string diagnostic_names(DiagnosticSet s) {
  std::string out;
  for (const DiagnosticInfo& d : diagnostic_table) {
    if (!s.has(d.code)) continue;
    if (!out.empty()) out += ' ';
    out += d.name;
  }
  return out;
}

}  // namespace hertzdash
