// Optimizers from the command line: a study comparing the paper's ES with CMA-ES runs every
// condition, its export names the algorithm on every row and its metrics table holds
// CMA-ES's step size; a CMA-ES run killed mid-run resumes to exactly the unbroken run, its
// metrics included; the report draws the metrics.
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

std::string es_vs_cmaes() { return std::string(ESC_SOURCE_DIR) + "/experiments/studies/es_vs_cmaes.esc"; }

// The lines of `text` whose field `column` (0-based, no quoted commas before it) is `value`.
int rows_with(const std::string& text, std::size_t column, const std::string& value) {
  std::stringstream in(text);
  int n = 0;
  for (std::string line; std::getline(in, line);) {
    std::stringstream fields(line);
    std::string cell;
    for (std::size_t i = 0; i <= column && std::getline(fields, cell, ','); ++i) {
    }
    n += cell == value ? 1 : 0;
  }
  return n;
}

TEST(Optimizers, TheEsAgainstCmaesStudyRunsEveryConditionAndExportsItsAlgorithmsAndMetrics) {
  const fs::path dir = scratch("es-vs-cmaes");
  const Outcome o = esc("run " + es_vs_cmaes() + " --runs 2 --generations 3 --set epochs=1 --out " + dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const Outcome exported = esc("export " + dir.string() + " --format csv");
  ASSERT_EQ(exported.status, 0) << exported.output;
  EXPECT_EQ(exported.output.substr(0, exported.output.find('\n')),
            "experiment,controller,run,run_seed,status,generation,best,mean,sd,evaluations,steps,seconds,condition,"
            "study,directory,algorithm");
  // 3 conditions x 4 controllers x 2 runs x 3 generations; the ES's condition by the ES.
  EXPECT_EQ(rows_with(exported.output, 15, "es"), 24);
  EXPECT_EQ(rows_with(exported.output, 15, "cmaes"), 48);
  EXPECT_EQ(rows_with(exported.output, 12, "sep_cmaes"), 24);
  const Outcome metrics = esc("export " + dir.string() + " --table metrics");
  ASSERT_EQ(metrics.status, 0) << metrics.output;
  EXPECT_EQ(metrics.output.substr(0, metrics.output.find('\n')),
            "experiment,condition,controller,algorithm,run,generation,metric,value");
  EXPECT_EQ(rows_with(metrics.output, 6, "sigma"), 48);   // CMA-ES's two conditions; the ES reports none
  EXPECT_EQ(rows_with(metrics.output, 1, "es"), 0);
  const Outcome json = esc("export " + dir.string() + " --table metrics --format json");
  EXPECT_NE(json.output.find("\"metric\": \"condition\""), std::string::npos) << json.output.substr(0, 400);
  const Outcome report = esc("report " + dir.string());
  ASSERT_EQ(report.status, 0) << report.output;
  EXPECT_TRUE(fs::exists(dir / "figures" / "es_vs_cmaes-cmaes-metrics.svg"));
  EXPECT_FALSE(fs::exists(dir / "figures" / "es_vs_cmaes-es-metrics.svg"));   // nothing reported
}

TEST(Optimizers, ACmaesRunKilledMidRunResumesToTheUnbrokenRun) {
  const std::vector<std::string> cmaes{"--set", "networks=cmaes", "--set", "cmaes.lambda=20"};
  const fs::path reference = scratch("cmaes-reference");
  const fs::path killed = scratch("cmaes-killed");
  ASSERT_EQ(esc("run " + tiny() + " --generations 100 --seed 5 --set networks=cmaes --set cmaes.lambda=20 "
                "--threads 1 --out " + reference.string())
                .status,
            0);
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tiny(), killed, 40, 400, "2", cmaes));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 1");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_results(reference, killed, {"CC", "SC"}, 2);
  EXPECT_EQ(esc("export " + reference.string() + " --table metrics").output,
            esc("export " + killed.string() + " --table metrics").output);
}

}  // namespace

namespace {

using namespace cli_test;

// A stop that fires ends the run's search there: stored, in summary.json, printed, and the run
// ends at that generation (every later output reads it as a finished run).
TEST(Optimizers, ACmaesStopEndsTheRunAndIsShown) {
  const fs::path dir = scratch("cmaes-stop");
  const Outcome o = esc("run " + tiny() + " --set networks=cmaes --set cmaes.stop_sigma=0.3 --out " + dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("CC           run 1 stopped its search after generation 0 (stop_sigma)"), std::string::npos)
      << o.output;
  const auto summary = read_json(dir / "summary.json");
  EXPECT_EQ(summary["controllers"]["SC"]["runs"][1]["stopped"], "stop_sigma");
  EXPECT_EQ(summary["controllers"]["SC"]["runs"][1]["best"].size(), 1u);
  EXPECT_EQ(committed_generations(dir), 4);   // 2 controllers x 2 runs x 1 generation
  EXPECT_EQ(esc("report " + dir.string()).status, 0);
  // Carried on, it stays where it stopped.
  ASSERT_EQ(esc("run --resume " + dir.string() + " --generations 9").status, 0);
  EXPECT_EQ(committed_generations(dir), 4);
}

}  // namespace
