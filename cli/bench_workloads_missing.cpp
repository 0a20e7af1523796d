// `esc bench` in a build without Google Benchmark (ESC_WITH_BENCHMARK off or not found).
#include <fmt/format.h>

#include "cli/bench.hpp"

namespace esc::cli {

int bench_workloads(const BenchOptions& /*options*/) {
  fmt::print(stderr,
             "esc: error: this esc was built without Google Benchmark, which `esc bench` needs to time the paper's "
             "workloads\nhelp: install it (Debian: libbenchmark-dev) and configure again with -DESC_WITH_BENCHMARK=ON; "
             "`esc bench --campaign FILE` works without it\n");
  return kExitBadInput;
}

}  // namespace esc::cli
