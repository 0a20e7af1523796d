// End to end: the energy experiment of section 4 with its evolved behavior libraries,
// the dependency cache, and experiments that evaluate or start from stored controllers.
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <regex>
#include <string>
#include <thread>
#include <vector>

#include "esc_process.hpp"
#include "results_support.hpp"

namespace {

using namespace cli_test;

std::string run_csv(int run) {
  char name[32];
  std::snprintf(name, sizeof name, "run-%02d.csv", run);
  return name;
}

// Best fitness of generation 0 of each run of `controller`, from its per-run CSV files.
std::vector<double> generation0_best(const fs::path& out, const std::string& controller, int runs) {
  std::vector<double> best;
  for (int r = 1; r <= runs; ++r) {
    std::ifstream in(out / controller / run_csv(r));
    std::string header, row;
    std::getline(in, header);
    std::getline(in, row);
    best.push_back(std::stod(row.substr(row.find(',') + 1)));
  }
  return best;
}

// The shipped experiments, copied so that the test may edit them.
fs::path copy_of_experiments(const std::string& name) {
  const fs::path dir = scratch(name);
  fs::copy(fs::path(ESC_SOURCE_DIR) / "experiments", dir, fs::copy_options::recursive);
  return dir;
}

const std::string kSmall = "--runs 2 --generations 4 --set epochs=3 --set steps=300 --set mu=5 --set lambda=25 --threads 2";

TEST(PaperEnergy, RunsAllFourArchitecturesAndReRunsOnlyWhatAChangeTouches) {
  const fs::path exp = copy_of_experiments("energy");
  const fs::path cache = exp / "cache", out = exp / "out";
  const std::string script = (exp / "paper" / "energy.esc").string();
  const Outcome o = esc("run " + script + " " + kSmall + " --out " + out.string() + " --cache " + cache.string());
  ASSERT_EQ(o.status, 0) << o.output;
  for (const char* dep : {"obstacle_avoidance", "light_following", "stop", "area_sweeping"})
    EXPECT_NE(o.output.find(std::string("esc: dependency ") + dep + ": running into"), std::string::npos) << dep;
  for (const char* row : {"CC           17-5r-2           127", "SC           17-5r-6           151",
                          "CS           17-5r-4           139", "SS           17-5r-4           139"})
    EXPECT_NE(o.output.find(row), std::string::npos) << row << "\n" << o.output;
  EXPECT_TRUE(std::regex_search(o.output, std::regex("CS +avoid \\d+%, follow \\d+%, stop \\d+%, sweep \\d+%")));
  EXPECT_TRUE(std::regex_search(o.output, std::regex("SS +avoid \\d+%, follow \\d+%, stop \\d+%, sweep \\d+%")));

  // The paper: supervisors start high, as picking an evolved behavior already moves the
  // robot well; a random direct controller does not. With these small settings the
  // symbolic supervisor beats both direct controllers at generation 0 in every run, and
  // the classical one beats the classical controller.
  const auto cc = generation0_best(out, "CC", 2), sc = generation0_best(out, "SC", 2);
  const auto cs = generation0_best(out, "CS", 2), ss = generation0_best(out, "SS", 2);
  for (int r = 0; r < 2; ++r) {
    EXPECT_GT(ss[r], 1.5 * cc[r]) << "run " << r + 1;
    EXPECT_GT(ss[r], sc[r]) << "run " << r + 1;
    EXPECT_GT(cs[r], 1.5 * cc[r]) << "run " << r + 1;
  }

  // Editing the stop behavior's fitness re-runs `stop`, and reuses the other three.
  const fs::path stop = exp / "paper" / "stop.esc";
  std::string text = slurp(stop);
  const auto at = text.find("step: 1 - com_speed");
  ASSERT_NE(at, std::string::npos);
  text.replace(at, 19, "step: 1 - 0.9 * com_speed");
  std::ofstream(stop) << text;
  const Outcome again = esc("run " + script + " " + kSmall + " --out " + (exp / "out2").string() + " --cache " + cache.string());
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("esc: dependency stop: running into"), std::string::npos) << again.output;
  for (const char* dep : {"obstacle_avoidance", "light_following", "area_sweeping"})
    EXPECT_NE(again.output.find(std::string("esc: dependency ") + dep + ": reused"), std::string::npos) << dep;
  EXPECT_EQ(again.output.find("running into " + (cache / "obstacle_avoidance").string()), std::string::npos);
}

TEST(StartFrom, EvaluatingAStoredGenomeAgainGivesItsStoredFitness) {
  const fs::path dir = scratch("start-from");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/start_from.esc";
  const std::string common = " --threads 2 --cache " + (dir / "cache").string();
  const Outcome o = esc("run " + script + " --experiment again --out " + (dir / "again").string() + common);
  ASSERT_EQ(o.status, 0) << o.output;
  const Outcome w = esc("run " + script + " --experiment onwards --out " + (dir / "onwards").string() + common);
  ASSERT_EQ(w.status, 0) << w.output;
  EXPECT_NE(w.output.find("esc: dependency basic: reused"), std::string::npos) << w.output;
  fs::path basic;
  for (const auto& e : fs::directory_iterator(dir / "cache"))
    if (e.path().filename().string().rfind("basic-", 0) == 0) basic = e.path();
  ASSERT_FALSE(basic.empty());
  const nlohmann::json stored = read_json(basic / "summary.json");
  const nlohmann::json evaluated = read_json(dir / "again" / "summary.json");
  const nlohmann::json onwards = read_json(dir / "onwards" / "summary.json");
  for (const char* c : {"CC", "SC"})
    for (int r = 0; r < 3; ++r) {
      const double was = stored["controllers"][c]["runs"][r]["best_fitness"].get<double>();
      // Seed-independent setting: the same genome scores the same, to the last bit.
      EXPECT_EQ(evaluated["controllers"][c]["runs"][r]["best_fitness"].get<double>(), was) << c << " run " << r;
      EXPECT_EQ(evaluated["controllers"][c]["runs"][r]["best"].size(), 1u);
      if (std::string(c) == "CC") {   // offspring 0 of generation 0 is the stored genome, unchanged
        EXPECT_GE(onwards["controllers"][c]["runs"][r]["best"][0].get<double>(), was) << " run " << r;
      }
    }
}

TEST(DependencyCache, TwoProcessesMayShareACache) {
  const fs::path dir = scratch("shared-cache");
  fs::create_directories(dir);
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/start_from.esc";
  const std::string run = std::string(ESC_BINARY) + " run " + script + " --experiment again --threads 1 --cache " +
                          (dir / "cache").string() + " --out ";
  const Outcome o = shell(run + (dir / "a").string() + " > " + (dir / "a.log").string() + " 2>&1 & " + run +
                          (dir / "b").string() + " > " + (dir / "b.log").string() + " 2>&1; s=$?; wait $!; t=$?; "
                          "exit $((s + t))");
  ASSERT_EQ(o.status, 0) << slurp(dir / "a.log") << slurp(dir / "b.log");
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir / "cache")) {
    ++entries;
    EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos) << e.path();
  }
  EXPECT_EQ(entries, 1);
  EXPECT_EQ(read_json(dir / "a" / "summary.json")["controllers"], read_json(dir / "b" / "summary.json")["controllers"]);
  // Prepared once: one process ran the dependency, the other waited for it and reused it.
  const std::string logs = slurp(dir / "a.log") + slurp(dir / "b.log");
  const auto count = [&](const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = logs.find(what); at != std::string::npos; at = logs.find(what, at + 1)) ++n;
    return n;
  };
  EXPECT_EQ(count("dependency basic: running into"), 1u) << logs;
  EXPECT_EQ(count("dependency basic: reused"), 1u) << logs;
}

TEST(DependencyCache, ARunKilledInADependencyContinuesIt) {
  const fs::path dir = scratch("killed-dependency");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/evolved.esc";
  const std::vector<std::string> args = {"run",           script, "--experiment", "supervised", "--generations",
                                         "300",           "--set", "epochs=10",   "--threads",  "1"};
  std::string line;
  for (const std::string& a : args) line += a + " ";
  const Outcome reference = esc(line + "--cache " + (dir / "ref").string() + " --out " + (dir / "ref-out").string());
  ASSERT_EQ(reference.status, 0) << reference.output;

  // Killed while `basic` (2 runs x 300 generations) runs into its .partial directory.
  std::vector<std::string> killed = args;
  killed.insert(killed.end(), {"--cache", (dir / "cache").string(), "--out", (dir / "killed").string()});
  const pid_t child = spawn_esc(killed);
  ASSERT_GE(child, 0);
  fs::path partial;
  for (int i = 0; i < 3000 && partial.empty(); ++i) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir / "cache", ec))
      if (e.is_directory() && e.path().filename().string().find(".partial-") != std::string::npos) partial = e.path();
    if (partial.empty()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_FALSE(partial.empty());
  const Killed k = kill_when_committed(child, partial, 40);
  ASSERT_TRUE(k.still_running) << "the dependency finished before it could be killed";
  ASSERT_LT(committed_generations(partial), 600);

  const Outcome again =
      esc(line + "--cache " + (dir / "cache").string() + " --out " + (dir / "again").string());
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("continuing the run a stopped process left in " + partial.string()), std::string::npos)
      << again.output;
  fs::path ref_basic, basic;
  for (const auto& e : fs::directory_iterator(dir / "ref")) ref_basic = e.path();
  for (const auto& e : fs::directory_iterator(dir / "cache")) {
    EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos) << e.path();
    basic = e.path();
  }
  expect_same_summary(ref_basic, basic);
  expect_same_summary(dir / "ref-out", dir / "again");
}

}  // namespace
