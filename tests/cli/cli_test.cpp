// End-to-end tests of the `esc` command: exit codes, located diagnostics, the run
// directory, improvement of fitness, and identical results for any thread count.
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"

namespace {

using namespace cli_test;

TEST(Cli, NoCommandIsAUsageError) { EXPECT_EQ(esc("").status, 2); }

TEST(Cli, CheckAcceptsAGoodScript) {
  const Outcome o = esc("check " + tiny());
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("ok"), std::string::npos);
}

TEST(Cli, CheckLocatesErrorsAndExitsOne) {
  const fs::path dir = scratch("check");
  fs::create_directories(dir);
  std::ofstream(dir / "broken.esc") << "experiment {\n";
  const Outcome o = esc("check " + (dir / "broken.esc").string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("broken.esc:1:"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("error"), std::string::npos);
}

TEST(Cli, MissingFileIsAnErrorNotACrash) {
  const Outcome o = esc("check /nonexistent/nothing.esc");
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("nothing.esc"), std::string::npos);
}

TEST(Cli, BadOverridesAreRejectedBeforeRunning) {
  const fs::path out = scratch("badset");
  Outcome o = esc("run " + tiny() + " --set epoch=2 --out " + out.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("epochs"), std::string::npos) << "no did-you-mean: " << o.output;
  EXPECT_FALSE(fs::exists(out / "summary.json"));
  o = esc("run " + tiny() + " --set nonsense --out " + out.string());
  EXPECT_EQ(o.status, 2) << o.output;   // not KEY=VALUE: a bad command line
  o = esc("run " + tiny() + " --experiment nope --out " + out.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("tiny"), std::string::npos) << o.output;
}

TEST(Cli, RunWritesResultsAndNeverOverwritesThem) {
  const fs::path out = scratch("run");
  const Outcome o = esc("run " + tiny() + " --threads 2 --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("ETA"), std::string::npos);
  EXPECT_NE(o.output.find("eval/s"), std::string::npos);
  EXPECT_NE(o.output.find("behavior usage"), std::string::npos) << o.output;
  const auto s = read_json(out / "summary.json");
  EXPECT_EQ(s["experiment"], "tiny");
  EXPECT_EQ(s["seed"], "3");   // seeds are strings in JSON (exact beyond 2^53)
  for (const char* name : {"CC", "SC"}) {
    const auto& runs = s["controllers"][name]["runs"];
    ASSERT_EQ(runs.size(), 2U) << name;
    for (const auto& r : runs) {
      EXPECT_EQ(r["best"].size(), 6U);
      EXPECT_EQ(r["mean"].size(), 6U);
    }
    EXPECT_TRUE(fs::exists(out / name / "run-01.csv"));
    EXPECT_TRUE(fs::exists(out / name / "run-02.best.json"));
  }
  EXPECT_TRUE(fs::exists(out / "settings.json"));
  // The symbolic controller's runs say how often each action acted in their best evaluation.
  for (const auto& r : s["controllers"]["SC"]["runs"]) {
    ASSERT_TRUE(r.contains("behavior_usage")) << r.dump();
    std::int64_t steps = 0;
    for (const char* action : {"forward", "left", "right"}) steps += r["behavior_usage"][action].get<std::int64_t>();
    EXPECT_GT(steps, 0);
  }
  EXPECT_FALSE(s["controllers"]["CC"]["runs"][0].contains("behavior_usage"));
  const std::string before = read_json(out / "summary.json").dump();
  const Outcome again = esc("run " + tiny() + " --out " + out.string());
  EXPECT_EQ(again.status, 1) << again.output;
  EXPECT_EQ(read_json(out / "summary.json").dump(), before);
}

TEST(Cli, SameSeedSameResultsWithOneOrTwoThreadsAndFitnessImproves) {
  const fs::path a = scratch("t1");
  const fs::path b = scratch("t2");
  const fs::path c = scratch("t2-one-run-at-once");
  const std::string common = "run " + tiny() + " --runs 2 --generations 6 --seed 11 --set epochs=2";
  ASSERT_EQ(esc(common + " --threads 1 --out " + a.string()).status, 0);
  // On 2 threads tiny's two runs advance together, unless told otherwise.
  ASSERT_EQ(esc(common + " --threads 2 --out " + b.string()).status, 0);
  ASSERT_EQ(esc(common + " --threads 2 --runs-at-once 1 --out " + c.string()).status, 0);
  EXPECT_EQ(esc(common + " --runs-at-once 0 --out " + scratch("t0").string()).status, 2);
  const auto sa = read_json(a / "summary.json");
  const auto sb = read_json(b / "summary.json");
  const auto sc = read_json(c / "summary.json");
  for (const char* name : {"CC", "SC"}) {
    double first = 0.0;
    double last = 0.0;
    for (std::size_t r = 0; r < 2; ++r) {
      EXPECT_EQ(sa["controllers"][name]["runs"][r]["best"], sb["controllers"][name]["runs"][r]["best"]);
      EXPECT_EQ(sa["controllers"][name]["runs"][r]["mean"], sb["controllers"][name]["runs"][r]["mean"]);
      EXPECT_EQ(sa["controllers"][name]["runs"][r]["mean"], sc["controllers"][name]["runs"][r]["mean"]);
      first += sa["controllers"][name]["runs"][r]["mean"].front().get<double>();
      last += sa["controllers"][name]["runs"][r]["mean"].back().get<double>();
    }
    EXPECT_GT(last, first) << name << ": mean fitness did not improve";
  }
}

}  // namespace

namespace {

TEST(Cli, PaperObstacleAvoidanceImprovesForEveryController) {
  const fs::path out = scratch("paper");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/experiments/paper/obstacle_avoidance.esc";
  const Outcome o = esc("run " + script + " --runs 2 --generations 4 --seed 11 --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const auto s = read_json(out / "summary.json");
  EXPECT_EQ(s["experiment"], "obstacle_avoidance");
  ASSERT_EQ(s["controllers"].size(), 6U);
  for (const auto& [name, c] : s["controllers"].items()) {
    double first = 0.0;
    double last = 0.0;
    for (const auto& r : c["runs"]) {
      first += r["mean"].front().get<double>();
      last += r["mean"].back().get<double>();
    }
    EXPECT_GT(last, first) << name;
  }
}

}  // namespace

namespace {

TEST(Cli, BenchEstimatesACampaignFromMeasuredRates) {
  const Outcome o = esc("bench --campaign " + tiny() + " --min-time 0.05");
  ASSERT_EQ(o.status, 0) << o.output;
  // tiny: 2 runs x 6 generations x 20 offspring = 240 evaluations of 3 epochs x 80 steps.
  EXPECT_NE(o.output.find("240"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("57600"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("core-hours"), std::string::npos);
}

// A study condition's setting of an experiment it depends on (start_from.esc's
// `basic.generations 2`) is estimated as it will run: the experiment as declared and the
// one with the setting, each with its own evaluations.
TEST(Cli, BenchEstimatesADependencyWithTheSettingsAConditionGivesIt) {
  const Outcome o = esc("bench --campaign " + std::string(ESC_SOURCE_DIR) + "/tests/cli/data/start_from.esc" +
                        " --min-time 0.02");
  ASSERT_EQ(o.status, 0) << o.output;
  // basic: 3 runs x 6 offspring x 4 generations = 72 evaluations; with 2 generations, 36.
  std::istringstream lines(o.output);
  std::map<std::string, std::string> evaluations;   // "experiment controller" -> evaluations
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string experiment, controller, architecture, count;
    if (words >> experiment >> controller >> architecture >> count) evaluations[experiment + " " + controller] = count;
  }
  EXPECT_EQ(evaluations["basic CC"], "72") << o.output;
  EXPECT_EQ(evaluations["basic[generations=2] CC"], "36") << o.output;
}

TEST(Cli, EvolvedBehaviorsRunTheirExperimentFirstAndReuseIt) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/evolved.esc";
  const fs::path out = scratch("evolved");
  Outcome o = esc("run " + script + " --experiment supervised --threads 2 --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("esc: dependency basic: running into"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("controller CC frozen with the best genome of 2 runs"), std::string::npos) << o.output;
  ASSERT_TRUE(fs::is_directory(out / "deps"));
  fs::path dep;
  for (const auto& e : fs::directory_iterator(out / "deps")) dep = e.path();
  EXPECT_EQ(dep.filename().string().rfind("basic-", 0), 0u) << dep;
  const auto basic = read_json(dep / "summary.json");
  EXPECT_EQ(basic["experiment"], "basic");
  EXPECT_EQ(basic["controllers"]["CC"]["runs"].size(), 2U);
  const auto top = read_json(out / "summary.json");
  EXPECT_EQ(top["experiment"], "supervised");
  EXPECT_EQ(top["controllers"]["SV"]["runs"].size(), 2U);

  // A shared cache: the second run reuses the first one's dependency run.
  const fs::path cache = scratch("evolved-cache");
  o = esc("run " + script + " --experiment supervised --runs 1 --out " + scratch("evolved-1").string() +
          " --cache " + cache.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("running into"), std::string::npos) << o.output;
  const fs::path second = scratch("evolved-2");
  o = esc("run " + script + " --experiment supervised --runs 1 --out " + second.string() + " --cache " +
          cache.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("esc: dependency basic: reused"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("running into"), std::string::npos) << o.output;
  EXPECT_TRUE(fs::exists(second / "summary.json"));
  EXPECT_FALSE(fs::exists(second / "deps"));
}

}  // namespace
