// The same script under `mpirun -np 3` gives the same results as one process: every rank
// breeds the same populations, evaluations (of several runs at once where generations are
// small) are shared out dynamically, results gathered; experiments a script needs first
// run under MPI too, and their cache is reused by a single process.
#include <unistd.h>

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

// The launcher with its options, before the ranks' programs.
std::string launcher() {
  std::string cmd = std::string(ESC_MPIEXEC) + " --oversubscribe";
  if (::geteuid() == 0) cmd += " --allow-run-as-root";
  return cmd;
}

std::string mpirun(int ranks) { return launcher() + " -np " + std::to_string(ranks) + " " + ESC_BINARY + " "; }

nlohmann::json results_only(const nlohmann::json& summary) {
  nlohmann::json r;
  for (const auto& [name, c] : summary["controllers"].items())
    for (const auto& run : c["runs"])
      r[name].push_back({run["seed"], run["best_fitness"], run["best"], run["mean"]});
  return r;
}

TEST(Mpi, ThreeRanksGiveTheSameSummaryAsOneProcess) {
  const fs::path one = scratch("mpi-1");
  const fs::path three = scratch("mpi-3");
  const std::string args = "run " + tiny() + " --seed 5 --out ";
  const Outcome a = esc(args + one.string() + " --threads 1");
  ASSERT_EQ(a.status, 0) << a.output;
  // Two threads per rank: each thread takes evaluations from the shared counter itself.
  const Outcome b = shell(mpirun(3) + args + three.string() + " --threads 2");
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_EQ(results_only(read_json(one / "summary.json")), results_only(read_json(three / "summary.json")));
}

// A group (`--set robots=3`, docs/groups.md): each evaluation steps its three robots wherever
// it runs.
TEST(Mpi, AGroupUnderThreeRanksGivesOneProcesssResults) {
  const fs::path one = scratch("mpi-group-1");
  const fs::path three = scratch("mpi-group-3");
  const std::string args = "run " + tiny() + " --seed 5 --generations 3 --set robots=3 --out ";
  const Outcome a = esc(args + one.string() + " --threads 1 --runs-at-once 1");
  ASSERT_EQ(a.status, 0) << a.output;
  const Outcome b = shell(mpirun(3) + args + three.string() + " --threads 2");
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_EQ(results_only(read_json(one / "summary.json")), results_only(read_json(three / "summary.json")));
}

// Any optimizer: every rank asks the same candidates of the same state.
TEST(Mpi, ThreeRanksGiveOneProcesssCmaesRuns) {
  const fs::path one = scratch("mpi-cmaes-1");
  const fs::path three = scratch("mpi-cmaes-3");
  const std::string args = "run " + tiny() + " --seed 5 --set networks=cmaes --out ";
  const Outcome a = esc(args + one.string() + " --threads 1");
  ASSERT_EQ(a.status, 0) << a.output;
  const Outcome b = shell(mpirun(3) + args + three.string() + " --threads 1");
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_EQ(slurp(one / "summary.json"), slurp(three / "summary.json"));
  EXPECT_EQ(esc("export " + one.string() + " --table metrics").output,
            esc("export " + three.string() + " --table metrics").output);
}

// NSGA-II's front, MAP-Elites' and novelty search's archives: the maze study's every method.
TEST(Mpi, ThreeRanksStoreOneProcesssFrontsAndArchives) {
  const fs::path one = scratch("mpi-mazes-1");
  const fs::path three = scratch("mpi-mazes-3");
  const std::string args = "run " + std::string(ESC_SOURCE_DIR) +
                           "/experiments/lehman_stanley/mazes.esc --runs 2 --generations 3 --set steps=30 --out ";
  const Outcome a = esc(args + one.string() + " --threads 1");
  ASSERT_EQ(a.status, 0) << a.output;
  const Outcome b = shell(mpirun(3) + args + three.string() + " --threads 1");
  ASSERT_EQ(b.status, 0) << b.output;
  for (const std::string table : {"metrics", "front", "archive"})
    EXPECT_EQ(esc("export " + one.string() + " --table " + table).output,
              esc("export " + three.string() + " --table " + table).output)
        << table;
}

TEST(Mpi, AStudyUnderThreeRanksGivesOneProcesssResults) {
  const fs::path one = scratch("mpi-study-1");
  const fs::path three = scratch("mpi-study-3");
  const std::string args = "run " + std::string(ESC_SOURCE_DIR) +
                           "/tests/cli/data/tiny_study.esc --experiment tiny_study_fewer --generations 3 --out ";
  const Outcome a = esc(args + one.string() + " --threads 1");
  ASSERT_EQ(a.status, 0) << a.output;
  const Outcome b = shell(mpirun(3) + args + three.string() + " --threads 1");
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_EQ(slurp(one / "summary.json"), slurp(three / "summary.json"));
}

TEST(Mpi, RanksWithDifferentThreadCountsPoolTheSameRuns) {
  // 1 + 3 + 3 threads: every rank must count 7 workers, so that all pool the same runs
  // (counting its own threads times 3 ranks, rank 0 would pool 3 runs, the others 4).
  const fs::path one = scratch("mpi-mixed-1");
  const fs::path mixed = scratch("mpi-mixed-3");
  const std::string args = "run " + tiny() + " --seed 5 --runs 4 --generations 3 --out ";
  const Outcome a = esc(args + one.string() + " --threads 1");
  ASSERT_EQ(a.status, 0) << a.output;
  const std::string each = std::string(ESC_BINARY) + " " + args + mixed.string();
  const Outcome b = shell(launcher() + " -np 1 " + each + " --threads 1 : -np 2 " + each + " --threads 3");
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_EQ(results_only(read_json(one / "summary.json")), results_only(read_json(mixed / "summary.json")));
}

TEST(Mpi, DiagnosticsArePrintedOnceNotOncePerRank) {
  const std::string bad = std::string(ESC_SOURCE_DIR) + "/tests/bad/unknown_one_letter_name.esc";
  const Outcome o = shell(mpirun(3) + "check " + bad);
  EXPECT_NE(o.status, 0);
  const std::string line = "error: unknown name `q`";
  const auto first = o.output.find(line);
  ASSERT_NE(first, std::string::npos) << o.output;
  EXPECT_EQ(o.output.find(line, first + 1), std::string::npos) << o.output;
}

TEST(Mpi, ThreeRanksGiveTheSameGpResultsAsOneProcess) {
  const fs::path one = scratch("mpi-gp-1");
  const fs::path three = scratch("mpi-gp-3");
  const std::string args = "run " + tiny_gp() + " --threads 1 --seed 5 --out ";
  const Outcome a = esc(args + one.string());
  ASSERT_EQ(a.status, 0) << a.output;
  const Outcome b = shell(mpirun(3) + args + three.string());
  ASSERT_EQ(b.status, 0) << b.output;
  const auto sa = read_json(one / "summary.json");
  const auto sb = read_json(three / "summary.json");
  EXPECT_EQ(results_only(sa), results_only(sb));
  EXPECT_EQ(sa["controllers"]["GS"]["runs"][1]["best_tree"], sb["controllers"]["GS"]["runs"][1]["best_tree"]);
}

TEST(Mpi, DependenciesRunUnderThreeRanksAsInOneProcess) {
  const fs::path dir = scratch("mpi-deps");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/evolved.esc";
  const std::string args = "run " + script + " --experiment supervised --threads 1 --out ";
  const Outcome a = esc(args + (dir / "one").string());
  ASSERT_EQ(a.status, 0) << a.output;
  const Outcome b = shell(mpirun(3) + args + (dir / "three").string() + " --cache " + (dir / "cache").string());
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_NE(b.output.find("esc: dependency basic: running into"), std::string::npos) << b.output;
  // Printed once, by rank 0.
  const auto frozen = b.output.find("controller CC frozen");
  ASSERT_NE(frozen, std::string::npos) << b.output;
  EXPECT_EQ(b.output.find("controller CC frozen", frozen + 1), std::string::npos) << b.output;
  EXPECT_EQ(results_only(read_json(dir / "one" / "summary.json")), results_only(read_json(dir / "three" / "summary.json")));
  // The cache the MPI job filled serves a single process.
  const Outcome c = esc(args + (dir / "again").string() + " --cache " + (dir / "cache").string());
  ASSERT_EQ(c.status, 0) << c.output;
  EXPECT_NE(c.output.find("esc: dependency basic: reused"), std::string::npos) << c.output;
  EXPECT_EQ(results_only(read_json(dir / "one" / "summary.json")), results_only(read_json(dir / "again" / "summary.json")));
}

TEST(Mpi, AnUnwritableDependencyCacheStopsEveryRankCleanly) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/evolved.esc";
  const Outcome o = shell(mpirun(3) + "run " + script + " --experiment supervised --threads 1 --cache /proc/esc-cache --out " +
                          scratch("mpi-bad-cache").string());
  EXPECT_NE(o.status, 0) << o.output;
  const auto first = o.output.find("esc: error: cannot create the dependency cache");
  ASSERT_NE(first, std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("esc: error: cannot create the dependency cache", first + 1), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("MPI_ABORT"), std::string::npos) << o.output;
}

TEST(Mpi, AnExistingOutputDirectoryStopsEveryRank) {
  const fs::path out = scratch("mpi-exists");
  fs::create_directories(out);
  std::ofstream(out / "keep.txt") << "precious";
  const Outcome o = shell(mpirun(3) + "run " + tiny() + " --out " + out.string());
  EXPECT_NE(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("esc: error:"), std::string::npos) << o.output;
  EXPECT_EQ(slurp(out / "keep.txt"), "precious");
}

TEST(Mpi, ARunCarriedOnUnderThreeRanksIsTheLongerRun) {
  const fs::path longer = scratch("mpi-carry-on-4");
  const fs::path two = scratch("mpi-carry-on-2");
  const Outcome a = esc("run " + tiny() + " --seed 5 --threads 1 --generations 4 --out " + longer.string());
  ASSERT_EQ(a.status, 0) << a.output;
  const Outcome b = esc("run " + tiny() + " --seed 5 --threads 1 --generations 2 --out " + two.string());
  ASSERT_EQ(b.status, 0) << b.output;
  const Outcome on = shell(mpirun(3) + "run --resume " + two.string() + " --generations 4 --threads 1");
  ASSERT_EQ(on.status, 0) << on.output;
  EXPECT_EQ(slurp(longer / "summary.json"), slurp(two / "summary.json"));
}

TEST(Mpi, ARunKilledHalfwayResumesUnderThreeRanksBitIdentical) {
  const fs::path reference = scratch("mpi-resume-reference");
  const fs::path killed = scratch("mpi-resume-killed");
  const Outcome a = esc("run " + tiny() + " --generations 100 --seed 5 --threads 1 --out " + reference.string());
  ASSERT_EQ(a.status, 0) << a.output;
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tiny(), killed, 40, 400));
  const Outcome resumed = shell(mpirun(3) + "run --resume " + killed.string() + " --threads 1");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_NE(resumed.output.find("resuming"), std::string::npos) << resumed.output;
  EXPECT_EQ(committed_generations(killed), 400);
  EXPECT_EQ(slurp(reference / "summary.json"), slurp(killed / "summary.json"));
}

}  // namespace
