#pragma once
// Helpers for studies that run every rod of Table 1: names for tables and LaTeX
// macros, and the provenance parameters shared by all rods of a study.
#include "hertzdash/simulation/options/run_description.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"
#include "hertzdash/simulation/run/impact_simulator.hpp"

#include <algorithm>
#include <cctype>
#include <string>

namespace hertzdash {

/// "steel" -> "Steel", "duralumin-c" -> "Duralumin C" (for tables and captions).
inline std::string rod_label(const std::string& rod) {
  if (rod.rfind("duralumin-", 0) == 0)
    return "Duralumin " + std::string(1, static_cast<char>(std::toupper(static_cast<unsigned char>(rod.back()))));
  std::string label = rod;
  if (!label.empty()) label[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(label[0])));
  return label;
}

/// "duralumin-c" -> "DuraluminC": a rod's part of a LaTeX macro name (letters only).
inline std::string rod_macro_tag(const std::string& rod) {
  std::string label = rod_label(rod), tag;
  std::copy_if(label.begin(), label.end(), std::back_inserter(tag), [](unsigned char c) { return std::isalpha(c); });
  return tag;
}

/// The run description of describe_run() without the entries that differ between rods
/// (mass, rod modulus and Poisson ratio, restitution) or that the study varies
/// (`varied`, e.g. "height_m"), plus a line saying where the per-rod values come from.
inline Parameters all_rods_parameters(const PaperParameters& paper, const SolverSettings& solver, double height_m,
                                      const std::vector<std::string>& varied = {}) {
  Parameters p = describe_run(paper_setup(paper, paper.rods.front().name, height_m), "hongo", solver);
  std::vector<std::string> per_rod{"mass_kg", "rod_E_Pa", "rod_nu", "restitution"};
  per_rod.insert(per_rod.end(), varied.begin(), varied.end());
  std::erase_if(p, [&](const auto& entry) {
    return std::find(per_rod.begin(), per_rod.end(), entry.first) != per_rod.end();
  });
  p.emplace_back("per_rod", "mass_kg, rod_E_Pa, rod_nu, restitution from Tables 1-3 and data/assumptions.csv");
  return p;
}

}  // namespace hertzdash
