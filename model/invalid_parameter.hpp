#pragma once
// Validation of physical input: every refusal carries the parameter's key, the value and its
// valid range, and each front end spells the key its own way (KeySpelling).
#include <cmath>
#include <stdexcept>
#include <string>
#include <string_view>

namespace hertzdash {

/// How a front end writes a parameter key: the key itself ("ball-E", a case file's spelling),
/// the command line's option ("--ball-E") or the Python keyword ("ball_E").
enum class KeySpelling { key, command_line, python };

/// Whether `text` is a parameter key: a letter, then letters, digits and hyphens. Anything else
/// (for example "rod length (Table 1)") describes a value that is no parameter and is shown as
/// it is in every spelling.
bool is_parameter_key(std::string_view text);

/// `key` written in `spelling` (text that is no key stays as it is): as declared, as an option
/// (--key), or as a Python keyword (hyphens as underscores, a word Python reserves with a trailing
/// underscore: `from` is from_).
std::string spell_key(std::string_view key, KeySpelling spelling);

/// A reference to the parameter `key` inside a range text: "`key`", which the refusal's
/// message() writes in the front end's own spelling ("`height` > 0" reads "--height > 0" on the
/// command line, "height > 0" in Python and in a case file). A bare backquoted word is always
/// read as a key: name a command with its program, hertzdash restitution, not as `restitution`.
std::string key_reference(std::string_view key);

/// Thrown for any invalid input. Carries {key, value, range}; what() is message(KeySpelling::key),
/// e.g. "invalid mass = -1: must be a finite number > 0 (kg)"; a front end shows message() in
/// its own spelling ("invalid --mass = -1: ...").
class InvalidParameter : public std::invalid_argument {
 public:
  /// key: the parameter's key, or a description of a value that is no parameter; range: what the
  /// value must be, other parameters written as key_reference()s.
  InvalidParameter(const std::string& key, const std::string& value, const std::string& range);
  std::string key;          ///< the parameter's key ("ball-E")
  std::string value;        ///< the offending value, as text
  std::string valid_range;  ///< what the value must be (the message's "must be ...")
  /// "invalid <key> = <value>: must be <range>", every key in `spelling`.
  std::string message(KeySpelling spelling) const;
};

/// `text` with each key_reference() in it written in `spelling`.
std::string spell_key_references(std::string_view text, KeySpelling spelling);

std::string format_value(double v);

/// Require a finite v > 0.
void require_positive(const std::string& key, double v, const std::string& unit);
/// Require a finite v >= 0.
void require_non_negative(const std::string& key, double v, const std::string& unit);
/// Require v in the open-closed interval (lo, hi].
void require_in_open_closed(const std::string& key, double v, double lo, double hi);
/// Require v in the open interval (lo, hi).
void require_in_open(const std::string& key, double v, double lo, double hi);

}  // namespace hertzdash
