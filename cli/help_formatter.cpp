#include "cli/help_formatter.hpp"

#include <algorithm>
#include <cstddef>
#include <sstream>
#include <string_view>
#include <vector>

namespace hertzdash::cli {

namespace {

// The position of the first of `separators` in `text` from `from` outside brackets and
// parentheses, or npos.
std::size_t find_outside_brackets(std::string_view text, std::initializer_list<std::string_view> separators,
                                  std::size_t from = 0) {
  int depth = 0;
  for (std::size_t i = from; i < text.size(); ++i) {
    if (depth == 0)
      for (std::string_view s : separators)
        if (text.substr(i, s.size()) == s) return i;
    const char c = text[i];
    if (c == '(' || c == '[') ++depth;
    else if ((c == ')' || c == ']') && depth > 0) --depth;
  }
  return std::string_view::npos;
}

// The parenthesis "(<label>...)" at the top level of `text` starting with `label`: its inner
// text without the label, and `text` without it; empty if there is none.
std::string take_parenthesis(std::string& text, std::string_view label) {
  for (std::size_t at = find_outside_brackets(text, {"("}), end = 0; at != std::string::npos;
       at = find_outside_brackets(text, {"("}, end + 1)) {
    int depth = 0;  // "(0, 1]" closes too
    for (end = at; end < text.size(); ++end) {
      if (text[end] == '(' || text[end] == '[') ++depth;
      else if ((text[end] == ')' || text[end] == ']') && --depth == 0) break;
    }
    if (end == text.size()) return {};
    if (std::string_view(text).substr(at + 1, label.size()) != label) continue;
    std::string inner = text.substr(at + 1 + label.size(), end - at - 1 - label.size());
    const std::size_t from = at > 0 && text[at - 1] == ' ' ? at - 1 : at;
    text.erase(from, end + 1 - from);
    return inner;
  }
  return {};
}

std::size_t words(std::string_view text) {
  std::size_t n = 1;
  for (char c : text) n += c == ' ';
  return n;
}

}  // namespace

std::string short_help(const std::string& help) {
  std::string body = help;
  std::string default_value = take_parenthesis(body, "default: ");
  const std::string choices = take_parenthesis(body, "one of: ");
  // The default without its source: "Table 1" of "Table 1; the paper's Table 1 (the rod's mass)".
  default_value = default_value.substr(0, find_outside_brackets(default_value, {"; "}));
  // The first clause; a short label before a colon ("Virtual measurement: ...") is kept with
  // the clause after it, a choice's name ("soft: the contact law ...") is left to the choices.
  std::string summary = body.substr(0, find_outside_brackets(body, {"; ", ": "}));
  if (summary.size() < body.size() && body.compare(summary.size(), 2, ": ") == 0 && words(summary) <= 2) {
    const bool choice_name = choices.find(summary) != std::string::npos;
    const std::size_t rest = summary.size() + 2;
    const std::size_t end = find_outside_brackets(body, {"; ", ": "}, rest);
    summary = choice_name ? std::string("One of") : summary + ": " + body.substr(rest, end - rest);
  }
  // A long list of values or a long default is left to `hertzdash parameters`: one line each.
  constexpr std::size_t longest_choices = 60, longest_default = 32;
  if (choices.size() > longest_choices) {
    const std::size_t n = 1 + static_cast<std::size_t>(std::count(choices.begin(), choices.end(), ','));
    return summary + (summary == "One of" ? " " : " (one of ") + std::to_string(n) + " values" + (summary == "One of" ? "" : ")") +
           (default_value.empty() || default_value.size() > longest_default ? "" : " (default: " + default_value + ")");
  }
  if (default_value.size() > longest_default) default_value.clear();
  std::ostringstream out;
  out << summary;
  if (choices.find(',') != std::string::npos) out << (summary == "One of" ? ": " : " (one of: ") << choices << (summary == "One of" ? "" : ")");
  if (!default_value.empty()) out << " (default: " << default_value << ")";
  return out.str();
}

ShortHelpFormatter::ShortHelpFormatter() { column_width(32); }

std::string ShortHelpFormatter::make_option_desc(const CLI::Option* opt) const {
  std::string text = short_help(opt->get_description());
  // "--bounces INT=5": CLI11 shows the default already.
  if (const std::size_t at = text.rfind(" (default: "); at != std::string::npos && !opt->get_default_str().empty())
    text.erase(at);
  return text;
}

std::string ShortHelpFormatter::make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const {
  if (mode != CLI::AppFormatMode::Normal || app->get_parent() == nullptr) return CLI::Formatter::make_help(app, name, mode);
  struct Group {
    std::string heading, options;  // the options one a line each
    std::size_t lines = 0;
    std::string names;              // their names, comma-separated
    bool switched_on = false;       // by an option its heading names
    bool collapsed = false;
  };
  std::vector<Group> groups;
  for (const std::string& heading : app->get_groups()) {
    const std::vector<const CLI::Option*> options = app->get_options([&](const CLI::Option* o) {
      return o->get_group() == heading && o->nonpositional() && o != app->get_help_ptr();
    });
    if (heading.empty() || options.empty()) continue;
    Group g{heading, {}, 0, {}, false, false};
    g.switched_on = heading.find("(--") != std::string::npos;
    for (const CLI::Option* o : options) {
      g.options += make_option(o, false);
      g.names += (g.names.empty() ? "" : ", ") + make_option_name(o, false) + make_option_opts(o);
    }
    for (char c : g.options) g.lines += c == '\n';
    groups.push_back(std::move(g));
  }
  std::string usage = make_usage(app, name);
  usage.insert(usage.find('\n'), "    (each option in full: hertzdash parameters)");
  const std::string head = make_description(app) + usage;
  std::size_t lines = 0;
  for (char c : head) lines += c == '\n';
  for (const Group& g : groups) lines += 2 + g.lines;  // a blank line and the heading
  for (auto g = groups.rbegin(); g != groups.rend() && lines > max_help_lines; ++g)
    if (g->switched_on) g->collapsed = true, lines -= g->lines - 1;
  std::string out = head;
  for (const Group& g : groups)
    out += "\n" + g.heading + (g.collapsed ? ": " + g.names + "\n" : ":\n" + g.options);
  // A command of subcommands (`orbit RIG`): each, with its description.
  if (const std::vector<const CLI::App*> subs = app->get_subcommands([](const CLI::App*) { return true; }); !subs.empty())
    out += make_subcommands(app, mode);
  return out;
}

}  // namespace hertzdash::cli
