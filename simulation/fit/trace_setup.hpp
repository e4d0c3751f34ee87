#pragma once
// The set-up a measured trace states (data/measurements/README.md): its header lines `rod:` (a
// rod of Tables 1-3, the preset of mass, flat and e) and `height_m:` (the drop height [m], so
// the approach speed sqrt(2 g h)) are the fit's set-up where the user gave no option for them.
//
// Rules, for each of rod and height:
//   - not given: the trace's value is used, validated like the option (`rod`'s choices; the
//     height's declared range and the set-up's checks, e.g. a Hertz deformation below the ball
//     radius), a refusal naming the header line and the file;
//   - given and equal (the rod by name; the height within height_match_tolerance_m, the
//     tolerance with which the figure programs match traces): the option is used;
//   - given and different: refused, naming both the option's and the trace's value.
// With `impact-velocity` given the trace's height is not used (the user states the approach
// speed; the option refuses a height beside it).
#include "hertzdash/io/measured_trace.hpp"
#include "hertzdash/simulation/options/run_options.hpp"
#include "hertzdash/simulation/paper/paper_parameters.hpp"

#include <string>
#include <vector>

namespace hertzdash {

/// Largest difference between a given --height and the trace's height_m that is no conflict [m]
/// (data/measurements/README.md: traces are matched within 0.5 mm).
inline constexpr double height_match_tolerance_m = 0.5e-3;

/// `base` with the trace's rod and height where neither `base` nor `given` (names of options a
/// front end was given even at their default value, e.g. "rod" for --rod steel) sets them.
/// Throws InvalidParameter (key `rod` or `height`) for a header value out of range or a
/// conflict with a given option; the range names the file.
RunOptions trace_setup_options(const MeasuredTrace& trace, const RunOptions& base, const PaperParameters& paper,
                               const std::vector<std::string>& given = {});

}  // namespace hertzdash
