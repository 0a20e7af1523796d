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

// What the campaign holds at its peak: one run of the compared controller that needs most
// at the height of its generation (its algorithm's own count, evo::MemoryPeak: genomes,
// sorting, archives, restarts' larger populations; the generation's results and outcomes),
// every run's per-generation statistics, and the replayed best evaluation's steps when
// `trace_best`. Runs advance together only while their generations are small, so one run
// at a time is what a large size holds. The process's own (the binary, the simulators, the
// threads' stacks) is left out: a few tens of MB.
struct MemoryNeed {
  double bytes = 0.0;
  std::string what;      // the largest part: "NSGA-II's ... for `CC`", "every run's statistics"
  std::string setting;   // the `--set` key that sizes it
};
[[nodiscard]] MemoryNeed memory_need(const ExperimentSpec& spec, bool trace_best);

struct MemoryLimit {
  double bytes = 0.0;
  std::string what;   // "physical memory", "the address-space limit (ulimit -v)", ...
};
// The least of the machine's physical memory, the process's address-space limit and the
// cgroup's memory limit (containers), where set.
[[nodiscard]] MemoryLimit memory_limit();

// When `spec` cannot fit under `limit`, one line saying what it needs, what takes most, what
// the limit is and the setting to lower: "experiment `x` needs about 23.1 GB of memory at
// once (NSGA-II's ... for `CC`: 23.0 GB); physical memory is 16.4 GB: lower
// `nsga2.population`". Empty when it fits.
[[nodiscard]] std::string memory_problem(const ExperimentSpec& spec, bool trace_best, const MemoryLimit& limit);

// "1.6 TB", "340 MB".
[[nodiscard]] std::string bytes_text(double bytes);

}  // namespace esc::eval
