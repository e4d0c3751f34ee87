#include "cli/option_suggestion.hpp"

#include <algorithm>
#include <string_view>
#include <vector>

namespace hertzdash::cli {

namespace {

/// Levenshtein distance: insertions, deletions and substitutions of one character.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::string unknown_options_message(const CLI::App& command, int argc, char** argv) {
  std::vector<std::string> names;  // the command's long option names, without "--"
  for (const CLI::Option* o : command.get_options())
    for (const std::string& name : o->get_lnames()) names.push_back(name);
  std::string message;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (!arg.starts_with("--") || arg.size() == 2) continue;
    const std::string name(arg.substr(2, arg.find('=') == std::string_view::npos ? std::string_view::npos
                                                                                 : arg.find('=') - 2));
    if (std::find(names.begin(), names.end(), name) != names.end()) continue;
    const std::size_t limit = std::max<std::size_t>(2, name.size() / 3);
    const std::string* best = nullptr;
    std::size_t best_distance = limit + 1;
    for (const std::string& candidate : names)
      if (const std::size_t d = edit_distance(name, candidate); d < best_distance) best = &candidate, best_distance = d;
    message += (message.empty() ? "" : "; ") + std::string("unknown option --") + name;
    if (best) message += ": did you mean --" + *best + "?";
  }
  return message;
}

}  // namespace hertzdash::cli
