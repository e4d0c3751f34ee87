#pragma once
// A command's --help in one screen (issue 46): each option on one line with a short description
// and its default, cut from its declared help (simulation/options: the sentence up to its first
// "; " or ": ", the valid values of a text option, the default without its source); groups
// separated by one blank line; the usage line points to `hertzdash parameters`, which prints
// every option's declaration in full (docs/parameters.md). A help longer than max_help_lines lists a
// group that another option switches on (its heading names it: "Elastic rod and load cell
// (--rod-model elastic)") by its options' names on one line, the last such group first.
#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>

namespace hertzdash::cli {

/// The short form of a declared option's help text: "Mass of the falling body [kg] (default:
/// Table 1)" from "Mass of the falling body [kg]: the paper's rod, or a dropped ball; a finite
/// number > 0 (kg) (default: Table 1; the paper's Table 1 (the rod's mass))".
std::string short_help(const std::string& help);

/// The most lines of a command's help.
inline constexpr std::size_t max_help_lines = 45;

/// CLI11's formatter, for a command's help as above (the program's own help is CLI11's).
class ShortHelpFormatter : public CLI::Formatter {
 public:
  ShortHelpFormatter();
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override;
  std::string make_option_desc(const CLI::Option* opt) const override;
};

}  // namespace hertzdash::cli
