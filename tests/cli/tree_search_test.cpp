// Tree controllers evolved by NSGA-II, MAP-Elites and novelty search through the `esc`
// binary (tests/cli/data/tree_search.esc): each runs, exports its front or archive, replays a
// member as a tree, gives the same results on any number of threads and runs at once, and a
// run killed mid-run resumes to exactly the unbroken run.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

std::string tree_search() { return std::string(ESC_SOURCE_DIR) + "/tests/cli/data/tree_search.esc"; }

const std::vector<std::string> kTrees{"TN", "TM", "TV"};   // by nsga2, map_elites, novelty

// The lines of an export that name `algorithm` in its algorithm column.
int rows_of(const std::string& csv, const std::string& algorithm) {
  int n = 0;
  std::size_t at = 0;
  while ((at = csv.find("," + algorithm + ",", at)) != std::string::npos) {
    ++n;
    ++at;
  }
  return n;
}

TEST(TreeSearchCli, EachAlgorithmEvolvesTreesExportsAndReplaysItsMembers) {
  const fs::path dir = scratch("tree-search");
  const Outcome run = esc("run " + tree_search() + " --threads 2 --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const auto s = read_json(dir / "summary.json");
  for (const std::string& c : kTrees) {
    EXPECT_EQ(s["controllers"][c]["architecture"], "tree wheels") << c;
    EXPECT_EQ(s["controllers"][c]["runs"][0]["best_tree"].get<std::string>().rfind("wheels(", 0), 0U) << c;
  }
  const Outcome front = esc("export " + dir.string() + " --table front");
  ASSERT_EQ(front.status, 0) << front.output;
  EXPECT_GT(rows_of(front.output, "nsga2"), 0) << front.output;
  EXPECT_GT(rows_of(front.output, "novelty"), 0) << front.output;
  const Outcome archive = esc("export " + dir.string() + " --table archive");
  ASSERT_EQ(archive.status, 0) << archive.output;
  EXPECT_GT(rows_of(archive.output, "map_elites"), 0) << archive.output;

  for (const std::string& c : {std::string("TN"), std::string("TV")}) {
    const Outcome member = esc("replay " + dir.string() + " --controller " + c + " --run 1 --member 0");
    EXPECT_EQ(member.status, 0) << c << ": " << member.output;
  }
  // The first archived cell of TM's first run.
  const std::string rows = archive.output;
  const std::size_t at = rows.find(",TM,map_elites,1,");
  ASSERT_NE(at, std::string::npos) << rows.substr(0, 400);
  std::vector<std::string> cells;
  std::string line = rows.substr(at, rows.find('\n', at) - at);
  for (std::size_t from = 0, comma; (comma = line.find(',', from)) != std::string::npos; from = comma + 1)
    cells.push_back(line.substr(from, comma - from));
  ASSERT_GE(cells.size(), 6u) << line;
  const Outcome elite = esc("replay " + dir.string() + " --controller TM --run 1 --member " + cells[5]);
  EXPECT_EQ(elite.status, 0) << line << "\n" << elite.output;
}

TEST(TreeSearchCli, AnyNumberOfThreadsGivesTheSameResults) {
  const fs::path one = scratch("tree-search-1"), two = scratch("tree-search-2");
  const std::string run = "run " + tree_search() + " --generations 4 --threads ";
  ASSERT_EQ(esc(run + "1 --out " + one.string()).status, 0);
  ASSERT_EQ(esc(run + "2 --runs-at-once 2 --out " + two.string()).status, 0);
  expect_same_results(one, two, kTrees, 2);
  for (const std::string table : {"metrics", "front", "archive"})
    EXPECT_EQ(esc("export " + one.string() + " --table " + table).output,
              esc("export " + two.string() + " --table " + table).output)
        << table;
}

TEST(TreeSearchCli, ARunKilledMidRunResumesToTheUnbrokenRun) {
  const fs::path reference = scratch("tree-search-reference"), killed = scratch("tree-search-killed");
  const std::vector<std::string> one_run{"--runs", "1"};
  ASSERT_EQ(esc("run " + tree_search() + " --generations 100 --seed 5 --runs 1 --threads 1 --out " +
                reference.string())
                .status,
            0);
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tree_search(), killed, 30, 300, "2", one_run));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 1");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_results(reference, killed, kTrees, 1);
  for (const std::string table : {"metrics", "front", "archive"})
    EXPECT_EQ(esc("export " + reference.string() + " --table " + table).output,
              esc("export " + killed.string() + " --table " + table).output)
        << table;
}

}  // namespace
