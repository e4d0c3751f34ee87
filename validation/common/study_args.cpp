#include "validation/common/study_args.hpp"

#include "hertzdash/io/atomic_file.hpp"

#include <cstdlib>
#include <iostream>
#include <string>

namespace hertzdash {

StudyArgs parse_study_args(int argc, char** argv) {
  StudyArgs a;
  const std::string usage_line = std::string("usage: ") + argv[0] + " --out DIR [--generated DIR] [--reduced | --full]\n";
  auto usage = [&] {
    std::cerr << usage_line << "(" << argv[0] << " --help explains them)\n";
    std::exit(2);
  };
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") {
      std::cout << usage_line
                << "  --out DIR        where the study's CSV data (and the figures drawn from it) go, e.g. paper/figures\n"
                   "  --generated DIR  where its LaTeX fragments go (default: DIR/../generated)\n"
                   "  --reduced        a small, fast version of the study (the pipeline test)\n"
                   "  --full           the full sample size of a study that `make figures` cuts\n";
      std::exit(0);
    }
    if (arg == "--out" && i + 1 < argc) a.out_dir = argv[++i];
    else if (arg == "--generated" && i + 1 < argc) a.generated_dir = argv[++i];
    else if (arg == "--reduced") a.reduced = true;
    else if (arg == "--full") a.full = true;
    else usage();
  }
  if (a.out_dir.empty() || (a.reduced && a.full)) usage();
  if (a.generated_dir.empty()) a.generated_dir = a.out_dir.parent_path() / "generated";
  std::filesystem::create_directories(a.out_dir);
  std::filesystem::create_directories(a.generated_dir);
  return a;
}

int study_failed(const char* program, const std::exception& e) {
  std::cerr << std::filesystem::path(program).filename().string() << ": error: " << e.what() << "\n";
  return 1;
}

int save_study_outputs(const StudyArgs& args, std::string_view name, const std::vector<StudyCsv>& csvs,
                       const std::string& latex_table, const LatexMacros& macros) {
  for (const StudyCsv& csv : csvs) csv.table.save(args.out_dir / csv.file);
  write_file_atomically(args.generated_dir / (std::string(name) + "_table.tex"), latex_table);
  macros.save(args.generated_dir / (std::string(name) + ".tex"));
  return 0;
}

}  // namespace hertzdash
