// Carrying evolution on: `esc run --resume DIR --generations G` extends every run of a
// finished (or interrupted) directory to G generations from its stored populations, step
// sizes and streams, so the directory ends as a run asked for G generations from the start
// with the same seed: the same per-generation statistics, best genomes and summary.json, for
// the ES and GP, on another thread count, and after a kill -9 during the extension. Fewer
// generations than stored is an error that changes nothing. A study is carried on as an
// experiment is, condition by condition, every condition's target stored first. A run
// carried on replays as stored.
#include <string>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

TEST(CarryOn, AnEsRunCarriedOnIsTheLongerRun) {
  const fs::path dir = scratch("carry-on-es");
  const std::string args = "run " + tiny() + " --seed 5 ";
  const Outcome longer = esc(args + "--generations 4 --threads 1 --out " + (dir / "four").string());
  ASSERT_EQ(longer.status, 0) << longer.output;
  const Outcome two = esc(args + "--generations 2 --threads 1 --out " + (dir / "two").string());
  ASSERT_EQ(two.status, 0) << two.output;
  const Outcome on = esc("run --resume " + (dir / "two").string() + " --generations 4 --threads 2");
  ASSERT_EQ(on.status, 0) << on.output;
  EXPECT_NE(on.output.find("carrying tiny"), std::string::npos) << on.output;
  expect_same_results(dir / "two", dir / "four", {"CC", "SC"}, 2);
  EXPECT_EQ(read_json(dir / "two" / "settings.json")["settings"], read_json(dir / "four" / "settings.json")["settings"]);
  // The report's curves run on across the extension.
  const Outcome report = esc("report " + (dir / "two").string());
  ASSERT_EQ(report.status, 0) << report.output;
  EXPECT_EQ(read_json(dir / "two" / "summary.json")["controllers"]["CC"]["runs"][0]["best"].size(), 4u);
  // Its best controllers replay as stored (the run now says 4 generations, its script 2).
  const Outcome replayed = esc("replay " + (dir / "two").string() + " --out " + (dir / "replays").string());
  EXPECT_EQ(replayed.status, 0) << replayed.output;
  EXPECT_NE(replayed.output.find("identical to the stored replay"), std::string::npos) << replayed.output;
  // Asked again: nothing left to do.
  const Outcome again = esc("run --resume " + (dir / "two").string() + " --generations 4");
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("is complete"), std::string::npos) << again.output;
}

TEST(CarryOn, AGpRunCarriedOnIsTheLongerRun) {
  const fs::path dir = scratch("carry-on-gp");
  const std::string args = "run " + tiny_gp() + " --seed 5 ";
  const Outcome longer = esc(args + "--generations 4 --threads 2 --out " + (dir / "four").string());
  ASSERT_EQ(longer.status, 0) << longer.output;
  const Outcome two = esc(args + "--generations 2 --threads 2 --out " + (dir / "two").string());
  ASSERT_EQ(two.status, 0) << two.output;
  const Outcome on = esc("run --resume " + (dir / "two").string() + " --generations 4 --threads 1");
  ASSERT_EQ(on.status, 0) << on.output;
  expect_same_results(dir / "two", dir / "four", {"SC", "GS", "GW"}, 2);
  EXPECT_EQ(slurp(dir / "two" / "GS" / "run-01.best.esc"), slurp(dir / "four" / "GS" / "run-01.best.esc"));
}

TEST(CarryOn, ARunWithDependenciesIsCarriedOnAloneTwice) {
  // `supervised` uses `basic`'s evolved controller: carried on (twice), it keeps the
  // behavior it started with, and its first generations stay as they were.
  const fs::path dir = scratch("carry-on-deps");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/evolved.esc";
  const Outcome run = esc("run " + script + " --experiment supervised --threads 2 --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const std::string three = results_without_times(dir);
  EXPECT_EQ(committed_generations(dir), 2 * 3);
  for (const int g : {4, 5}) {
    const Outcome on = esc("run --resume " + dir.string() + " --generations " + std::to_string(g) + " --threads 1");
    ASSERT_EQ(on.status, 0) << on.output;
    EXPECT_NE(on.output.find("dependency basic: reused"), std::string::npos) << on.output;
    EXPECT_EQ(committed_generations(dir), 2 * g);
  }
  const std::string five = results_without_times(dir);
  // Run 1's three generations are the first lines of its five (the header, then run 1).
  std::stringstream a(three), b(five);
  std::string line_a, line_b;
  for (int k = 0; k < 1 + 3; ++k) {
    ASSERT_TRUE(std::getline(a, line_a) && std::getline(b, line_b));
    EXPECT_EQ(line_a, line_b);
  }
  const Outcome again = esc("run --resume " + dir.string());
  EXPECT_EQ(again.status, 0) << again.output;
  EXPECT_NE(again.output.find("is complete"), std::string::npos) << again.output;
}

// A dependency cache entry is read by its dependents as it was made: carried on in place, it
// would hand them the longer run under the shorter one's fingerprint. It is refused, and
// carried on once copied out of the cache, finding its own dependencies there.
TEST(CarryOn, ADependencyCacheEntryIsCarriedOnOnlyOutsideTheCache) {
  const fs::path dir = scratch("carry-on-cache-entry");
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/evolved_nested.esc";
  const Outcome run = esc("run " + script + " --threads 2 --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  fs::path entry;
  for (const auto& e : fs::directory_iterator(dir / "deps"))
    if (e.path().filename().string().starts_with("supervised-") && fs::is_directory(e.path())) entry = e.path();
  ASSERT_FALSE(entry.empty());
  const std::string summary = slurp(entry / "summary.json");
  const Outcome refused = esc("run --resume " + entry.string() + " --generations 4");
  EXPECT_EQ(refused.status, 1) << refused.output;
  EXPECT_NE(refused.output.find("esc: error: " + entry.string() + " is an entry of a dependency cache"),
            std::string::npos)
      << refused.output;
  EXPECT_EQ(slurp(entry / "summary.json"), summary);
  const Outcome complete = esc("run --resume " + entry.string());
  EXPECT_EQ(complete.status, 0) << complete.output;
  EXPECT_NE(complete.output.find("is complete"), std::string::npos) << complete.output;

  const fs::path copy = scratch("carry-on-cache-entry-copy");
  fs::copy(entry, copy, fs::copy_options::recursive);
  fs::remove(copy / "fingerprint.txt");
  const Outcome on = esc("run --resume " + copy.string() + " --generations 4 --cache " + (dir / "deps").string());
  ASSERT_EQ(on.status, 0) << on.output;
  EXPECT_NE(on.output.find("dependency basic: reused"), std::string::npos) << on.output;
  EXPECT_EQ(committed_generations(copy), 2 * 4);
  EXPECT_EQ(slurp(entry / "summary.json"), summary);
}

TEST(CarryOn, FewerGenerationsThanStoredIsAnErrorThatChangesNothing) {
  const fs::path dir = scratch("carry-on-shorter");
  const Outcome run = esc("run " + tiny() + " --seed 5 --generations 3 --threads 2 --out " + dir.string());
  ASSERT_EQ(run.status, 0) << run.output;
  const std::string before = esc("export " + dir.string() + " --format json").output;
  const std::string summary = slurp(dir / "summary.json");
  const Outcome shorter = esc("run --resume " + dir.string() + " --generations 2");
  EXPECT_EQ(shorter.status, 1) << shorter.output;
  EXPECT_NE(shorter.output.find("esc: error: the runs of CC in " + dir.string() +
                                " have 3 generations; --generations 2 would cut them"),
            std::string::npos)
      << shorter.output;
  EXPECT_EQ(esc("export " + dir.string() + " --format json").output, before);
  EXPECT_EQ(slurp(dir / "summary.json"), summary);
}

TEST(CarryOn, AStudyCarriedOnIsTheLongerStudy) {
  const fs::path dir = scratch("carry-on-study");
  const std::string args = "run " + std::string(ESC_SOURCE_DIR) + "/tests/cli/data/tiny_study.esc --experiment "
                           "tiny_study_fewer --runs 2 --set epochs=1 ";
  const Outcome longer = esc(args + "--generations 3 --threads 2 --out " + (dir / "three").string());
  ASSERT_EQ(longer.status, 0) << longer.output;
  const Outcome one = esc(args + "--generations 1 --threads 2 --out " + (dir / "one").string());
  ASSERT_EQ(one.status, 0) << one.output;
  const Outcome on = esc("run --resume " + (dir / "one").string() + " --generations 3 --threads 1");
  ASSERT_EQ(on.status, 0) << on.output;
  EXPECT_NE(on.output.find("carrying study tiny_study_fewer"), std::string::npos) << on.output;
  EXPECT_EQ(slurp(dir / "one" / "summary.json"), slurp(dir / "three" / "summary.json"));
  EXPECT_EQ(results_without_times(dir / "one"), results_without_times(dir / "three"));
  const Outcome again = esc("run --resume " + (dir / "one").string());
  EXPECT_NE(again.output.find("is complete"), std::string::npos) << again.output;
  const Outcome replayed = esc("replay " + (dir / "one" / "no_inertia").string() + " --out " + (dir / "replays").string());
  EXPECT_EQ(replayed.status, 0) << replayed.output;
  const Outcome shorter = esc("run --resume " + (dir / "one").string() + " --generations 2");
  EXPECT_EQ(shorter.status, 1) << shorter.output;
}

// Every condition's target is stored when the carry-on starts: killed in the second of three
// conditions, a plain resume takes all three to it, not the second alone.
TEST(CarryOn, AStudyCarriedOnAndKilledIsFinishedByAPlainResume) {
  const fs::path dir = scratch("carry-on-study-killed");
  // Epochs of up to 2000 steps: a condition's 36 generations take about a second, several
  // times a poll of `esc export` (about 0.2 s); with tiny's 80 steps the second condition
  // passed in less than one poll, and a loaded machine killed the carry-on in the third.
  const std::string args = "run " + std::string(ESC_SOURCE_DIR) + "/tests/cli/data/tiny_study.esc --experiment "
                           "tiny_study_fewer --runs 1 --threads 1 --set steps=2000 ";
  const Outcome longer = esc(args + "--generations 20 --out " + (dir / "twenty").string());
  ASSERT_EQ(longer.status, 0) << longer.output;
  const fs::path killed = dir / "killed";
  const Outcome two = esc(args + "--generations 2 --out " + killed.string());
  ASSERT_EQ(two.status, 0) << two.output;
  // 3 conditions x 2 controllers x 20 generations: 12 stored, the first condition's 36 more,
  // then killed in the second.
  const pid_t child = spawn_esc({"run", "--resume", killed.string(), "--generations", "20", "--threads", "1"});
  ASSERT_GE(child, 0);
  const Killed k = kill_when_committed(child, killed, 12 + 36 + 1);
  ASSERT_TRUE(k.still_running) << "the carry-on finished before it could be killed";
  ASSERT_LT(committed_generations(killed), 12 + 2 * 36);
  const Outcome resumed = esc("run --resume " + killed.string());
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_EQ(committed_generations(killed), 120);
  EXPECT_EQ(slurp(dir / "twenty" / "summary.json"), slurp(killed / "summary.json"));
  EXPECT_EQ(results_without_times(dir / "twenty"), results_without_times(killed));
  EXPECT_NE(esc("run --resume " + killed.string()).output.find("is complete"), std::string::npos);
}

TEST(CarryOn, AnExtensionKilledHalfwayResumesBitIdentical) {
  const fs::path dir = scratch("carry-on-killed");
  const Outcome reference = esc("run " + tiny() + " --generations 100 --seed 5 --threads 1 --out " + (dir / "ref").string());
  ASSERT_EQ(reference.status, 0) << reference.output;
  const fs::path killed = dir / "killed";
  const Outcome two = esc("run " + tiny() + " --generations 2 --seed 5 --threads 1 --out " + killed.string());
  ASSERT_EQ(two.status, 0) << two.output;
  // 2 controllers x 2 runs x 100 generations in all; killed once 40 more are committed.
  const pid_t child = spawn_esc({"run", "--resume", killed.string(), "--generations", "100", "--threads", "1"});
  ASSERT_GE(child, 0);
  const Killed k = kill_when_committed(child, killed, 8 + 40);
  ASSERT_TRUE(k.still_running) << "the extension finished before it could be killed";
  ASSERT_LT(committed_generations(killed), 400);
  // Resumed without --generations: the directory remembers what it is carried on to.
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 2");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  EXPECT_EQ(committed_generations(killed), 400);
  EXPECT_EQ(slurp(dir / "ref" / "summary.json"), slurp(killed / "summary.json"));
  EXPECT_EQ(results_without_times(dir / "ref"), results_without_times(killed));
}

}  // namespace
