#pragma once
// Whether a campaign fits in this machine's memory, decided before anything is allocated.
// A size that cannot fit (lambda 1e9, a population of trees of 1e6 nodes, ten million runs)
// used to grow until the kernel killed the process or std::bad_alloc ended it after the run
// directory was made; now it is refused with what it would need and what the machine has.
// A size that fits but makes a generation long is legitimate (lambda 1,000,000 on a
// cluster): the campaign then reports progress within the generation (RoundProgress).
#include <string>

#include "runtime/eval/experiment.hpp"

namespace esc::eval {

// Bytes the campaign holds at once, at least: the largest generation of one run of any
// compared controller (parents, offspring and their step sizes, or two generations of
// trees at max_size; their results), every run's per-generation statistics, and the
// replayed best evaluation's steps when `trace_best`. An estimate from below (allocator
// overhead and the simulators are left out), so a refusal is never wrong.
[[nodiscard]] double memory_needed_bytes(const ExperimentSpec& spec, bool trace_best);

struct MemoryLimit {
  double bytes = 0.0;
  std::string what;   // "physical memory", "the address-space limit (ulimit -v)", ...
};
// The least of the machine's physical memory, the process's address-space limit and the
// cgroup's memory limit (containers), where set.
[[nodiscard]] MemoryLimit memory_limit();

// "... needs about 1.6 TB at once; physical memory is 125.8 GB" when `spec` cannot fit
// under `limit`; empty when it can.
[[nodiscard]] std::string memory_problem(const ExperimentSpec& spec, bool trace_best, const MemoryLimit& limit);

// "1.6 TB", "340 MB".
[[nodiscard]] std::string bytes_text(double bytes);

}  // namespace esc::eval
