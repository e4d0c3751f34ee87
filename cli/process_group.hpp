#pragma once
// The processes a sweep is shared among: the MPI world when the program was started by an MPI
// launcher (mpirun, mpiexec, srun), else this process alone. MPI is initialised only then, so
// an ordinary run never pays for it, and a build without MPI (HERTZDASH_HAVE_MPI undefined)
// refuses to run under a launcher rather than have every process do the whole sweep.
#include <cstddef>
#include <string>
#include <vector>

namespace hertzdash::cli {

class ProcessGroup {
 public:
  ProcessGroup();   ///< joins the MPI world if launched by an MPI launcher
  ~ProcessGroup();  ///< leaves it (MPI_Finalize)
  ProcessGroup(const ProcessGroup&) = delete;
  ProcessGroup& operator=(const ProcessGroup&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  /// Processes of the group on this machine (to share its cores among them).
  int local_size() const { return local_size_; }
  /// True if `flag` is true on any process (every process gets the answer).
  bool any(bool flag) const;
  /// Each process's `mine`, in rank order, on rank 0 (empty elsewhere).
  std::vector<std::vector<double>> gather(const std::vector<double>& mine) const;
  std::vector<std::string> gather(const std::string& mine) const;

 private:
  int rank_ = 0, size_ = 1, local_size_ = 1;
  bool joined_ = false;
};

}  // namespace hertzdash::cli
