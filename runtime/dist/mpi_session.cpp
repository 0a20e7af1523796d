#include "runtime/dist/mpi_session.hpp"

#include <algorithm>
#include <cstdlib>

#include <mpi.h>

namespace esc::dist {

bool built_with_mpi() noexcept { return true; }

MpiSession::MpiSession(int& argc, char**& argv) {
  set_current(this);
  if (!launched_by_mpi()) return;
  // Worker threads fetch evaluations from the shared counter themselves (Distribution).
  MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &thread_support_);
  active_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  if (active_) MPI_Finalize();
  set_current(nullptr);
}

bool MpiSession::all_ok(bool ok) const {
  if (!active_) return ok;
  int mine = ok ? 1 : 0;
  int all = 0;
  MPI_Allreduce(&mine, &all, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  return all == 1;
}

void MpiSession::broadcast(std::string& text) const {
  if (!active_) return;
  auto size = static_cast<unsigned long long>(text.size());
  MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  text.resize(static_cast<std::size_t>(size));
  // In pieces: MPI counts are ints.
  constexpr std::size_t kPiece = std::size_t{1} << 30;
  for (std::size_t at = 0; at < text.size(); at += kPiece)
    MPI_Bcast(text.data() + at, static_cast<int>(std::min(kPiece, text.size() - at)), MPI_CHAR, 0, MPI_COMM_WORLD);
}

void MpiSession::abort(int status) const {
  if (active_) MPI_Abort(MPI_COMM_WORLD, status);
  std::exit(status);
}

}  // namespace esc::dist
