// `make bench`: the work-precision benchmark at full repeats.
//   hertzdash_bench --out DIR --generated DIR [--readme README.md] [--figures-ms MS]
// Prints the side-by-side table and the ratios at equal error, writes the CSVs and
// LaTeX macros (the same files the study validation/work_precision_peers writes
// with fewer repeats) and, with --readme, refreshes the README's generated block;
// --figures-ms is the measured wall time of `make figures` from a built tree, reported there.
#include "bench/work_precision.hpp"

#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  hertzdash::bench::WorkPrecisionConfig c;
  c.budget_ms = 20;
  c.repeats = 11;
  c.sweep_impacts = 200000;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--out" && i + 1 < argc) c.out_dir = argv[++i];
    else if (arg == "--generated" && i + 1 < argc) c.generated_dir = argv[++i];
    else if (arg == "--readme" && i + 1 < argc) c.readme = argv[++i];
    else if (arg == "--figures-ms" && i + 1 < argc) c.figures_seconds = std::atof(argv[++i]) / 1000.0;
    else {
      std::cerr << "usage: " << argv[0] << " --out DIR --generated DIR [--readme README.md] [--figures-ms MS]\n";
      return 2;
    }
  }
  if (c.out_dir.empty() || c.generated_dir.empty()) {
    std::cerr << "usage: " << argv[0] << " --out DIR --generated DIR [--readme README.md] [--figures-ms MS]\n";
    return 2;
  }
  try {
    std::filesystem::create_directories(c.out_dir);
    std::filesystem::create_directories(c.generated_dir);
    return hertzdash::bench::run_work_precision(c);
  } catch (const std::exception& e) {
    std::cerr << "hertzdash_bench: " << e.what() << "\n";
    return 1;
  }
}
