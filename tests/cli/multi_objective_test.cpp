// Several objectives and behavior descriptors from the command line: NSGA-II
// (experiments/examples/speed_energy.esc) and MAP-Elites (behavior_map.esc) run, store their
// metrics every generation, give the same results on any number of threads, and a run
// killed mid-run resumes to exactly the unbroken run, Lehman & Stanley's maze study too.
#include <algorithm>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <sys/resource.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

std::string example(const std::string& name) {
  return std::string(ESC_SOURCE_DIR) + "/experiments/examples/" + name + ".esc";
}

// metric -> run -> its values by generation, from `esc export --table metrics`.
std::map<std::string, std::map<std::string, std::vector<double>>> metrics_of(const fs::path& dir) {
  const Outcome o = esc("export " + dir.string() + " --table metrics");
  EXPECT_EQ(o.status, 0) << o.output;
  std::map<std::string, std::map<std::string, std::vector<double>>> m;
  std::stringstream in(o.output);
  std::string line;
  std::getline(in, line);   // experiment,condition,controller,algorithm,run,generation,metric,value
  while (std::getline(in, line)) {
    std::vector<std::string> f;
    std::stringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) f.push_back(c);
    if (f.size() == 8) m[f[6]][f[4]].push_back(std::stod(f[7]));
  }
  return m;
}

TEST(MultiObjective, MapElitesStoresItsArchiveMetricsEveryGeneration) {
  const fs::path dir = scratch("map-elites");
  const Outcome o = esc("run " + example("behavior_map") + " --runs 2 --generations 6 --set epochs=1 --out " +
                        dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const auto m = metrics_of(dir);
  ASSERT_EQ(m.at("qd_score").size(), 2u);
  for (const auto& [run, qd] : m.at("qd_score")) {
    ASSERT_EQ(qd.size(), 6u) << run;
    for (std::size_t g = 1; g < qd.size(); ++g) EXPECT_GE(qd[g], qd[g - 1]) << "an elite is only ever replaced by a better one";
    EXPECT_GT(qd.back(), 0.0);
    const std::vector<double>& coverage = m.at("coverage").at(run);
    EXPECT_GT(coverage.back(), 0.0);
    EXPECT_LE(coverage.back(), 1.0);
  }
}

TEST(MultiObjective, AnArchiveLargerThanMemoryIsRefusedBeforeTheRun) {
  const fs::path out = scratch("map-elites-huge");
  // 5,000 x 5,000 cells of 18 weights, about 8 GB, under an address-space limit of 4 GB that
  // esc inherits (so the test does not depend on the machine's memory).
  rlimit before{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &before), 0);
  rlimit limited = before;
  limited.rlim_cur = std::min<rlim_t>(before.rlim_max, rlim_t{4} << 30);
  ASSERT_EQ(setrlimit(RLIMIT_AS, &limited), 0);
  const Outcome o = esc("run " + example("behavior_map") + " --set map_elites.bins=5000 --out " + out.string());
  ASSERT_EQ(setrlimit(RLIMIT_AS, &before), 0);
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("(MAP-Elites of `CC_8_2`: "), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("MAP-Elites' bins or cells"), std::string::npos) << o.output;
  EXPECT_FALSE(fs::exists(out)) << "refused before the run directory is made";
}

TEST(MultiObjective, NsgaIiStoresItsFrontAndHypervolumeEveryGeneration) {
  const fs::path dir = scratch("nsga2");
  const Outcome o = esc("run " + example("speed_energy") + " --runs 2 --generations 4 --set epochs=1 --out " +
                        dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const auto m = metrics_of(dir);
  for (const auto& [run, hv] : m.at("hypervolume")) {
    ASSERT_EQ(hv.size(), 4u) << run;
    // The reference is the worst corner of the declared ranges: 0 speed, 450 effort.
    for (const double v : hv) {
      EXPECT_GT(v, 0.0);
      EXPECT_LE(v, 450.0 * 450.0);
    }
    for (const double f : m.at("front").at(run)) {
      EXPECT_GE(f, 1.0);
      EXPECT_LE(f, 40.0);   // the population
    }
  }
}

TEST(MultiObjective, AnyNumberOfThreadsGivesTheSameResults) {
  for (const std::string name : {"behavior_map", "speed_energy"}) {
    const fs::path one = scratch(name + "-1"), two = scratch(name + "-2");
    const std::string run = "run " + example(name) + " --runs 2 --generations 3 --set epochs=1 --threads ";
    ASSERT_EQ(esc(run + "1 --out " + one.string()).status, 0);
    ASSERT_EQ(esc(run + "2 --runs-at-once 2 --out " + two.string()).status, 0);
    expect_same_results(one, two, {name == "behavior_map" ? "CC_8_2" : "C"}, 2);
    EXPECT_EQ(esc("export " + one.string() + " --table metrics").output,
              esc("export " + two.string() + " --table metrics").output)
        << name;
  }
}

TEST(MultiObjective, ARunKilledMidRunResumesToTheUnbrokenRun) {
  for (const std::string name : {"behavior_map", "speed_energy"}) {
    const fs::path reference = scratch(name + "-reference"), killed = scratch(name + "-killed");
    const std::vector<std::string> shorter{"--set", "epochs=1"};
    ASSERT_EQ(esc("run " + example(name) + " --generations 100 --seed 5 --set epochs=1 --threads 1 --out " +
                  reference.string())
                  .status,
              0);
    ASSERT_NO_FATAL_FAILURE(run_killed_halfway(example(name), killed, 30, 300, "2", shorter));
    const Outcome resumed = esc("run --resume " + killed.string() + " --threads 1");
    ASSERT_EQ(resumed.status, 0) << resumed.output;
    expect_same_results(reference, killed, {name == "behavior_map" ? "CC_8_2" : "C"}, 3);
    EXPECT_EQ(esc("export " + reference.string() + " --table metrics").output,
              esc("export " + killed.string() + " --table metrics").output)
        << name;
  }
}

// Lehman & Stanley's medium maze: one study of CMA-ES, novelty search (alone and with the
// fitness) and MAP-Elites, killed mid-study, resumes to exactly the unbroken study.
TEST(MultiObjective, TheMazeStudyKilledMidStudyResumesToTheUnbrokenStudy) {
  const std::string mazes = std::string(ESC_SOURCE_DIR) + "/experiments/lehman_stanley/mazes.esc";
  const fs::path reference = scratch("maze-reference"), killed = scratch("maze-killed");
  ASSERT_EQ(esc("run " + mazes + " --runs 2 --generations 100 --seed 5 --set steps=30 --threads 1 --out " +
                reference.string())
                .status,
            0);
  // 4 conditions x 2 runs x 100 generations.
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(mazes, killed, 150, 800, "2", {"--runs", "2", "--set", "steps=30"}));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 1");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_EQ(results_without_times(reference), results_without_times(killed));
  EXPECT_EQ(esc("export " + reference.string() + " --table metrics").output,
            esc("export " + killed.string() + " --table metrics").output);
  // The mazes declare success: every run's evaluations to success (none reach the goal in 30
  // steps) and each method's count resume as they were.
  const std::string summary = slurp(reference / "summary.json");
  EXPECT_EQ(summary, slurp(killed / "summary.json"));
  EXPECT_NE(summary.find("\"success\": \"reach_goal > -0.0171875\""), std::string::npos);
}

}  // namespace
