// End-to-end tests of `esc run --controllers`: a chosen controller's results are those it
// has in a run of the whole experiment (common random numbers), the choice survives a
// SIGKILL and resume, dependencies run only for the chosen controllers, and bad names are
// refused before anything runs.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

namespace fs = std::filesystem;
using namespace cli_test;

TEST(ControllerSelection, AChosenControllerHasTheResultsItHasBesideTheOthers) {
  const fs::path whole = scratch("selection-whole");
  const fs::path chosen = scratch("selection-chosen");
  const std::string common = " --generations 20 --seed 5 --threads 2 --out ";
  ASSERT_EQ(esc("run " + tiny() + common + whole.string()).status, 0);
  const Outcome o = esc("run " + tiny() + common + chosen.string() + " --controllers SC");
  ASSERT_EQ(o.status, 0) << o.output;
  const auto a = read_json(whole / "summary.json");
  const auto b = read_json(chosen / "summary.json");
  ASSERT_EQ(b["controllers"].size(), 1U);
  EXPECT_EQ(b["controllers"]["SC"], a["controllers"]["SC"]);
  EXPECT_EQ(slurp(whole / "SC/run-01.best.json"), slurp(chosen / "SC/run-01.best.json"));
  EXPECT_FALSE(fs::exists(chosen / "CC"));
}

TEST(ControllerSelection, TheChoiceIsKeptAcrossAKillAndResume) {
  const fs::path reference = scratch("selection-reference");
  const fs::path killed = scratch("selection-killed");
  ASSERT_EQ(esc("run " + tiny() + " --generations 100 --seed 5 --threads 1 --controllers SC,CC --out " +
                reference.string())
                .status,
            0);
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tiny(), killed, 40, 400, "1", {"--controllers", "SC,CC"}));
  const Outcome resumed = esc("run --resume " + killed.string() + " --threads 2");
  ASSERT_EQ(resumed.status, 0) << resumed.output;
  expect_same_summary(reference, killed);
  // In the order chosen, not the script's.
  const std::string text = slurp(killed / "summary.json");
  EXPECT_LT(text.find("\"SC\""), text.find("\"CC\""));
  EXPECT_EQ(esc("run --resume " + killed.string() + " --controllers CC").status, 2);
}

TEST(ControllerSelection, DependenciesRunOnlyForTheChosenControllers) {
  const std::string script = std::string(ESC_SOURCE_DIR) + "/tests/cli/data/selection.esc";
  const fs::path direct = scratch("selection-direct");
  Outcome o = esc("run " + script + " --controllers CC --threads 2 --out " + direct.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(o.output.find("dependency basic"), std::string::npos) << o.output;
  EXPECT_FALSE(fs::exists(direct / "deps"));

  const fs::path supervised = scratch("selection-supervised");
  o = esc("run " + script + " --controllers SV --threads 2 --out " + supervised.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("dependency basic"), std::string::npos) << o.output;
  EXPECT_EQ(read_json(supervised / "summary.json")["controllers"].size(), 1U);
}

TEST(ControllerSelection, UnknownOrRepeatedNamesAreRefusedBeforeRunning) {
  const fs::path out = scratch("selection-bad");
  Outcome o = esc("run " + tiny() + " --controllers SV --out " + out.string());
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.output.find("compares no controller `SV`"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("did you mean `SC`?"), std::string::npos) << o.output;
  o = esc("run " + tiny() + " --controllers CC,CC --out " + out.string());
  EXPECT_EQ(o.status, 1);
  EXPECT_NE(o.output.find("names `CC` twice"), std::string::npos) << o.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
