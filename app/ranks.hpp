#pragma once
// Under mpirun every rank runs the same command: they compile and compute alike, rank 0
// alone reads and writes results and caches and reports events, and every decision rank 0
// takes reaches the others before they act on it.
#include <functional>
#include <string>

namespace esc::dist {
class MpiSession;
}

namespace esc::app {

// True on the ranks of an MPI job other than rank 0.
[[nodiscard]] bool follower_rank();

// The running MPI job, or null for a lone process.
[[nodiscard]] const dist::MpiSession* job();

// Rank 0's `value` on every rank.
[[nodiscard]] bool agree(bool rank0);
// Rank 0's `text` on every rank.
void agree(std::string& text);

// Rank 0 (or a lone process) calls `act`; every rank learns whether it succeeded and
// throws what it threw (the other ranks an empty app::Error), so that they all stop
// together without an MPI_Abort racing their MPI_Finalize.
void on_rank0(const std::function<void()>& act);

}  // namespace esc::app
