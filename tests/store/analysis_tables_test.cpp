// The store's schema-4 tables (sealed since schema 5) and what they serve: behavior usage per generation, choices
// and transfers load back bit for bit; a finished run keeps its state and is carried on from
// it; the best replay is the earliest best run whatever the order runs finish in; replays
// carry the light sensors; an older database reads without usage and is upgraded for writing.
#include <filesystem>
#include <span>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "runtime/evo/es/es_optimizer.hpp"
#include "runtime/store/results_db.hpp"
#include "runtime/store/row_checksum.hpp"
#include "runtime/store/sqlite.hpp"
#include "runtime/store/summary_json.hpp"
#include "runtime/store/usage_export.hpp"
#include "tests/store/older_schema.hpp"
#include "tests/store/scratch.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::store {
namespace {

namespace fs = std::filesystem;

eval::ExperimentSpec spec(int generations) {
  eval::ExperimentSpec e;
  e.name = "demo";
  e.runs = 2;
  e.generations = generations;
  control::ControllerSpec c;
  c.name = "SV";
  c.mlp.inputs = {5};
  c.head = control::Head::Supervisor;
  c.behaviors = {{"go(0.5)", control::BehaviorCall{}}, {"crash", control::BehaviorCall{}},
                 {"crash_2", control::BehaviorCall{}}};
  c.choices = {{"go", "go", "", false, 0}, {"crash", "junk.crash", "junk", true, 1},
               {"crash_2", "junk.crash", "junk", true, 2}};
  e.controllers.push_back(c);
  return e;
}

// Generation g of a run: usage that adds up to its steps_total, a mean with a fraction.
eval::GenerationStats generation(int g) {
  eval::GenerationStats s{g, 1.5 + g, 1.0 / 3.0, 0.25, 6, 600, 0.1};
  s.usage = {100, {60, 30 + g, 10 - g}, {51.0 / 3.0, 0.1 * g, 0.5}};
  return s;
}

eval::RunState run_state(int run, int generations) {
  eval::RunState s;
  s.run = run;
  s.seed = 40 + static_cast<std::uint64_t>(run);
  for (int g = 0; g < generations; ++g) s.generations.push_back(generation(g));
  s.has_best = true;
  s.best_fitness = 1.5 + generations - 1;
  s.best_genome = std::vector<double>(spec(1).controllers[0].genome_size(), 0.5);
  s.best_generation = generations - 1;
  const evo::Individual parent{s.best_genome, {0.05}, s.best_fitness};
  s.optimizer = {"es", 1, evo::es_state(std::span(&parent, 1))};
  s.transfer = eval::Transfer{"origin", run, 2.0, false, 1.75};
  return s;
}

eval::RunResult finished(const eval::RunState& s) {
  eval::RunResult r;
  r.run = s.run;
  r.seed = s.seed;
  r.generations = s.generations;
  r.best_fitness = s.best_fitness;
  r.best_genome = s.best_genome;
  r.best_generation = s.best_generation;
  r.transfer = s.transfer;
  return r;
}

// A directory whose two runs finished after `generations` generations.
fs::path finished_dir(const std::string& name, int generations) {
  const fs::path dir = test::fresh_dir(name);
  fs::create_directories(dir);
  ResultsDb db = ResultsDb::create(dir, spec(generations), {}, {});
  for (int run = 0; run < 2; ++run) {
    for (int g = 1; g <= generations; ++g) db.commit_generation("SV", run_state(run, g));
    db.commit_run("SV", finished(run_state(run, generations)));
  }
  db.mark_finished();
  return dir;
}

TEST(AnalysisTables, UsageChoicesAndTransfersLoadBackBitForBit) {
  const fs::path dir = finished_dir("usage-roundtrip", 3);
  const StoredExperiment s = ResultsDb::open(dir, true).load_single();
  const StoredController& c = s.controllers.at(0);
  ASSERT_EQ(c.choices.size(), 3u);
  EXPECT_EQ(c.choices[2].name, "crash_2");
  EXPECT_EQ(c.choices[2].behavior, "junk.crash");
  EXPECT_TRUE(c.choices[1].useless);
  EXPECT_FALSE(c.choices[0].useless);
  ASSERT_EQ(c.finished.size(), 2u);
  for (int g = 0; g < 3; ++g) EXPECT_EQ(c.finished[1].generations[static_cast<std::size_t>(g)].usage, generation(g).usage);
  ASSERT_TRUE(c.finished[1].transfer.has_value());
  EXPECT_EQ(c.finished[1].transfer->experiment, "origin");
  EXPECT_EQ(c.finished[1].transfer->origin_run, 1);
  EXPECT_EQ(c.finished[1].transfer->fitness_here, 1.75);
  // The tidy table and summary.json show the same numbers.
  const std::vector<StoredDirectory> directories{{dir, {s}}};
  const std::string csv = usage_csv(directories);
  EXPECT_NE(csv.find("demo,,SV,2,2,crash_2,8,0.5,100,junk,1\n"), std::string::npos) << csv;   // no condition
  EXPECT_NE(csv.find("demo,,SV,1,0,go(0.5),60,17,100,,0\n"), std::string::npos) << csv;
  EXPECT_EQ(usage_json(directories).size(), 2u * 3u * 3u);
  const auto summary = summary_json(s.result());
  const auto& usage = summary["controllers"]["SV"]["runs"][0]["usage"];
  EXPECT_EQ(usage["behaviors"], nlohmann::json({"go(0.5)", "crash", "crash_2"}));
  EXPECT_EQ(usage["best_steps"][2], nlohmann::json({60, 32, 8}));
  EXPECT_EQ(usage["steps_total"], nlohmann::json({100, 100, 100}));
  const auto& transfer = summary["controllers"]["SV"]["runs"][0]["transfer"];
  EXPECT_EQ(transfer["change_percent"], -12.5);
  EXPECT_EQ(transfer["regained_at_generation"], 1);   // generation 1's best is 2.5 >= 2.0
}

TEST(AnalysisTables, AFinishedRunIsCarriedOnFromTheStateItKept) {
  const fs::path dir = finished_dir("carry-on", 2);
  ResultsDb db = ResultsDb::open(dir);
  const StoredExperiment s = db.load_single();
  const eval::ResumePoint same = db.resume_point(s, spec(2));
  EXPECT_EQ(same.finished.size(), 2u);
  EXPECT_TRUE(same.in_progress.empty());
  const eval::ResumePoint longer = db.resume_point(s, spec(5));
  EXPECT_TRUE(longer.finished.empty());
  ASSERT_EQ(longer.in_progress.size(), 2u);
  const eval::RunState& st = longer.in_progress[1].state;
  EXPECT_EQ(st.generations.size(), 2u);
  EXPECT_EQ(st.best_fitness, 2.5);
  ASSERT_TRUE(st.transfer.has_value());
  EXPECT_EQ(st.optimizer, run_state(1, 2).optimizer);
  // Recorded: the experiment's generations, settings and overrides, running again.
  eval::ExperimentSpec five = spec(5);
  five.resolved_settings = {{"generations", "5"}};
  db.extend({{db.experiment_id(), &five, nlohmann::ordered_json{{"carry_on", 5}}}});
  const StoredExperiment after = ResultsDb::open(dir, true).load_single();
  EXPECT_EQ(after.generations, 5);
  EXPECT_EQ(after.status, "running");
  EXPECT_EQ(after.settings.at("generations"), "5");
  EXPECT_EQ(after.overrides["carry_on"], 5);
}

TEST(AnalysisTables, ARunFinishedWithoutItsStateCannotBeCarriedOn) {
  const fs::path dir = finished_dir("no-state", 2);
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    raw.exec("DELETE FROM optimizer_state WHERE run = 1");
  }
  ResultsDb db = ResultsDb::open(dir);
  const StoredExperiment s = db.load_single();
  EXPECT_EQ(db.resume_point(s, spec(2)).finished.size(), 2u);   // nothing to carry on: fine
  try {
    (void)db.resume_point(s, spec(3));
    ADD_FAILURE() << "carried on without a state";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("run 2 of SV in"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("finished without keeping the state to carry it on from"), std::string::npos)
        << e.what();
  }
}

TEST(AnalysisTables, TheReplayIsTheEarliestBestRunWhateverTheOrder) {
  const fs::path dir = test::fresh_dir("replay-order");
  fs::create_directories(dir);
  ResultsDb db = ResultsDb::create(dir, spec(1), {}, {});
  eval::TraceStep t;
  t.light[6] = 0.625;
  t.zone_count = 1;
  t.zones[0] = {0.3, 0.1};
  const std::vector<eval::TraceStep> trace = {t};
  eval::RunResult second = finished(run_state(1, 1));
  eval::RunResult first = finished(run_state(0, 1));
  db.commit_replay("SV", second, trace);   // run 2 finishes first
  db.commit_replay("SV", first, trace);    // run 1, as good: it is the earliest
  const StoredExperiment s = ResultsDb::open(dir, true).load_single();
  ASSERT_TRUE(s.controllers[0].replay.has_value());
  EXPECT_EQ(s.controllers[0].replay->run, 0);
  // The light sensors travel with the replay, after the zones.
  EXPECT_EQ(s.controllers[0].replay->steps.at(0).light[6], 0.625);
  EXPECT_EQ(s.controllers[0].replay->steps.at(0).zones[0].x, 0.3);
  EXPECT_EQ(s.controllers[0].replay->steps.at(0).range_count, 0u);
}

// A directory whose one run of SV stored `steps` as its replay.
fs::path with_replay(const std::string& name, const std::vector<eval::TraceStep>& steps) {
  const fs::path dir = test::fresh_dir(name);
  fs::create_directories(dir);
  ResultsDb db = ResultsDb::create(dir, spec(1), {}, {});
  db.commit_replay("SV", finished(run_state(0, 1)), steps);
  return dir;
}

TEST(AnalysisTables, TheNavigatorsRangefindersAndRadarsTravelWithTheReplay) {
  eval::TraceStep t;
  t.light[7] = 0.5;
  t.range_count = 3;
  t.range = {0.25, 1.0, 0.75};
  t.radar_count = 4;
  t.radar = {0.0, 1.0, 0.0, 0.0};
  eval::TraceStep u = t;
  u.step = 1;
  u.radar = {1.0, 0.0, 0.0, 0.0};
  const fs::path dir = with_replay("replay-navigation", {t, u});
  const StoredExperiment s = ResultsDb::open(dir, true).load_single();
  ASSERT_TRUE(s.controllers[0].replay.has_value());
  const auto& steps = s.controllers[0].replay->steps;
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0].light[7], 0.5);
  EXPECT_EQ(steps[0].range_count, 3u);
  EXPECT_EQ(steps[0].range[0], 0.25);
  EXPECT_EQ(steps[0].range[2], 0.75);
  EXPECT_EQ(steps[0].radar_count, 4u);
  EXPECT_EQ(steps[0].radar[1], 1.0);
  EXPECT_EQ(steps[1].radar[0], 1.0);
  EXPECT_EQ(steps[1].radar[1], 0.0);
}

TEST(AnalysisTables, GroundSensorsAndBumpersTravelWithTheReplayAfterTheRadars) {
  eval::TraceStep t;
  t.radar_count = 1;
  t.radar = {1.0};
  t.ground_count = 2;
  t.ground = {1.0, 0.0};
  t.bumper_count = 3;
  t.bumper = {0.0, 0.0, 1.0};
  const fs::path dir = with_replay("replay-ground-bumpers", {t});
  sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadOnly);
  auto columns = raw.prepare("SELECT columns FROM replays");
  ASSERT_TRUE(columns.step());
  EXPECT_NE(columns.text(0).find(R"("radar0","ground_sensor0","ground_sensor1","bumper0","bumper1","bumper2"])"), std::string::npos)
      << columns.text(0);
  const StoredExperiment s = ResultsDb::open(dir, true).load_single();
  const eval::TraceStep& back = s.controllers[0].replay->steps.at(0);
  EXPECT_EQ(back.radar_count, 1u);
  EXPECT_EQ(back.ground_count, 2u);
  EXPECT_EQ(back.ground[0], 1.0);
  EXPECT_EQ(back.ground[1], 0.0);
  EXPECT_EQ(back.bumper_count, 3u);
  EXPECT_EQ(back.bumper[2], 1.0);
}

// A group's replay (docs/groups.md): each row ends with its robot and the group observables,
// read back as written.
TEST(AnalysisTables, AGroupsRobotAndObservablesTravelWithTheReplay) {
  std::vector<eval::TraceStep> rows;
  for (int r = 0; r < 3; ++r) {
    eval::TraceStep t;
    t.bumper_count = 1;
    t.robot = r;
    t.grouped = true;
    for (std::size_t g = 0; g < t.group.size(); ++g) t.group[g] = 0.1 * static_cast<double>(r) + static_cast<double>(g);
    rows.push_back(t);
  }
  const fs::path dir = with_replay("replay-group", rows);
  sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadOnly);
  auto columns = raw.prepare("SELECT columns FROM replays");
  ASSERT_TRUE(columns.step());
  EXPECT_NE(columns.text(0).find(R"("bumper0","robot","centroid_x","centroid_y","centroid_moved","centroid_distance",)"
                                 R"("nearest_robot","robot_distance","spread"])"),
            std::string::npos)
      << columns.text(0);
  const StoredExperiment s = ResultsDb::open(dir, true).load_single();
  const auto& back = s.controllers[0].replay->steps;
  ASSERT_EQ(back.size(), 3U);
  for (int r = 0; r < 3; ++r) {
    EXPECT_TRUE(back[static_cast<std::size_t>(r)].grouped);
    EXPECT_EQ(back[static_cast<std::size_t>(r)].robot, r);
    EXPECT_EQ(back[static_cast<std::size_t>(r)].group, rows[static_cast<std::size_t>(r)].group);
  }
  // A robot alone's replay has neither.
  const fs::path alone = with_replay("replay-alone", {eval::TraceStep{}});
  sql::Database one(alone / kDatabaseFile, sql::Database::Mode::ReadOnly);
  auto names = one.prepare("SELECT columns FROM replays");
  ASSERT_TRUE(names.step());
  EXPECT_EQ(names.text(0).find("robot"), std::string::npos) << names.text(0);
}

// A replay column this esc does not know (one a newer esc added, sealed as it seals rows) is
// a newer esc's database, not a damaged one.
TEST(AnalysisTables, AReplayColumnOfANewerEscIsSaidToBeOne) {
  eval::TraceStep t;
  t.bumper_count = 1;
  const fs::path dir = with_replay("replay-newer-column", {t});
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    raw.exec("UPDATE replays SET columns = replace(columns, '\"bumper0\"', '\"sonar0\"')");
    seal_table(raw, "replays");
  }
  try {
    (void)ResultsDb::open(dir, true).load_single();
    FAIL() << "a column of a newer esc was read";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("written by a newer esc: its replay traces have a column `sonar0`"),
              std::string::npos)
        << e.what();
  }
}

TEST(AnalysisTables, ASchemaThreeDatabaseReadsWithoutUsageAndIsUpgradedForWriting) {
  const fs::path dir = finished_dir("schema-3", 1);
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    test::keep_state_as_schema5(raw);
    raw.exec("DROP TABLE generation_usage; DROP TABLE choices; DROP TABLE transfers; PRAGMA user_version=3;");
  }
  const StoredExperiment old = ResultsDb::open(dir, true).load_single();
  EXPECT_TRUE(old.controllers[0].choices.empty());
  EXPECT_TRUE(old.controllers[0].finished[0].generations[0].usage.empty());
  EXPECT_FALSE(old.controllers[0].finished[0].transfer.has_value());
  EXPECT_FALSE(summary_json(old.result())["controllers"]["SV"]["runs"][0].contains("usage"));
  ResultsDb db = ResultsDb::open(dir);   // upgraded
  db.commit_generation("SV", run_state(1, 2));
  const StoredExperiment now = ResultsDb::open(dir, true).load_single();
  ASSERT_EQ(now.controllers[0].in_progress.size(), 1u);
  const auto& gens = now.controllers[0].in_progress[0].generations;
  EXPECT_TRUE(gens[0].usage.empty());   // stored before the upgrade
  EXPECT_EQ(gens[1].usage, generation(1).usage);
  sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadOnly);
  auto version = raw.prepare("PRAGMA user_version");
  ASSERT_TRUE(version.step());
  EXPECT_EQ(version.int64(0), kSchemaVersion);
}

// Schema 5: the analyses' rows carry checksums like every other row; a changed value in any
// of them (or in the state a finished run keeps, or in what a carry-on records) is refused.
TEST(AnalysisTables, TheirRowsAndAFinishedRunsKeptStateAreVerified) {
  const std::vector<std::pair<std::string, std::string>> changes = {
      {"generation_usage", "UPDATE generation_usage SET best_steps = best_steps + 1 WHERE run = 1 AND generation = 1 "
                           "AND choice_idx = 2"},
      {"choices", "UPDATE choices SET useless = 0 WHERE idx = 1"},
      {"transfers", "UPDATE transfers SET origin_fitness = 2.5 WHERE run = 0"},
      {"optimizer_state", "UPDATE optimizer_state SET format = 2 WHERE run = 1"},
  };
  for (const auto& [table, change] : changes) {
    const fs::path dir = finished_dir("sealed-" + table, 2);
    (void)ResultsDb::open(dir, true).load();   // as written: verified
    {
      sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
      raw.exec(change);
    }
    try {
      (void)ResultsDb::open(dir, true).load();
      ADD_FAILURE() << "a changed row of " << table << " was read";
    } catch (const StoreError& e) {
      EXPECT_NE(std::string(e.what()).find("checksum"), std::string::npos) << table << ": " << e.what();
      // The message says what the damaged row held, not another table's meaning.
      EXPECT_EQ(std::string(e.what()).find("a condition's setting"), std::string::npos) << table << ": " << e.what();
    }
  }
  // What a carry-on records is sealed with it.
  const fs::path dir = finished_dir("sealed-extend", 2);
  {
    ResultsDb db = ResultsDb::open(dir);
    eval::ExperimentSpec five = spec(5);
    five.resolved_settings = {{"generations", "5"}};
    db.extend({{db.experiment_id(), &five, nlohmann::ordered_json{{"carry_on", 5}}}});
  }
  EXPECT_EQ(ResultsDb::open(dir, true).load_single().generations, 5);
}

// A database written by schema 4 (usage tables, no checksums) is read as it is and sealed,
// its usage rows included, when opened for writing.
TEST(AnalysisTables, ASchemaFourDatabaseIsSealedWhenUpgraded) {
  const fs::path dir = finished_dir("schema-4", 2);
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    test::keep_state_as_schema5(raw);
    test::drop_checksums(raw);
    raw.exec("ALTER TABLE generations DROP COLUMN saturated; PRAGMA user_version=4;");
  }
  const StoredExperiment old = ResultsDb::open(dir, true).load_single();
  EXPECT_EQ(old.controllers[0].finished[1].generations[1].usage, generation(1).usage);
  { ResultsDb db = ResultsDb::open(dir); }   // upgraded
  const StoredExperiment now = ResultsDb::open(dir, true).load_single();
  EXPECT_EQ(now.controllers[0].finished[1].generations[1].usage, generation(1).usage);
  EXPECT_EQ(now.controllers[0].choices.size(), 3u);
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    auto version = raw.prepare("PRAGMA user_version");
    ASSERT_TRUE(version.step());
    EXPECT_EQ(version.int64(0), kSchemaVersion);
    raw.exec("UPDATE generation_usage SET mean_steps = 1.0 WHERE run = 0 AND generation = 0 AND choice_idx = 0");
  }
  EXPECT_THROW((void)ResultsDb::open(dir, true).load(), StoreError);
}

}  // namespace
}  // namespace esc::store
