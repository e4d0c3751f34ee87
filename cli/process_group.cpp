#include "cli/process_group.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

#ifdef HERTZDASH_HAVE_MPI
#include <mpi.h>
#endif

namespace hertzdash::cli {

namespace {

// The world size an MPI launcher announces (Open MPI, MPICH/Hydra, Slurm's PMI/PMIx), or 0.
int launcher_world_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* v = std::getenv(name)) return std::max(1, std::atoi(v));
  return std::getenv("PMIX_RANK") ? 2 : 0;  // PMIx (srun --mpi=pmix) names no size: a launcher all the same
}

#ifdef HERTZDASH_HAVE_MPI
void check(int code, const char* call) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw std::runtime_error(std::string(call) + " failed: " + std::string(text, static_cast<std::size_t>(length)));
}

template <class T>
std::vector<std::vector<T>> gather_values(const std::vector<T>& mine, MPI_Datatype type, int rank, int size) {
  const int n = static_cast<int>(mine.size());
  std::vector<int> counts(rank == 0 ? static_cast<std::size_t>(size) : 0), offsets(counts.size());
  check(MPI_Gather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD), "MPI_Gather");
  std::vector<T> all;
  if (rank == 0) {
    int total = 0;
    for (int r = 0; r < size; ++r) {
      offsets[static_cast<std::size_t>(r)] = total;
      total += counts[static_cast<std::size_t>(r)];
    }
    all.resize(static_cast<std::size_t>(total));
  }
  check(MPI_Gatherv(mine.data(), n, type, all.data(), counts.data(), offsets.data(), type, 0, MPI_COMM_WORLD),
        "MPI_Gatherv");
  std::vector<std::vector<T>> parts;
  for (int r = 0; rank == 0 && r < size; ++r) {
    const auto begin = all.begin() + offsets[static_cast<std::size_t>(r)];
    parts.emplace_back(begin, begin + counts[static_cast<std::size_t>(r)]);
  }
  return parts;
}
#endif

}  // namespace

ProcessGroup::ProcessGroup() {
  const int announced = launcher_world_size();
#ifdef HERTZDASH_HAVE_MPI
  if (announced == 0) return;
  int provided = 0;
  check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  joined_ = true;
  check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
  check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
  MPI_Comm local;
  check(MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &local), "MPI_Comm_split_type");
  check(MPI_Comm_size(local, &local_size_), "MPI_Comm_size");
  check(MPI_Comm_free(&local), "MPI_Comm_free");
#else
  if (announced > 1)
    throw std::runtime_error("this hertzdash was built without MPI (HERTZDASH_WITH_MPI, libopenmpi-dev): under an MPI "
                             "launcher every process would run the whole sweep; run it without the launcher");
#endif
}

ProcessGroup::~ProcessGroup() {
#ifdef HERTZDASH_HAVE_MPI
  if (joined_) MPI_Finalize();
#endif
}

bool ProcessGroup::any(bool flag) const {
#ifdef HERTZDASH_HAVE_MPI
  if (joined_) {
    int mine = flag ? 1 : 0, result = 0;
    check(MPI_Allreduce(&mine, &result, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD), "MPI_Allreduce");
    return result != 0;
  }
#endif
  return flag;
}

std::vector<std::vector<double>> ProcessGroup::gather(const std::vector<double>& mine) const {
#ifdef HERTZDASH_HAVE_MPI
  if (joined_) return gather_values(mine, MPI_DOUBLE, rank_, size_);
#endif
  return {mine};
}

std::vector<std::string> ProcessGroup::gather(const std::string& mine) const {
#ifdef HERTZDASH_HAVE_MPI
  if (joined_) {
    std::vector<std::string> parts;
    for (const std::vector<char>& p : gather_values(std::vector<char>(mine.begin(), mine.end()), MPI_CHAR, rank_, size_))
      parts.emplace_back(p.begin(), p.end());
    return parts;
  }
#endif
  return {mine};
}

}  // namespace hertzdash::cli
