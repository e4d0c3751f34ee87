#pragma once
// `hertzdash shaker --sweep KEY:FROM:TO:COUNT`: a bifurcation diagram, one independent shaker run
// per value on every core, or under an MPI launcher on every process of the job (value i on rank
// i mod size; rank 0 gathers the runs and writes the same file byte for byte), one CSV row per
// kept impact (simulation/reports/shaker_sweep_report.hpp, docs/shaker.md).
#include "hertzdash/simulation/rigs/shaker_rig.hpp"

#include <optional>
#include <string>

namespace hertzdash::cli {

struct ShakerSweepRequest {
  RunOptions run;
  RigInputs shaker;
  std::string sweep, csv_path;
  std::optional<double> threads;
  bool json = false, mkdir = false;
};

/// Runs the sweep and writes --csv; InvalidParameter for bad input (`threads` without `sweep`,
/// `json`, no `csv`, a bad `sweep`). Returns the exit code.
int run_shaker_sweep_command(const ShakerSweepRequest& request);

}  // namespace hertzdash::cli
