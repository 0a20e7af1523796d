#pragma once
// The process's place in an MPI job. esc runs as a plain process unless it was started by
// an MPI launcher (mpirun sets OMPI_COMM_WORLD_SIZE / PMI_SIZE / PMIX_RANK), so a normal
// `esc run` never pays MPI's start-up or needs a launcher. MPI is optional (ESC_WITH_MPI):
// mpi_session.cpp and distribution.cpp use it, single_process.cpp stands in for both without.
//
// Under MPI every rank runs the same campaign logic (compiling the same script, breeding
// the same populations from the same streams); only evaluations are shared out, and their
// results gathered back to every rank (see distribution.hpp). Rank 0 alone writes results
// and prints progress.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace esc::dist {

class MpiSession {
 public:
  // Initialises MPI (thread level: funneled) when launched by mpirun, else does nothing.
  MpiSession(int& argc, char**& argv);
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  [[nodiscard]] bool active() const noexcept { return active_; }
  [[nodiscard]] int rank() const noexcept { return rank_; }
  [[nodiscard]] int size() const noexcept { return size_; }
  [[nodiscard]] bool is_root() const noexcept { return rank_ == 0; }
  // The MPI thread level granted (MPI_THREAD_SINGLE .. MPI_THREAD_MULTIPLE); 0 when inactive.
  [[nodiscard]] int thread_support() const noexcept { return thread_support_; }

  // True when every rank passes true (a collective: all ranks must call it). Used so a
  // failure on one rank (an existing output directory on rank 0) stops every rank.
  [[nodiscard]] bool all_ok(bool ok) const;

  // Rank 0's `text` on every rank (a collective: all ranks must call it). Used for what
  // rank 0 alone reads from files, so that the other ranks never touch the filesystem.
  void broadcast(std::string& text) const;

  // Ends the job from any rank after a fatal error (MPI_Abort), so no rank waits forever.
  [[noreturn]] void abort(int status) const;

  // The session of this process, set by the constructor; null before.
  [[nodiscard]] static const MpiSession* current() noexcept;

 private:
  static void set_current(const MpiSession* session) noexcept;
  bool active_ = false;
  int rank_ = 0;
  int size_ = 1;
  int thread_support_ = 0;
};

// True when the environment says an MPI launcher started this process.
[[nodiscard]] bool launched_by_mpi() noexcept;

// Whether this esc shares evaluations among MPI ranks (built with ESC_WITH_MPI). Without
// it, a process started by mpirun stays alone (MpiSession::active() is false).
[[nodiscard]] bool built_with_mpi() noexcept;

}  // namespace esc::dist
