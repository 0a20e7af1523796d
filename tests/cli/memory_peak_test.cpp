// The campaign's memory estimate (runtime/eval/memory_need.hpp) against what `esc run` really
// holds, per algorithm: each experiment of tests/cli/data/memory.esc run in a child process
// whose peak resident memory wait4 reads (ru_maxrss). At the smallest size the process's own
// memory (the binary, the simulator, the threads) is nearly all of it; that baseline, less
// the estimate there, is added to the estimate at three larger sizes, which must then come
// within 25% of the measured peak. ESC_MEMORY_TABLE=1 runs sizes where the algorithm's part
// dominates instead and prints the table docs/performance.md keeps.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <gtest/gtest.h>

#include "compiler/compiler.hpp"
#include "runtime/eval/memory_need.hpp"

namespace {

namespace fs = std::filesystem;
namespace compiler = esc::compiler;
namespace eval = esc::eval;

const std::string kScript = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/memory.esc";

struct Case {
  std::string algorithm;                  // its experiment is `<algorithm>_memory`
  std::string key;                        // the setting that sizes it
  std::vector<std::string> sizes;         // the baseline first, then three larger
  std::vector<std::string> table_sizes;   // ESC_MEMORY_TABLE: where the algorithm dominates
  std::vector<std::string> also = {};     // further settings at every size
};

const std::vector<Case>& cases() {
  static const std::vector<Case> all = {
      {"es", "lambda", {"100", "25000", "50000", "100000"}, {"100000", "200000", "400000"}},
      {"cmaes", "cmaes.lambda", {"100", "25000", "50000", "100000"}, {"100000", "200000", "400000"}},
      {"gp", "gp.population", {"100", "10000", "20000", "40000"}, {"40000", "80000", "160000"}},
      {"nsga2", "nsga2.population", {"100", "25000", "50000", "100000"}, {"100000", "200000", "400000"}},
      {"novelty", "novelty.population", {"100", "25000", "50000", "100000"}, {"100000", "200000", "400000"}},
      {"map_elites", "map_elites.bins", {"10", "500", "1000", "1500"}, {"1500", "2000", "3000"}},
      {"cvt_map_elites", "cvt_map_elites.cells", {"100", "50000", "100000", "200000"},
       {"200000", "400000", "800000"}, {"cvt_map_elites.samples=800000"}},
  };
  return all;
}

std::vector<std::string> settings_of(const Case& c, const std::string& size) {
  std::vector<std::string> s = c.also;
  s.push_back(c.key + "=" + size);
  return s;
}

// The estimate `esc run` checks, for the case's experiment with `settings`.
double estimate_bytes(const Case& c, const std::vector<std::string>& settings) {
  compiler::CompileOptions options;
  options.import_paths = {fs::path(ESC_SOURCE_DIR) / "experiments"};
  const compiler::CompileResult r = compiler::compile_file(kScript, options);
  for (eval::ExperimentSpec spec : r.experiments) {
    if (spec.name != c.algorithm + "_memory") continue;
    for (const std::string& kv : settings) {
      const auto eq = kv.find('=');
      if (const std::string error = compiler::apply_setting(spec, kv.substr(0, eq), kv.substr(eq + 1)); !error.empty())
        ADD_FAILURE() << kv << ": " << error;
    }
    return eval::memory_need(spec, true).bytes;
  }
  ADD_FAILURE() << "no experiment " << c.algorithm << "_memory in " << kScript;
  return 0.0;
}

// The peak resident bytes of `esc run` on the case's experiment with `settings`.
double measured_bytes(const Case& c, const std::vector<std::string>& settings) {
  const fs::path out = fs::temp_directory_path() / fmt::format("esc-memory-test-{}", ::getpid());
  fs::remove_all(out);
  std::vector<std::string> args = {ESC_BINARY, "run", kScript, "--experiment", c.algorithm + "_memory", "--runs", "1",
                                   "--threads", "1", "--out", out.string()};
  for (const std::string& kv : settings) {
    args.push_back("--set");
    args.push_back(kv);
  }
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid == 0) {
    const int null = open("/dev/null", O_WRONLY);
    dup2(null, STDOUT_FILENO);
    dup2(null, STDERR_FILENO);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  EXPECT_EQ(wait4(pid, &status, 0, &usage), pid);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << fmt::format("{}", fmt::join(settings, " "));
  fs::remove_all(out);
  return static_cast<double>(usage.ru_maxrss) * 1024.0;
}

// Sizes that would have run out of this machine's memory are refused by name, one line each
// (the campaign's check, as `esc run` makes it: tests/cli/exit_codes_test.cpp runs one).
TEST(MemoryPeak, EveryAlgorithmsBlowupNamesTheSettingToLower) {
  const eval::MemoryLimit limit{5e8, "physical memory"};
  const std::vector<std::pair<Case, std::string>> blowups = {
      {{"es", "lambda", {}, {}}, "10000000"},
      {{"cmaes", "cmaes.lambda", {}, {}}, "1000000"},
      {{"cmaes", "cmaes.restarts", {}, {}, {"cmaes.lambda=100000"}}, "12"},
      {{"gp", "gp.population", {}, {}}, "100000000"},
      {{"nsga2", "nsga2.population", {}, {}}, "1000000"},
      {{"novelty", "novelty.population", {}, {}}, "1000000"},
      {{"map_elites", "map_elites.bins", {}, {}}, "8000"},
      {{"cvt_map_elites", "cvt_map_elites.cells", {}, {}, {"cvt_map_elites.samples=10000000"}}, "10000000"},
  };
  for (const auto& [c, size] : blowups) {
    compiler::CompileOptions options;
    options.import_paths = {fs::path(ESC_SOURCE_DIR) / "experiments"};
    const compiler::CompileResult r = compiler::compile_file(kScript, options);
    int found = 0;
    for (eval::ExperimentSpec spec : r.experiments) {
      if (spec.name != c.algorithm + "_memory") continue;
      ++found;
      for (const std::string& kv : settings_of(c, size)) {
        const auto eq = kv.find('=');
        ASSERT_EQ(compiler::apply_setting(spec, kv.substr(0, eq), kv.substr(eq + 1)), "") << kv;
      }
      const std::string problem = eval::memory_problem(spec, true, limit);
      EXPECT_NE(problem.find(fmt::format(": lower `{}`", c.key)), std::string::npos) << problem;
      EXPECT_EQ(problem.find('\n'), std::string::npos) << problem;
    }
    EXPECT_EQ(found, 1) << c.algorithm;
  }
}

TEST(MemoryPeak, EstimatePlusTheProcessComesWithinAQuarterOfTheMeasuredPeak) {
  const bool table = std::getenv("ESC_MEMORY_TABLE") != nullptr;
  if (table) fmt::print("| algorithm | setting | estimate | measured, less the process | ratio |\n|---|---|---|---|---|\n");
  for (const Case& c : cases()) {
    const double baseline = measured_bytes(c, settings_of(c, c.sizes.front())) -
                            estimate_bytes(c, settings_of(c, c.sizes.front()));
    for (const std::string& size : table ? c.table_sizes : std::vector<std::string>(c.sizes.begin() + 1, c.sizes.end())) {
      const std::vector<std::string> settings = settings_of(c, size);
      const double estimate = estimate_bytes(c, settings);
      const double measured = measured_bytes(c, settings);
      if (table)
        fmt::print("| {} | `{}={}` | {:.0f} MB | {:.0f} MB | {:.2f} |\n", c.algorithm, c.key, size, estimate / 1e6,
                   (measured - baseline) / 1e6, estimate / (measured - baseline));
      EXPECT_NEAR(estimate + baseline, measured, 0.25 * measured)
          << c.key << "=" << size << ": estimate " << estimate / 1e6 << " MB, baseline " << baseline / 1e6 << " MB";
    }
  }
}

}  // namespace
