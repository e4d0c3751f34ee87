#pragma once
// The inputs of the shaker (a body on a harmonically vibrating wall, model/wall_motion.hpp,
// simulation/shaker/shaker.hpp), each declared once (model/parameter.hpp). The body, the contact,
// the law and e are the drop test's (model/drop_test_parameters.hpp); the drop height is not read.
#include "hertzdash/model/parameter.hpp"

namespace hertzdash::shaker_parameters {

using R = NumberRange;
using T = ParameterType;

inline constexpr ParameterDecl frequency{
    .key = "frequency", .unit = "Hz", .column_unit = "Hz", .range = R::positive(), .default_value = "20",
    .default_number = 20.0, .default_source = "chosen: a period long against the paper's contact time",
    .help = "Frequency f of the wall's motion s(t) = A sin(2 pi f t) [Hz]"};
inline constexpr ParameterDecl amplitude{
    .key = "amplitude", .unit = "m", .column_unit = "m", .range = R::non_negative(),
    .default_value = "from `gamma`", .default_source = "computed: A = gamma g / (2 pi f)^2",
    .help = "Amplitude A of the wall's motion [m], instead of `gamma`"};
inline constexpr ParameterDecl gamma{
    .key = "gamma", .range = R::non_negative(), .default_value = "the middle of the period-1 window of e",
    .default_source = "computed: (gamma_1 + gamma_2)/2, where the instantaneous map's period-1 orbit appears, gamma_1 "
                      "= pi (1-e)/(1+e), and doubles, gamma_2 = sqrt(gamma_1^2 + (2 (1+e^2)/(1+e)^2)^2) "
                      "(model/wall_motion.hpp)",
    .help = "The wall's peak acceleration in units of gravity, gamma = A (2 pi f)^2 / g, instead of `amplitude`"};
inline constexpr ParameterDecl impacts{
    .key = "impacts", .range = R::integer(1, 1e7), .default_value = "100", .default_number = 100,
    .default_source = "chosen", .help = "Impacts kept and reported, after the transient"};
inline constexpr ParameterDecl transient{
    .key = "transient", .range = R::integer(0, 1e7), .default_value = "1000", .default_number = 1000,
    .default_source = "chosen", .help = "Impacts run first and discarded (the transient)"};
inline constexpr ParameterDecl impact_model{
    .key = "impact-model", .type = T::text, .choices = "soft, instantaneous", .default_value = "soft",
    .default_source = "the paper's contact",
    .help = "soft: the contact law integrated with the wall's motion; instantaneous: Newton's law with e = "
            "`restitution`, the textbook bouncing-ball map"};

inline constexpr ParameterDecl start_phase{
    .key = "start-phase", .range = R::closed_open(0, 1), .default_value = "the period-1 orbit's apex",
    .default_source = "computed: theta*/(2 pi) + 1/2 where the instantaneous map's period-1 orbit exists, else 0 "
                      "(simulation/shaker/shaker.hpp)",
    .help = "Table phase in [0, 1) at which the body is released from rest at `height` above the wall's mean "
            "position (`height` 0: at rest on the wall)"};

/// The shaker's own inputs, in the order of the options.
inline constexpr ParameterDecl all[] = {frequency, amplitude, gamma, impacts, transient, impact_model, start_phase};

}  // namespace hertzdash::shaker_parameters
