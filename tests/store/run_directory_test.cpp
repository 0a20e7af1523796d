#include "runtime/store/run_directory.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/store/scratch.hpp"

namespace esc::store {
namespace {

namespace fs = std::filesystem;

using test::fresh_dir;
using test::slurp;

eval::ExperimentSpec spec() {
  eval::ExperimentSpec e;
  e.name = "demo";
  e.seed = 42;
  e.resolved_settings = {{"epochs", "10"}, {"steps", "150"}};
  control::ControllerSpec c;
  c.name = "CC";
  c.mlp.inputs = {5, 6};
  e.controllers.push_back(c);
  return e;
}

TEST(RunDirectory, WritesSettingsSourcesCsvGenomesAndSummary) {
  const fs::path dir = fresh_dir("write");
  const eval::ExperimentSpec e = spec();
  RunDirectory rd(dir, e, {{"a/main.esc", "experiment x {}"}, {"lib/k.esc", "robot k {}"}});
  eval::GenerationStats g0{0, 2.0, 1.0, 0.5, 10, 100, 0.1};
  eval::GenerationStats g1{1, 3.0, 2.0, 0.5, 10, 100, 0.1};
  rd.generation_done(e.controllers[0], 0, g0);
  rd.generation_done(e.controllers[0], 0, g1);
  eval::RunResult r{0, 99, {g0, g1}, 3.0, {0.25, -0.5}, 1, 3, {}};
  rd.run_done(e.controllers[0], r);

  const auto settings = nlohmann::json::parse(slurp(dir / "settings.json"));
  EXPECT_EQ(settings["experiment"], "demo");
  EXPECT_EQ(settings["seed"], "42");
  EXPECT_EQ(settings["settings"]["epochs"], "10");
  EXPECT_EQ(slurp(dir / "sources" / "00-main.esc"), "experiment x {}");
  EXPECT_EQ(slurp(dir / "CC" / "run-01.csv"),
            "generation,best,mean,sd,evaluations,steps,seconds\n0,2,1,0.5,10,100,0.100\n1,3,2,0.5,10,100,0.100\n");
  const auto best = nlohmann::json::parse(slurp(dir / "CC" / "run-01.best.json"));
  EXPECT_EQ(best["genome"], (std::vector<double>{0.25, -0.5}));
  const auto summary = nlohmann::json::parse(slurp(dir / "summary.json"));
  EXPECT_EQ(summary["experiment"], "demo");
  const auto& run = summary["controllers"]["CC"]["runs"][0];
  EXPECT_EQ(run["seed"], "99");
  EXPECT_EQ(run["best_fitness"], 3.0);
  EXPECT_EQ(run["best"], (std::vector<double>{2.0, 3.0}));
  EXPECT_EQ(run["mean"], (std::vector<double>{1.0, 2.0}));
  EXPECT_FALSE(fs::exists(dir / "summary.json.tmp"));
  fs::remove_all(dir);
}

TEST(RunDirectory, RunsFinishingInAnyOrderKeepTheExperimentsOrder) {
  // Runs advancing together finish out of order: summary.json still lists controllers as
  // the experiment compares them, and each controller's runs by index.
  const fs::path dir = fresh_dir("order");
  eval::ExperimentSpec e = spec();
  e.controllers.push_back(e.controllers[0]);
  e.controllers[1].name = "SC";
  RunDirectory rd(dir, e, {});
  const eval::GenerationStats g{0, 1.0, 1.0, 0.0, 10, 100, 0.1};
  const auto run = [&](int index) { return eval::RunResult{index, 7, {g}, 1.0 + index, {0.5}, 0, 0, {}}; };
  rd.run_done(e.controllers[1], run(0));
  rd.run_done(e.controllers[0], run(1));
  rd.run_done(e.controllers[0], run(0));
  rd.run_done(e.controllers[1], run(1));
  // ordered_json: the file's key order is the order written.
  const auto summary = nlohmann::ordered_json::parse(slurp(dir / "summary.json"));
  std::vector<std::string> names;
  for (const auto& [name, c] : summary["controllers"].items()) names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{"CC", "SC"}));
  for (const char* c : {"CC", "SC"}) {
    EXPECT_EQ(summary["controllers"][c]["runs"][0]["best_fitness"], 1.0) << c;
    EXPECT_EQ(summary["controllers"][c]["runs"][1]["best_fitness"], 2.0) << c;
  }
  fs::remove_all(dir);
}

// Before any run finishes (a run killed early leaves this one), summary.json already names the
// group: its robots, roles and bodies, as the finished campaign's and a resumed one's do.
TEST(RunDirectory, TheFirstSummaryNamesTheGroup) {
  const fs::path dir = fresh_dir("group");
  eval::ExperimentSpec e = spec();
  e.robots = 5;
  e.roles = 2;
  e.resolved_settings["bodies"] = "khepera x 2, lit x 3";
  RunDirectory rd(dir, e, {});
  const auto summary = nlohmann::json::parse(slurp(dir / "summary.json"));
  EXPECT_EQ(summary["robots"], 5);
  EXPECT_EQ(summary["roles"], 2);
  EXPECT_EQ(summary["bodies"], "khepera x 2, lit x 3");
  fs::remove_all(dir);
}

TEST(RunDirectory, NeverOverwritesExistingResults) {
  const fs::path dir = fresh_dir("exists");
  fs::create_directories(dir);
  std::ofstream(dir / "summary.json") << "{}";
  const eval::ExperimentSpec e = spec();
  EXPECT_THROW(RunDirectory(dir, e, {}), std::runtime_error);
  EXPECT_EQ(slurp(dir / "summary.json"), "{}");
  fs::remove_all(dir);
}

TEST(RunDirectory, ContentHashIsStableAndSensitive) {
  EXPECT_EQ(content_hash("abc"), content_hash("abc"));
  EXPECT_NE(content_hash("abc"), content_hash("abd"));
  EXPECT_EQ(content_hash(""), 0xcbf29ce484222325ULL);   // FNV-1a offset basis
}

}  // namespace
}  // namespace esc::store
