#include "runtime/eval/memory_need.hpp"

#include <algorithm>
#include <fstream>
#include <string>

#include <sys/resource.h>
#include <unistd.h>

#include <fmt/format.h>

#include "runtime/eval/evaluator.hpp"
#include "runtime/eval/run_state.hpp"

namespace esc::eval {

namespace {

// One run of `c` at the height of a generation: its optimizer's peak, and per candidate its
// row of results, its outcome (objectives and descriptors) and its fitness, twice.
evo::MemoryPeak run_peak(const ExperimentSpec& spec, const control::ControllerSpec& c) {
  const Evolution e = spec.evolution_of(c);
  evo::MemoryPeak peak;
  if (!spec.evaluates_only() && e.settings.has_value() && e.algorithm != nullptr) {
    peak = e.algorithm->memory(e.settings, spec.problem_of(c), spec.generations_for(c));
    peak.what += fmt::format(" for `{}`", c.name);
  } else {
    peak = {0.0, static_cast<double>(spec.evaluations_per_generation(c)), fmt::format("the evaluations of `{}`", c.name),
            "runs"};
  }
  const double objectives = 1.0 + static_cast<double>(spec.further.size());
  const double descriptors = static_cast<double>(spec.descriptors.size());
  const double width = 3.0 + static_cast<double>(c.choice_names().size()) + objectives + descriptors;
  const double candidate = (width + 2.0) * sizeof(double) + sizeof(evo::Outcome) +
                           evo::heap_bytes(objectives * sizeof(double)) + evo::heap_bytes(descriptors * sizeof(double));
  peak.bytes += peak.candidates * candidate;
  return peak;
}

// A number from a file such as /sys/fs/cgroup/memory.max ("max" when unlimited).
double number_in(const char* path) {
  std::ifstream in(path);
  double v = 0.0;
  return (in >> v) && v > 0.0 ? v : 0.0;
}

}  // namespace

MemoryNeed memory_need(const ExperimentSpec& spec, bool trace_best) {
  evo::MemoryPeak largest;
  double statistics = 0.0;
  for (const control::ControllerSpec& c : spec.controllers) {
    if (evo::MemoryPeak p = run_peak(spec, c); p.bytes > largest.bytes || largest.what.empty()) largest = std::move(p);
    statistics += static_cast<double>(spec.runs) * spec.generations_for(c) * sizeof(GenerationStats);
  }
  const double trace = trace_best ? static_cast<double>(replay_rows(spec)) * sizeof(TraceStep) : 0.0;
  MemoryNeed need{largest.bytes + statistics + trace, fmt::format("{}: {}", largest.what, bytes_text(largest.bytes)),
                  largest.setting};
  if (statistics > largest.bytes && statistics >= trace)
    need = {need.bytes, fmt::format("every run's statistics, {} runs: {}", spec.runs, bytes_text(statistics)), "runs"};
  else if (trace > largest.bytes && trace > statistics)
    need = {need.bytes, fmt::format("the best run's replay of {} epochs x {} steps{}: {}", spec.epochs, spec.steps,
                                    spec.robots > 1 ? fmt::format(" x {} robots, at most {} rows", spec.robots,
                                                                  kMaxReplayRows)
                                                    : std::string(),
                                    bytes_text(trace)),
            "steps"};
  return need;
}

MemoryLimit memory_limit() {
  MemoryLimit m{static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE)),
                "physical memory"};
  rlimit as{};
  // The address space counts what esc maps already (its libraries, its heap so far): about
  // 100 MB that the estimate, which counts what the campaign allocates, leaves out.
  const double mapped = number_in("/proc/self/statm") * static_cast<double>(sysconf(_SC_PAGE_SIZE));
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY &&
      static_cast<double>(as.rlim_cur) - mapped < m.bytes)
    m = {static_cast<double>(as.rlim_cur) - mapped, "the address-space limit (ulimit -v), less what esc maps already,"};
  for (const char* cgroup : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"})
    if (const double v = number_in(cgroup); v > 0.0 && v < m.bytes) m = {v, "the container's memory limit (cgroup)"};
  return m;
}

std::string memory_problem(const ExperimentSpec& spec, bool trace_best, const MemoryLimit& limit) {
  const MemoryNeed need = memory_need(spec, trace_best);
  if (need.bytes <= limit.bytes) return {};
  return fmt::format("experiment `{}` needs about {} of memory at once ({}); {} is {}: lower `{}`", spec.name,
                     bytes_text(need.bytes), need.what, limit.what, bytes_text(limit.bytes), need.setting);
}

std::string bytes_text(double bytes) {
  constexpr const char* kUnits[] = {"B", "kB", "MB", "GB", "TB", "PB", "EB"};
  std::size_t u = 0;
  while (bytes >= 1000.0 && u + 1 < std::size(kUnits)) {
    bytes /= 1000.0;
    ++u;
  }
  return u == 0 ? fmt::format("{:.0f} B", bytes) : fmt::format("{:.1f} {}", bytes, kUnits[u]);
}

}  // namespace esc::eval
