#pragma once
// The parts of `esc bench`: the fractions of plain references and of free-space stepping and
// the campaign estimate, which are always built, and the paper's workloads and thread scaling
// timed with Google Benchmark, which is optional (ESC_WITH_BENCHMARK).
#include <string>

#include "cli/commands.hpp"

namespace esc::cli {

// Times the paper's workloads; without Google Benchmark, says what is missing (exit 1).
int bench_workloads(const BenchOptions& options);

// The fractions: each paper workload against its plain reference, contact-heavy against
// free-space stepping (bench_reference.cpp; needs no benchmark library).
int bench_reference(const BenchOptions& options);
// One of the loops the fractions time, --evaluations items of it, for a profiler.
int bench_profile(const BenchOptions& options);

// The processor's model name, for the reports.
[[nodiscard]] std::string cpu_model();

}  // namespace esc::cli
