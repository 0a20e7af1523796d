// The same script under `mpirun -np 3` gives the same results as one process: every rank
// breeds the same populations, evaluations are shared out dynamically, results gathered.
#include <unistd.h>

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"

namespace {

using namespace cli_test;

std::string mpirun(int ranks) {
  std::string cmd = std::string(ESC_MPIEXEC) + " --oversubscribe -np " + std::to_string(ranks);
  if (::geteuid() == 0) cmd += " --allow-run-as-root";
  return cmd + " " + ESC_BINARY + " ";
}

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
  const std::string args = "run " + tiny() + " --threads 1 --seed 5 --out ";
  const Outcome a = esc(args + one.string());
  ASSERT_EQ(a.status, 0) << a.output;
  const Outcome b = shell(mpirun(3) + args + three.string());
  ASSERT_EQ(b.status, 0) << b.output;
  EXPECT_EQ(results_only(read_json(one / "summary.json")), results_only(read_json(three / "summary.json")));
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

TEST(Mpi, AnExistingOutputDirectoryStopsEveryRank) {
  const fs::path out = scratch("mpi-exists");
  fs::create_directories(out);
  std::ofstream(out / "keep.txt") << "precious";
  const Outcome o = shell(mpirun(3) + "run " + tiny() + " --out " + out.string());
  EXPECT_NE(o.status, 0) << o.output;
  EXPECT_EQ(slurp(out / "keep.txt"), "precious");
}

}  // namespace
