#pragma once
// How the evaluations of one generation are shared out among processes. Each
// evaluation's result depends only on its genome and seed, so every way of sharing gives
// the same results; this only decides who computes what.
//
// Alone (no MPI), a process evaluates everything. Under MPI, ranks take chunks of the
// generation from a shared counter on rank 0 (an MPI atomic fetch-and-add), so a rank
// whose evaluations end early (collisions) simply takes more: dynamic load balancing.
// Afterwards every rank receives every result (bit for bit, an all-gather of the packed
// values), so all ranks continue with identical populations.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>

namespace esc::dist {

class Distribution {
 public:
  // Collective under MPI: every rank must construct it, in the same order.
  Distribution();
  ~Distribution();
  Distribution(const Distribution&) = delete;
  Distribution& operator=(const Distribution&) = delete;

  // Evaluates items [0, n) with `threads` of this process's threads (in the caller's TBB
  // arena): `evaluate(i)` computes item i and writes its results into `results` (`width`
  // doubles per item, item i at [i * width, (i + 1) * width)); it is called concurrently
  // for different items. On return, every process holds all n results. Under MPI each
  // thread takes one item at a time from the shared counter, so neither a rank nor a
  // thread waits on another's long evaluation until the generation runs out.
  void run(std::size_t n, std::size_t width, std::size_t threads, std::span<double> results,
           const std::function<void(std::size_t i)>& evaluate);

  [[nodiscard]] bool distributed() const noexcept { return impl_ != nullptr; }
  // Worker threads of all processes, given this one's: the sum over the MPI job's ranks
  // (which may differ, e.g. nodes with other core counts), the same on every rank.
  // Collective under MPI.
  [[nodiscard]] std::size_t workers(std::size_t threads_here) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace esc::dist
