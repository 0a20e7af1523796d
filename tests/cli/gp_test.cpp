// Genetic programming end to end through the `esc` binary: a network and its GP twin in
// one compare line (the same results for one or two threads), a killed GP run resumed
// bit for bit, a tree supervisor over an evolved network (its experiment runs first), and
// the best trees in the run directory, the export and the report.
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

TEST(GpCli, NetworkAndTreesInOneCompareLineSameForOneOrTwoThreads) {
  const fs::path a = scratch("gp1");
  const fs::path b = scratch("gp2");
  const Outcome one = esc("run " + tiny_gp() + " --threads 1 --out " + a.string());
  ASSERT_EQ(one.status, 0) << one.output;
  ASSERT_EQ(esc("run " + tiny_gp() + " --threads 2 --out " + b.string()).status, 0);
  expect_same_summary(a, b);
  // The table has a row per controller, and the best trees as script code.
  EXPECT_NE(one.output.find("GS           tree actions       40"), std::string::npos) << one.output;
  EXPECT_NE(one.output.find("GW           tree wheels        40"), std::string::npos) << one.output;
  EXPECT_NE(one.output.find("SC vs GS"), std::string::npos) << one.output;
  EXPECT_NE(one.output.find("GW           run 1 best tree (fitness"), std::string::npos) << one.output;
  const auto s = read_json(a / "summary.json");
  EXPECT_EQ(s["controllers"]["GW"]["architecture"], "tree wheels");
  EXPECT_EQ(s["controllers"]["GW"]["genome_size"], 40);
  EXPECT_EQ(s["controllers"]["GS"]["runs"][0]["behavior_usage"].size(), 3U);
  const std::string tree = s["controllers"]["GW"]["runs"][1]["best_tree"].get<std::string>();
  EXPECT_EQ(tree.rfind("wheels(", 0), 0U) << tree;
  EXPECT_FALSE(s["controllers"]["SC"]["runs"][0].contains("best_tree"));
  // A Wheels tree is written as a behavior to paste; its script compiles.
  const std::string best = slurp(a / "GW" / "run-02.best.esc");
  EXPECT_NE(best.find("behavior GW_run02() { " + tree + " }"), std::string::npos) << best;
  const fs::path pasted = scratch("gp-paste.esc");
  std::ofstream(pasted) << best << "controller p = supervisor(mlp(ir[0]), behaviors [GW_run02])\n";
  const Outcome check = esc("check " + pasted.string());
  EXPECT_EQ(check.status, 0) << check.output;
  EXPECT_EQ(read_json(a / "GS" / "run-01.best.json")["tree"], s["controllers"]["GS"]["runs"][0]["best_tree"]);

  // Export and report read tree controllers too.
  const auto j = nlohmann::json::parse(esc("export " + a.string() + " --format json").output);
  const auto& gw = j["experiments"][0]["controllers"]["GW"];
  EXPECT_EQ(gw["head"], "tree");
  EXPECT_EQ(gw["runs"][1]["best_tree"], tree);
  EXPECT_NE(esc("export " + a.string() + " --format csv").output.find("\ntiny_gp,GS,2,"), std::string::npos);
  const Outcome report = esc("report " + a.string());
  EXPECT_EQ(report.status, 0) << report.output;
  EXPECT_NE(slurp(a / "report.html").find(tree.substr(0, 20)), std::string::npos);
}

TEST(GpCli, KilledGpRunResumesBitIdentical) {
  const fs::path reference = scratch("gp-reference");
  const fs::path killed = scratch("gp-killed");
  const std::string args = " --generations 100 --seed 5 ";   // 3 controllers x 2 runs x 100 generations
  ASSERT_EQ(esc("run " + tiny_gp() + args + "--threads 2 --out " + reference.string()).status, 0);
  // Killed once the ES controller's runs are done and the GP runs are under way.
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tiny_gp(), killed, 240, 600));

  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 2");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming"), std::string::npos) << resumed.output;
  expect_same_summary(reference, killed);
  for (const char* file : {"GS/run-01.best.json", "GS/run-02.best.json", "GW/run-01.best.esc", "GW/run-02.best.esc"})
    EXPECT_EQ(slurp(reference / file), slurp(killed / file)) << file;
  EXPECT_EQ(committed_generations(killed), 600);
}

TEST(GpCli, TreeSupervisorOverAnEvolvedNetwork) {
  const fs::path out = scratch("gp-supervised");
  const Outcome o = esc("run " + tiny_gp() + " --experiment tree_supervised --threads 2 --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("esc: dependency basic: running into"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("controller CC frozen with the best genome of 2 runs"), std::string::npos) << o.output;
  const auto s = read_json(out / "summary.json");
  const auto& tv = s["controllers"]["TV"];
  EXPECT_EQ(tv["architecture"], "tree behaviors");
  ASSERT_EQ(tv["runs"].size(), 2U);
  EXPECT_EQ(tv["runs"][0]["behavior_usage"].size(), 3U);
  EXPECT_TRUE(tv["runs"][0]["behavior_usage"].contains("evolved_avoid"));
}

}  // namespace
