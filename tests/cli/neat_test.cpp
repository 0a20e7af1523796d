// NEAT from the command line (docs/neat.md, "In scripts"): a `neat(...)` controller evolves
// and improves, whatever the threads and runs at once; a run killed mid-run resumes to the
// unbroken one; its metrics (species, hidden nodes, links) are stored per generation; its
// best replays, its topology is exported and drawn; `evaluate from` scores a stored network
// again and `start from` evolves on from it; the shipped example runs.
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

std::string tiny_neat() { return std::string(ESC_SOURCE_DIR) + "/tests/cli/data/tiny_neat.esc"; }

// Field `column` of every row of a CSV export whose field `key_column` is `key`.
std::vector<std::string> column_where(const std::string& csv, std::size_t key_column, const std::string& key,
                                      std::size_t column) {
  std::vector<std::string> out;
  for (const auto& row : csv_rows(csv))
    if (row.size() > std::max(key_column, column) && row[key_column] == key) out.push_back(row[column]);
  return out;
}

TEST(Neat, ANeatControllerEvolvesAndImprovesWhateverTheThreadsAndRunsAtOnce) {
  const fs::path one = scratch("neat-threads-1");
  const fs::path two = scratch("neat-threads-2");
  const Outcome a = esc("run " + tiny_neat() + " --threads 1 --out " + one.string());
  ASSERT_EQ(a.status, 0) << a.output;
  const Outcome b = esc("run " + tiny_neat() + " --threads 2 --runs-at-once 3 --out " + two.string());
  ASSERT_EQ(b.status, 0) << b.output;
  expect_same_results(one, two, {"NC", "NS"}, 2);
  // Every run of both controllers found a better network than its first generation's best
  // (export: controller 1, run 2, generation 5, best 6).
  const auto rows = csv_rows(esc("export " + one.string() + " --format csv").output);
  const auto summary = read_json(one / "summary.json");
  for (const std::string c : {"NC", "NS"})
    for (int run = 1; run <= 2; ++run) {
      double gen0 = 0.0;
      for (const auto& r : rows)
        if (r.size() > 6 && r[1] == c && r[2] == std::to_string(run) && r[5] == "0") gen0 = std::stod(r[6]);
      EXPECT_GT(summary["controllers"][c]["runs"][run - 1]["best_fitness"].get<double>(), gen0) << c << " run " << run;
    }
  // NEAT's own numbers per generation: 2 controllers x 2 runs x 6 generations each.
  const Outcome metrics = esc("export " + one.string() + " --table metrics");
  ASSERT_EQ(metrics.status, 0) << metrics.output;
  for (const char* m : {"species", "hidden_nodes", "enabled_links", "threshold"})
    EXPECT_EQ(column_where(metrics.output, 6, m, 3).size(), 24u) << m;
  EXPECT_EQ(column_where(metrics.output, 6, "species", 3).front(), "neat");
  // Each run's best network, node by node and link by link: NC's 8 inputs, the bias and 2
  // outputs at least, and every one of the minimal start's 18 links (enabled or not).
  const Outcome topology = esc("export " + one.string() + " --table topology");
  ASSERT_EQ(topology.status, 0) << topology.output;
  EXPECT_EQ(topology.output.substr(0, topology.output.find('\n')),
            "experiment,condition,controller,run,member,cell,element,id,kind,activation,in,out,weight,enabled");
  int nodes = 0, links = 0, outputs = 0;
  for (const auto& r : csv_rows(topology.output)) {
    ASSERT_EQ(r.size(), 14u);
    if (r[0] == "experiment") continue;
    EXPECT_EQ(r[4], "best");   // NEAT keeps no genomes beside each run's best
    if (r[2] == "NC" && r[3] == "1") {
      nodes += r[6] == "node" ? 1 : 0;
      links += r[6] == "link" ? 1 : 0;
      if (r[8] == "output") {
        ++outputs;
        EXPECT_EQ(r[9], "tanh");   // the classical head's activation
      }
    }
  }
  EXPECT_GE(nodes, 11);
  EXPECT_GE(links, 18);
  EXPECT_EQ(outputs, 2);
  const auto json = nlohmann::json::parse(esc("export " + one.string() + " --table topology --format json").output);
  EXPECT_EQ(static_cast<int>(json.size()), static_cast<int>(csv_rows(topology.output).size()) - 1);
  // The report draws each run's best network: a circle per node, a line per enabled link.
  ASSERT_EQ(esc("report " + one.string()).status, 0);
  const std::string svg = slurp(one / "figures" / "neat_basic-network-NC-run-01.svg");
  int circles = 0;
  for (std::size_t at = svg.find("<circle"); at != std::string::npos; at = svg.find("<circle", at + 1)) ++circles;
  EXPECT_EQ(circles, nodes);
  EXPECT_TRUE(fs::exists(one / "figures" / "neat_basic-network-NS-run-02.svg"));
  EXPECT_TRUE(fs::exists(one / "figures" / "neat_basic-metrics.svg"));
}

TEST(Neat, ANeatRunKilledMidRunResumesToTheUnbrokenRun) {
  const fs::path reference = scratch("neat-reference");
  const fs::path killed = scratch("neat-killed");
  ASSERT_EQ(esc("run " + tiny_neat() + " --generations 100 --seed 5 --threads 1 --out " + reference.string()).status, 0);
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tiny_neat(), killed, 40, 400, "2"));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 1");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_results(reference, killed, {"NC", "NS"}, 2);
  EXPECT_EQ(esc("export " + reference.string() + " --table metrics").output,
            esc("export " + killed.string() + " --table metrics").output);
}

TEST(Neat, ANeatRunScoredByNoveltyArchivesAndResumesToTheUnbrokenRun) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/tiny_neat_novelty.esc";
  const fs::path reference = scratch("neat-novelty-reference");
  const fs::path killed = scratch("neat-novelty-killed");
  ASSERT_EQ(esc("run " + script + " --generations 100 --seed 5 --threads 1 --out " + reference.string()).status, 0);
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(script, killed, 40, 200, "2"));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 1");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_results(reference, killed, {"NC"}, 2);
  const std::string metrics = esc("export " + reference.string() + " --table metrics").output;
  EXPECT_EQ(metrics, esc("export " + killed.string() + " --table metrics").output);
  // The archive grows, and holds the behaviors the run stored.
  const std::vector<std::string> archive = column_where(metrics, 6, "archive", 7);
  ASSERT_EQ(archive.size(), 200U);
  EXPECT_LT(std::stod(archive.front()), std::stod(archive[99]));
  const Outcome members = esc("export " + reference.string() + " --table archive");
  ASSERT_EQ(members.status, 0) << members.output;
  EXPECT_EQ(members.output, esc("export " + killed.string() + " --table archive").output);
  EXPECT_GT(csv_rows(members.output).size(), 10U);
}

// NEAT networks under NSGA-II (two objectives), novelty search and MAP-Elites, varied by
// NEAT's operators: each improves or grows, its front or archive holds graph genomes (each
// run's best drawn and exported as a network), and a run killed mid-run resumes to the
// unbroken one, fronts and archives included.
TEST(Neat, NeatNetworksUnderEverySelectionResumeToTheUnbrokenRun) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/tiny_neat_selections.esc";
  const std::vector<std::string> controllers = {"NC", "NC_nsga2", "NC_novelty", "NC_me"};
  const fs::path reference = scratch("neat-selections-reference");
  const fs::path killed = scratch("neat-selections-killed");
  const Outcome whole = esc("run " + script + " --generations 100 --seed 5 --threads 1 --out " + reference.string());
  ASSERT_EQ(whole.status, 0) << whole.output;
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(script, killed, 100, 800, "2"));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 1");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_results(reference, killed, controllers, 2);
  for (const std::string table : {"front", "archive", "metrics", "topology"})
    EXPECT_EQ(esc("export " + reference.string() + " --table " + table).output,
              esc("export " + killed.string() + " --table " + table).output)
        << table;
  // Every controller's best network has grown hidden nodes in some run, whatever selected it;
  // NSGA-II's final fronts and MAP-Elites' final archives are there too, network by network.
  const std::string topology = esc("export " + reference.string() + " --table topology").output;
  for (const std::string& c : controllers) {
    int hidden = 0;
    for (const auto& r : csv_rows(topology))
      if (r.size() == 14 && r[2] == c && r[4] == "best" && r[8] == "hidden") ++hidden;
    EXPECT_GT(hidden, 0) << c;
  }
  std::set<std::string> front_cells, archive_cells, others;
  for (const auto& r : csv_rows(topology)) {
    if (r.size() != 14 || r[4] == "best" || r[0] == "experiment") continue;
    if (r[2] == "NC_nsga2" && r[3] == "1" && r[4] == "front") front_cells.insert(r[5]);
    else if (r[2] == "NC_me" && r[3] == "1" && r[4] == "archive") archive_cells.insert(r[5]);
    else if (r[3] == "1") others.insert(r[2] + " " + r[4]);
  }
  EXPECT_GT(front_cells.size(), 1u);
  EXPECT_GT(archive_cells.size(), 10u);
  // Novelty search without the fitness keeps behaviors, not networks; NEAT its best alone.
  EXPECT_TRUE(others.empty()) << *others.begin();
  // NSGA-II's fronts (both objectives) and MAP-Elites' archive hold measured members.
  EXPECT_GT(column_where(esc("export " + reference.string() + " --table front").output, 2, "NC_nsga2", 7).size(), 10u);
  EXPECT_GT(column_where(esc("export " + reference.string() + " --table archive").output, 2, "NC_me", 6).size(), 10u);
  ASSERT_EQ(esc("report " + reference.string()).status, 0);
  EXPECT_TRUE(fs::exists(reference / "figures" / "selections-network-NC_me-run-02.svg"));
}

TEST(Neat, TheBestNetworkReplaysAndIsEvaluatedAndEvolvedOnFromStore) {
  const fs::path dir = scratch("neat-start-from");
  const std::string common = " --threads 2 --cache " + (dir / "cache").string();
  const Outcome again = esc("run " + tiny_neat() + " --experiment again --out " + (dir / "again").string() + common);
  ASSERT_EQ(again.status, 0) << again.output;
  const Outcome onwards =
      esc("run " + tiny_neat() + " --experiment onwards --out " + (dir / "onwards").string() + common);
  ASSERT_EQ(onwards.status, 0) << onwards.output;
  fs::path basic;
  for (const auto& e : fs::directory_iterator(dir / "cache"))
    if (e.path().filename().string().rfind("neat_basic-", 0) == 0) basic = e.path();
  ASSERT_FALSE(basic.empty());
  const auto stored = read_json(basic / "summary.json");
  const auto evaluated = read_json(dir / "again" / "summary.json");
  const auto evolved = read_json(dir / "onwards" / "summary.json");
  for (const char* c : {"NC", "NS"})
    for (int r = 0; r < 2; ++r) {
      const double was = stored["controllers"][c]["runs"][r]["best_fitness"].get<double>();
      // A fixed start pose and no noise: the same network scores the same, to the last bit.
      EXPECT_EQ(evaluated["controllers"][c]["runs"][r]["best_fitness"].get<double>(), was) << c << " run " << r;
      if (std::string(c) == "NC") {   // member 0 of generation 0 is the stored network, unchanged
        EXPECT_GE(evolved["controllers"][c]["runs"][r]["best"][0].get<double>(), was) << "run " << r;
      }
    }
  const Outcome replayed = esc("replay " + basic.string() + " --out " + (dir / "replays").string());
  ASSERT_EQ(replayed.status, 0) << replayed.output;
  EXPECT_NE(replayed.output.find("NC"), std::string::npos) << replayed.output;
}

// The shipped example compares fixed networks evolved by the ES with NEAT networks in one
// experiment, each controller by its own algorithm.
TEST(Neat, TheExampleComparesNeatWithFixedNetworksInOneExperiment) {
  const fs::path dir = scratch("neat-example");
  const Outcome o = esc("run " + std::string(ESC_SOURCE_DIR) + "/examples/neat_obstacle_avoidance.esc --runs 1 "
                        "--generations 2 --set epochs=1 --out " + dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("8-neat-2"), std::string::npos) << o.output;
  const std::string csv = esc("export " + dir.string() + " --format csv").output;
  for (const char* c : {"CC_8_2", "CC_8_20_2"}) EXPECT_EQ(column_where(csv, 1, c, 15), std::vector<std::string>(2, "es"));
  for (const char* c : {"NEAT_8_2", "NEAT_SC"})
    EXPECT_EQ(column_where(csv, 1, c, 15), std::vector<std::string>(2, "neat"));
}

// Its study compares NEAT and fixed networks in both conditions (with and without inertia):
// every controller has its runs in each, and the study's tables pair them across conditions.
TEST(Neat, TheExamplesStudyComparesNeatWithFixedNetworksAcrossConditions) {
  const fs::path dir = scratch("neat-study");
  const Outcome o = esc("run " + std::string(ESC_SOURCE_DIR) + "/examples/neat_obstacle_avoidance.esc --experiment "
                        "neat_inertia --runs 2 --generations 2 --set epochs=1 --set steps=40 --out " + dir.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const auto summary = read_json(dir / "summary.json");
  ASSERT_EQ(summary["conditions"].size(), 2u);
  for (const auto& condition : summary["conditions"]) {
    for (const char* c : {"CC_8_2", "CC_8_20_2", "NEAT_8_2", "NEAT_SC"})
      EXPECT_EQ(condition["controllers"][c]["runs"].size(), 2u) << condition["name"] << " " << c;
    EXPECT_EQ(condition["controllers"]["NEAT_8_2"]["architecture"], "8-neat-2");
  }
  EXPECT_NE(o.output.find("NEAT_8_2"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("no_inertia"), std::string::npos) << o.output;
  const Outcome topology = esc("export " + dir.string() + " --table topology");
  ASSERT_EQ(topology.status, 0) << topology.output;
  EXPECT_FALSE(column_where(topology.output, 1, "no_inertia", 2).empty());
}

}  // namespace
