// A study's database (schema 3): every condition an experiment row, with its study, name,
// directory and settings; each condition written through its own RunDirectory; the study's
// summary.json; a carry-on recorded for every condition at once; and a schema-2 database
// upgraded when opened for writing.
#include <filesystem>

#include <gtest/gtest.h>

#include "runtime/store/sqlite.hpp"
#include "runtime/store/study_directory.hpp"
#include "tests/eval/test_experiment.hpp"
#include "tests/store/older_schema.hpp"
#include "tests/store/scratch.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::store {
namespace {

namespace fs = std::filesystem;

eval::StudySpec two_conditions() {
  eval::StudySpec s;
  s.name = "st";
  s.seed = 3;
  eval::ExperimentSpec x = testing::small_experiment();
  x.seed = 3;
  s.conditions.push_back({"base", "base", std::nullopt, {}, x});
  x.robot.motor.time_constant_s = 0.05;
  s.conditions.push_back(
      {"time_constant=50ms", "time_constant=50ms", 0, {{"robot.time_constant", "50ms", true, 50.0, "ms"}}, x});
  return s;
}

eval::RunResult finished_run(double fitness) {
  eval::RunResult r;
  r.generations.push_back({0, fitness, 1.0, 0.5, 24, 999, 0.1});
  r.best_fitness = fitness;
  r.best_genome = {0.25};
  return r;
}

TEST(StudyStore, EveryConditionIsAnExperimentWithItsStudyNameDirectoryAndSettings) {
  const fs::path dir = test::fresh_dir("study");
  const eval::StudySpec study = two_conditions();
  {
    StudyDirectory sd(dir, study, {{"s.esc", "study st { conditions small }"}}, {LaunchInfo{}, LaunchInfo{}});
    ASSERT_EQ(sd.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) {
      RunDirectory run = sd.open_condition(i, {});
      const control::ControllerSpec& c = study.conditions[i].experiment.controllers.front();
      eval::RunState st;
      st.generations = finished_run(1.5 + static_cast<double>(i)).generations;
      run.generation_done(c, 0, st.generations.front());
      run.checkpoint(c, st);
      run.run_done(c, finished_run(1.5 + static_cast<double>(i)));
      eval::CampaignResult result;
      result.experiment = "small";
      result.seed = 3;
      result.controllers.push_back({c.name, c.architecture(), c.genome_size(), {finished_run(1.5 + static_cast<double>(i))},
                                    c.choice_names()});
      run.finish(result);
    }
  }
  const std::vector<StoredExperiment> all = study_conditions(ResultsDb::open(dir, true).load());
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[1].name, "small");
  ASSERT_TRUE(all[1].condition.has_value());
  EXPECT_EQ(all[1].condition->study, "st");
  EXPECT_EQ(all[1].condition->study_seed, 3u);
  EXPECT_EQ(all[1].condition->name, "time_constant=50ms");
  EXPECT_EQ(all[1].condition->sweep, 0);
  ASSERT_EQ(all[1].condition->settings.size(), 1u);
  EXPECT_EQ(all[1].condition->settings[0].value, "50ms");
  EXPECT_EQ(all[1].condition->settings[0].x, 50.0);
  EXPECT_FALSE(all[0].condition->sweep.has_value());
  EXPECT_TRUE(all[0].finished() && all[1].finished());
  EXPECT_EQ(all[1].controllers.front().finished.front().best_fitness, 2.5);
  EXPECT_THROW((void)ResultsDb::open(dir, true).load_single(), StoreError);   // a study is not one experiment

  const auto summary = nlohmann::json::parse(test::slurp(dir / "summary.json"));
  EXPECT_EQ(summary["study"], "st");
  ASSERT_EQ(summary["conditions"].size(), 2u);
  EXPECT_EQ(summary["conditions"][1]["settings"]["robot.time_constant"], "50ms");
  EXPECT_EQ(summary["conditions"][1]["controllers"]["CC"]["runs"][0]["best_fitness"], 2.5);
  EXPECT_TRUE(fs::exists(dir / "time_constant=50ms" / "settings.json"));
  EXPECT_TRUE(fs::exists(dir / "time_constant=50ms" / "CC" / "run-01.csv"));
}

// A carry-on records every condition carried on before the first runs on: in the database
// (generations, settings, `carry_on`, running again) and in each condition's settings.json;
// a condition not carried on is left as it was.
TEST(StudyStore, ACarryOnIsRecordedForEveryConditionAtOnce) {
  const fs::path dir = test::fresh_dir("study-carry-on");
  const eval::StudySpec study = two_conditions();
  { StudyDirectory sd(dir, study, {{"s.esc", "study st { conditions small }"}}, {LaunchInfo{}, LaunchInfo{}}); }
  std::vector<eval::ExperimentSpec> longer;
  for (const eval::ConditionSpec& c : study.conditions) {
    longer.push_back(c.experiment);
    longer.back().generations = 7;
    longer.back().resolved_settings["generations"] = "7";
  }
  {
    StudyDirectory sd(dir, ResultsDb::open(dir, true).load());
    sd.carry_on({StudyDirectory::CarryOn{&longer[0], {{"carry_on", 7}}}, std::nullopt});
  }
  {
    StudyDirectory sd(dir, ResultsDb::open(dir, true).load());
    sd.carry_on({std::nullopt, StudyDirectory::CarryOn{&longer[1], {{"carry_on", 7}}}});
  }
  const std::vector<StoredExperiment> all = study_conditions(ResultsDb::open(dir, true).load());
  for (const StoredExperiment& e : all) {
    EXPECT_EQ(e.generations, 7) << e.condition->name;
    EXPECT_EQ(e.overrides["carry_on"], 7) << e.condition->name;
    EXPECT_EQ(e.settings.at("generations"), "7") << e.condition->name;
    EXPECT_FALSE(e.finished()) << e.condition->name;
    const auto doc = nlohmann::json::parse(test::slurp(dir / e.condition->directory / "settings.json"));
    EXPECT_EQ(doc["settings"]["generations"], "7") << e.condition->name;
  }
}

TEST(StudyStore, ASchemaTwoDatabaseIsReadAndUpgradedWhenWritten) {
  const fs::path dir = test::fresh_dir("upgrade-2");
  const eval::ExperimentSpec e = testing::small_experiment();
  fs::create_directories(dir);
  { (void)ResultsDb::create(dir, e, {}, {}); }
  {  // What esc wrote before studies.
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    test::keep_state_as_schema5(raw);
    raw.exec("DROP TABLE generation_usage; DROP TABLE choices; DROP TABLE transfers; "
             "DROP TABLE condition_settings; DROP TABLE conditions; DROP TABLE studies; PRAGMA user_version=2;");
  }
  EXPECT_FALSE(ResultsDb::open(dir, true).load_single().condition.has_value());
  { ResultsDb db = ResultsDb::open(dir); }
  sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadOnly);
  auto version = raw.prepare("PRAGMA user_version");
  ASSERT_TRUE(version.step());
  EXPECT_EQ(version.int64(0), kSchemaVersion);
  auto tables = raw.prepare("SELECT count(*) FROM sqlite_master WHERE name IN ('studies', 'conditions', "
                            "'condition_settings')");
  ASSERT_TRUE(tables.step());
  EXPECT_EQ(tables.int64(0), 3);
}

}  // namespace
}  // namespace esc::store
