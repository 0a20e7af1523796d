// esc built without MPI (ESC_WITH_MPI off): a process is always alone and evaluates every
// item of a generation on its own threads. Stands in for mpi_session.cpp and distribution.cpp.
#include <cstdlib>

#include <tbb/parallel_for.h>

#include "runtime/dist/distribution.hpp"
#include "runtime/dist/mpi_session.hpp"

namespace esc::dist {

bool built_with_mpi() noexcept { return false; }

MpiSession::MpiSession(int& /*argc*/, char**& /*argv*/) { set_current(this); }

MpiSession::~MpiSession() { set_current(nullptr); }

bool MpiSession::all_ok(bool ok) const { return ok; }

void MpiSession::broadcast(std::string& /*text*/) const {}

void MpiSession::abort(int status) const { std::exit(status); }

struct Distribution::Impl {};

Distribution::Distribution() = default;

Distribution::~Distribution() = default;

std::size_t Distribution::workers(std::size_t threads_here) const { return threads_here; }

void Distribution::run(std::size_t n, std::size_t /*width*/, std::size_t /*threads*/, std::span<double> /*results*/,
                       const std::function<void(std::size_t)>& evaluate) {
  tbb::parallel_for(std::size_t{0}, n, [&](std::size_t i) { evaluate(i); });
}

}  // namespace esc::dist
