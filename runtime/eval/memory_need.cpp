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

// One generation of one run of `c`: its optimizer and the pooled results (fitness, steps)
// with the fitness handed to the run. In doubles: sizes multiply beyond any integer type.
double generation_bytes(const ExperimentSpec& spec, const control::ControllerSpec& c) {
  const double results = static_cast<double>(spec.evaluations_per_generation(c)) * 3.0 * sizeof(double);
  const Evolution e = spec.evolution_of(c);
  if (spec.evaluates_only() || !e.settings.has_value()) return results;
  return e.algorithm->memory_bytes(e.settings, spec.problem_of(c)) + results;
}

// A number from a file such as /sys/fs/cgroup/memory.max ("max" when unlimited).
double number_in(const char* path) {
  std::ifstream in(path);
  double v = 0.0;
  return (in >> v) && v > 0.0 ? v : 0.0;
}

}  // namespace

double memory_needed_bytes(const ExperimentSpec& spec, bool trace_best) {
  double largest = 0.0;
  double statistics = 0.0;
  for (const control::ControllerSpec& c : spec.controllers) {
    largest = std::max(largest, generation_bytes(spec, c));
    statistics += static_cast<double>(spec.runs) * spec.generations_for(c) * sizeof(GenerationStats);
  }
  const double trace = trace_best ? static_cast<double>(spec.epochs) * spec.steps * sizeof(TraceStep) : 0.0;
  return largest + statistics + trace;
}

MemoryLimit memory_limit() {
  MemoryLimit m{static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGE_SIZE)),
                "physical memory"};
  rlimit as{};
  if (getrlimit(RLIMIT_AS, &as) == 0 && as.rlim_cur != RLIM_INFINITY && static_cast<double>(as.rlim_cur) < m.bytes)
    m = {static_cast<double>(as.rlim_cur), "the address-space limit (ulimit -v)"};
  for (const char* cgroup : {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"})
    if (const double v = number_in(cgroup); v > 0.0 && v < m.bytes) m = {v, "the container's memory limit (cgroup)"};
  return m;
}

std::string memory_problem(const ExperimentSpec& spec, bool trace_best, const MemoryLimit& limit) {
  const double need = memory_needed_bytes(spec, trace_best);
  if (need <= limit.bytes) return {};
  // What takes the most: the generation of one run of the hungriest controller.
  const control::ControllerSpec* hungriest = nullptr;
  double most = -1.0;
  for (const control::ControllerSpec& c : spec.controllers)
    if (const double b = generation_bytes(spec, c); b > most) {
      most = b;
      hungriest = &c;
    }
  std::string what;
  if (hungriest != nullptr) {
    const Evolution e = spec.evolution_of(*hungriest);
    const std::string algorithm = e.algorithm != nullptr ? std::string(e.algorithm->what) : "its optimizer";
    what = fmt::format("{} of `{}`: {} per run; ", algorithm, hungriest->name, bytes_text(most));
  }
  return fmt::format("experiment `{}` needs at least {} of memory at once ({}{} run{}, {} epochs x {} steps); {} is {}",
                     spec.name, bytes_text(need), what, spec.runs, spec.runs == 1 ? "" : "s", spec.epochs, spec.steps,
                     limit.what, bytes_text(limit.bytes));
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
