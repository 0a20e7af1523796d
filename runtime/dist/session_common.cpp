// What an MPI session is whether or not esc was built with MPI: how a launcher is
// recognised, and the process's session.
#include <cstdlib>

#include "runtime/dist/mpi_session.hpp"

namespace esc::dist {

namespace {
const MpiSession* g_session = nullptr;
}

bool launched_by_mpi() noexcept {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}

const MpiSession* MpiSession::current() noexcept { return g_session; }

void MpiSession::set_current(const MpiSession* session) noexcept { g_session = session; }

}  // namespace esc::dist
