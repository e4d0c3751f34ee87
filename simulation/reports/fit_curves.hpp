#pragma once
// `fit --curves` and the data of `fit --figure` for a restitution table and a bounce recording
// (issue 46; a trace's are write_fit_curves, fit_report.hpp): e against the impact speed, the
// data's and the fitted law's, row by row.
//
// A recording's e per bounce, drag-corrected: impact k's rebound speed is the one whose flight
// (model/air_drag.hpp return_flight, the fit's air and body) lasts the measured interval to the
// next impact less the fitted model's contact time there; its approach speed is the landing
// speed of the measured flight before it (the first impact of a drop, or one after a missed
// impact: the fitted model's); e_measured is their ratio. Interval ratios, which carry the drag's
// bias, are not plotted against the model's e.
#include "hertzdash/io/csv_writer.hpp"
#include "hertzdash/simulation/reports/fit_report.hpp"

namespace hertzdash {

/// One row per table row or recorded impact: speed_measured_mps, e_measured (NaN where not known:
/// a recording's last impact of a drop, or before a missed one), impact_speed_mps and e_model,
/// e_model_se (the fitted model's at that impact), residual_e; a table's e_sd; a recording's
/// drop, impact_number, impact_time_s, model_time_s, residual_s. Throws std::logic_error for a trace.
CsvWriter restitution_curves_csv(const FitRun& run, const FitResult& fit, const PaperParameters& paper);

/// The fitted law's e at the data's impacts sorted by speed, with its 1-sigma band:
/// impact_speed_mps, e_model, e_low, e_high.
CsvWriter law_curve_csv(const FitRun& run, const FitResult& fit);

}  // namespace hertzdash
