#pragma once
// The two halves of `esc bench`: the paper's workloads timed with Google Benchmark, which is
// optional (ESC_WITH_BENCHMARK), and the campaign estimate, which is always built.
#include <string>

#include "cli/commands.hpp"

namespace esc::cli {

// Times the paper's workloads; without Google Benchmark, says what is missing (exit 1).
int bench_workloads(const BenchOptions& options);

// The processor's model name, for the reports.
[[nodiscard]] std::string cpu_model();

}  // namespace esc::cli
