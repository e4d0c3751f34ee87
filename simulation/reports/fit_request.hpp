#pragma once
// `hertzdash fit`'s own options, declared once (key, type, unit, range, default, help, and which
// kinds of data read each), and the request they make: the command line builds its options from
// the table (cli/fit_command.cpp), Python's fit functions pass their keywords through the same
// reader (python/), `hertzdash parameters` can list it (fit_command_options()).
#include "hertzdash/model/parameter.hpp"
#include "hertzdash/simulation/reports/fit_report.hpp"

#include <map>
#include <span>
#include <string>
#include <string_view>

namespace hertzdash {

/// One option of `fit`: its declaration and the kinds of data that read it (a bit per FitDataKind).
struct FitOption {
  ParameterDecl decl;
  unsigned kinds;
};

/// Every option of `fit` besides the set-up's (run_options()), in the order the help lists them.
std::span<const FitOption> fit_command_options();

/// The option naming the data of `kind`: "trace", "restitution-table", "bounce-times".
std::string_view fit_kind_option(FitDataKind kind);

/// The request made by `values`, the options given (key: value; a flag's value "true"), and the
/// set-up `options`: exactly one of trace, restitution-table and bounce-times names the data
/// (InvalidParameter naming both when two do; a front end says a missing one its own way); an
/// option its kind does not read is refused naming both; a number that is not one is refused (its
/// range is checked where it is read).
FitRequest fit_request(const std::map<std::string, std::string>& values, const RunOptions& options);

}  // namespace hertzdash
