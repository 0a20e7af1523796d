// The results database: what is committed loads back exactly (bit for bit, for resume);
// foreign, damaged and newer databases give clear errors; exports show what is stored.
#include "runtime/store/results_db.hpp"

#include <bit>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <limits>
#include <memory>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "runtime/evo/es/es_optimizer.hpp"
#include "runtime/store/es_state.hpp"
#include "runtime/store/export.hpp"
#include "runtime/store/row_checksum.hpp"
#include "runtime/store/run_directory.hpp"
#include "runtime/store/sqlite.hpp"
#include "tests/store/older_schema.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::store {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("esc-db-test-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

eval::ExperimentSpec spec() {
  eval::ExperimentSpec e;
  e.name = "demo";
  e.seed = 18446744073709551557ULL;   // above INT64_MAX: stored as text
  e.runs = 2;
  e.generations = 3;
  e.resolved_settings = {{"epochs", "10"}, {"steps", "150"}};
  e.arena.cylinders.push_back({{0.2, 0.3}, 0.025});
  control::ControllerSpec c;
  c.name = "SC";
  c.mlp.inputs = {5, 6};
  c.head = control::Head::Symbolic;
  c.actions.resize(2);
  c.actions[0].name = "forward";
  c.actions[1].name = "left";
  e.controllers.push_back(c);
  return e;
}

eval::RunState state(int generations) {
  eval::RunState s;
  s.run = 1;
  s.seed = 0xfedcba9876543210ULL;
  for (int g = 0; g < generations; ++g)
    s.generations.push_back({g, 1.0 / 3.0 + g, 0.1 * g, 1e-300, 20, 1234, 0.25});
  const std::size_t n = spec().controllers[0].genome_size();
  std::vector<double> a(n);
  std::vector<double> b(n);
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = static_cast<double>(i) / 7.0 - 0.5;
    b[i] = -1.0 / (1.0 + static_cast<double>(i));
  }
  const std::vector<evo::Individual> parents{{a, {0.05}, 3.25}, {b, {0.01}, -2.5}};
  s.optimizer = {"es", 1, evo::es_state(parents)};
  s.generations.back().metrics = {{"sigma", 0.125}, {"condition", std::numeric_limits<double>::infinity()},
                                  {"nothing", std::numeric_limits<double>::quiet_NaN()}};
  s.has_best = true;
  s.best_fitness = 9.875;
  s.best_genome = {0.5, 0.25, -0.125};
  s.best_generation = 1;
  s.best_index = 17;
  return s;
}

TEST(ResultsDb, GenerationStateRoundTripsBitForBit) {
  const fs::path dir = fresh_dir("roundtrip");
  const eval::ExperimentSpec e = spec();
  {
    ResultsDb db = ResultsDb::create(dir, e, {{"a/main.esc", "experiment demo {}"}}, {"/x/main.esc", {}, "0.1.0"});
    db.commit_generation("SC", state(1));
    db.commit_generation("SC", state(2));
  }
  ResultsDb db = ResultsDb::open(dir);
  const StoredExperiment s = db.load_single();
  EXPECT_EQ(s.name, "demo");
  EXPECT_EQ(s.seed, e.seed);
  EXPECT_EQ(s.status, "running");
  EXPECT_EQ(s.settings, e.resolved_settings);
  EXPECT_EQ(s.script, fs::path("/x/main.esc"));
  EXPECT_EQ(s.sources.at(0).text, "experiment demo {}");
  ASSERT_EQ(s.controllers.size(), 1U);
  const StoredController& c = s.controllers[0];
  EXPECT_EQ(c.head, "symbolic");
  EXPECT_EQ(c.actions, (std::vector<std::string>{"forward", "left"}));
  ASSERT_EQ(c.in_progress.size(), 1U);
  const eval::RunState want = state(2);
  const eval::RunState& got = c.in_progress[0];
  EXPECT_EQ(got.seed, want.seed);
  ASSERT_EQ(got.generations.size(), 2U);
  EXPECT_EQ(got.generations[1].best, want.generations[1].best);
  EXPECT_EQ(got.generations[1].sd, want.generations[1].sd);
  EXPECT_EQ(got.optimizer, want.optimizer) << "the optimizer's state comes back byte for byte";
  const std::vector<evo::Metric>& m = got.generations[1].metrics;
  ASSERT_EQ(m.size(), 3U) << "metrics come back in the order written";
  EXPECT_EQ(m[0], want.generations[1].metrics[0]);
  EXPECT_EQ(m[1], want.generations[1].metrics[1]);
  EXPECT_EQ(m[2].name, "nothing");
  EXPECT_TRUE(std::isnan(m[2].value)) << "NaN, which SQLite keeps as NULL, reads back as NaN";
  EXPECT_EQ(got.best_genome, want.best_genome);
  EXPECT_EQ(got.best_index, 17);
  const eval::ResumePoint p = db.resume_point(s, e);
  EXPECT_EQ(p.in_progress.size(), 1U);
  EXPECT_TRUE(p.finished.empty());
}

TEST(ResultsDb, FinishedRunsKeepUsageAndTheBestReplay) {
  const fs::path dir = fresh_dir("finished");
  const eval::ExperimentSpec e = spec();
  ResultsDb db = ResultsDb::create(dir, e, {}, {});
  eval::RunResult r{0, 5, {{0, 2.0, 1.0, 0.5, 10, 100, 0.1}}, 2.0, {0.1}, 0, 3, {7, 3}};
  db.commit_generation("SC", {0, 5, r.generations, true, 2.0, {0.1}, 0, 3, eval::OptimizerState{"es", 1, {1, 2, 3}}});
  eval::TraceStep t;
  t.epoch = 0;
  t.step = 4;
  t.pose = {0.1, 0.2, 0.3};
  t.ir[3] = 0.75;
  t.action = 1;
  t.fitness = 2.0;
  t.collided = true;
  t.energy = 0.25;
  t.zone_count = 2;
  t.zones[0] = {0.4, 0.45};
  t.zones[1] = {0.05, 0.5};
  const std::vector<eval::TraceStep> trace = {t};
  db.commit_replay("SC", r, trace);
  db.commit_run("SC", r);
  eval::RunResult worse = r;
  worse.run = 1;
  worse.best_fitness = 1.0;
  db.commit_replay("SC", worse, trace);   // not better: the replay of run 0 stays
  db.mark_finished();
  const StoredExperiment s = db.load_single();
  EXPECT_TRUE(s.finished());
  const StoredController& c = s.controllers[0];
  ASSERT_EQ(c.finished.size(), 1U);
  EXPECT_TRUE(c.in_progress.empty());
  EXPECT_EQ(c.finished[0].action_usage, (std::vector<std::int64_t>{7, 3}));
  ASSERT_TRUE(c.replay.has_value());
  EXPECT_EQ(c.replay->run, 0);
  ASSERT_EQ(c.replay->steps.size(), 1U);
  EXPECT_EQ(c.replay->steps[0].ir[3], 0.75);
  EXPECT_EQ(c.replay->steps[0].action, 1);
  EXPECT_TRUE(c.replay->steps[0].collided);
  // The accumulator and where the (possibly random) zones were that epoch.
  EXPECT_EQ(c.replay->steps[0].energy, 0.25);
  ASSERT_EQ(c.replay->steps[0].zone_count, 2U);
  EXPECT_EQ(c.replay->steps[0].zones[1].x, 0.05);
  EXPECT_EQ(c.replay->steps[0].zones[1].y, 0.5);

  const std::string csv = export_csv({{"dir", {s}}});
  EXPECT_NE(csv.find("demo,SC,1,5,finished,0,2,1,0.5,10,100,0.100"), std::string::npos) << csv;
  const auto j = export_json({{"dir", {s}}});
  EXPECT_EQ(j["experiments"][0]["controllers"]["SC"]["runs"][0]["behavior_usage"]["forward"], 7);
}

// A MAP-Elites-like run: a grid archive of 2 x 3 cells whose generations change some cells.
eval::RunState with_members(int generations) {
  eval::RunState s = state(generations);
  auto layout = std::make_shared<eval::MemberLayout>();
  layout->kind = evo::MemberKind::Archive;
  layout->objectives = {"f"};
  layout->minimized = {false};
  layout->descriptors = {"dx", "dy"};
  layout->descriptor_ranges = {{0.0, 1.0}, {-2.0, 2.0}};
  layout->bins = {2, 3};
  s.member_layout = layout;
  const double g = generations - 1;
  s.members = {{static_cast<std::int64_t>(generations), {g + 0.5}, {0.25, -1.0}, {}, {}},
               {5, {-g}, {0.75, 1.5}, {}, {}}};
  s.members_due = true;
  return s;
}

// An NSGA-II-like run's first front after `generations`, of two members, the first's
// objective `value`; `due` when its generation is one that stores the front.
eval::RunState with_front(int generations, double value, bool due) {
  eval::RunState s = with_members(generations);
  auto layout = std::make_shared<eval::MemberLayout>(*s.member_layout);
  layout->kind = evo::MemberKind::Front;
  layout->bins.clear();
  s.member_layout = layout;
  s.members = {{0, {value}, {0.25, -1.0}, {}, {}}, {1, {-1.0}, {0.5, 0.5}, {}, {}}};
  s.members_due = due;
  return s;
}

// A front is stored where its generation stores one, and not again where it equals the last
// stored bit for bit (0.0 and -0.0 differ): a generation's front is the last stored up to it.
TEST(ResultsDb, AFrontIsStoredWhereDueAndNotWhereUnchanged) {
  const fs::path dir = fresh_dir("fronts");
  {
    ResultsDb db = ResultsDb::create(dir, spec(), {}, {});
    db.commit_generation("SC", with_front(1, 0.0, true));    // generation 0: stored
    db.commit_generation("SC", with_front(2, 7.0, false));   // 1: not one that stores it
    db.commit_generation("SC", with_front(3, 0.0, true));    // 2: unchanged since 0
    db.commit_generation("SC", with_front(4, -0.0, true));   // 3: changed in a bit
    db.commit_generation("SC", with_front(5, -0.0, true));   // 4: unchanged since 3
  }
  const StoredController c = ResultsDb::open(dir, true).load_single().controllers.at(0);
  ASSERT_TRUE(c.members.has_value());
  EXPECT_EQ(c.members->layout.kind, evo::MemberKind::Front);
  ASSERT_EQ(c.members->rows.size(), 4U);
  EXPECT_EQ(c.members->rows[0].generation, 0);
  EXPECT_EQ(c.members->rows[2].generation, 3);
  for (const int g : {0, 1, 2}) {
    const std::vector<StoredMember> front = members_at(*c.members, 1, g);
    ASSERT_EQ(front.size(), 2U) << g;
    EXPECT_EQ(front[0].generation, 0) << g;
    EXPECT_FALSE(std::signbit(front[0].objectives[0])) << g;
  }
  const std::vector<StoredMember> last = members_at(*c.members, 1, 4);
  ASSERT_EQ(last.size(), 2U);
  EXPECT_EQ(last[0].generation, 3);
  EXPECT_TRUE(std::signbit(last[0].objectives[0]));
  EXPECT_TRUE(members_at(*c.members, 2, 4).empty());   // another run stored none
}

TEST(ResultsDb, MembersRoundTripAndAnyGenerationsArchiveIsReadBack) {
  const fs::path dir = fresh_dir("members");
  {
    ResultsDb db = ResultsDb::create(dir, spec(), {}, {});
    for (int g = 1; g <= 3; ++g) db.commit_generation("SC", with_members(g));
  }
  const StoredController c = ResultsDb::open(dir, true).load_single().controllers.at(0);
  ASSERT_TRUE(c.members.has_value());
  EXPECT_EQ(c.members->layout, *with_members(1).member_layout);
  ASSERT_EQ(c.members->rows.size(), 6U);
  EXPECT_EQ(c.members->rows[2].generation, 1);
  EXPECT_EQ(c.members->rows[2].cell, 2);
  EXPECT_EQ(c.members->rows[2].objectives, (std::vector<double>{1.5}));
  // Generation 1's archive: cell 1 from generation 0, cells 2 and 5 from generation 1.
  const std::vector<StoredMember> at1 = members_at(*c.members, 1, 1);
  ASSERT_EQ(at1.size(), 3U);
  EXPECT_EQ(at1[0].cell, 1);
  EXPECT_EQ(at1[2].cell, 5);
  EXPECT_EQ(at1[2].objectives, (std::vector<double>{-1.0}));
  EXPECT_EQ(members_at(*c.members, 1, 2).size(), 4U);
  {  // A bit flipped in a stored member is refused.
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    raw.exec("UPDATE member_generations SET members = 4 WHERE generation = 2");
  }
  EXPECT_THROW((void)ResultsDb::open(dir, true).load(), StoreError);
}

// Schema 10: a generation's members in one row. A schema-8 or 9 database (a row per member)
// reads the same members as it is, and packs them when opened for writing; a row whose
// values do not fit its count is refused, located, even with a matching checksum.
TEST(ResultsDb, ASchemaEightDatabasesMembersArePackedWhenWritten) {
  const fs::path dir = fresh_dir("members-8");
  {
    ResultsDb db = ResultsDb::create(dir, spec(), {}, {});
    for (int g = 1; g <= 3; ++g) db.commit_generation("SC", with_members(g));
  }
  const auto rows = [&dir](bool writable) {
    const StoredExperiment s = ResultsDb::open(dir, !writable).load_single();
    return s.controllers.at(0).members.value().rows;
  };
  const auto same = [](const std::vector<StoredMember>& a, const std::vector<StoredMember>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i].run != b[i].run || a[i].generation != b[i].generation || a[i].cell != b[i].cell ||
          a[i].objectives != b[i].objectives || a[i].descriptors != b[i].descriptors)
        return false;
    return true;
  };
  const std::vector<StoredMember> written = rows(false);
  ASSERT_EQ(written.size(), 6U);
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    test::as_schema8(raw);
  }
  EXPECT_TRUE(same(rows(false), written)) << "read from a row per member";
  EXPECT_TRUE(same(rows(true), written)) << "packed, the same members";
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    EXPECT_FALSE(raw.has_table("members"));
    raw.exec("UPDATE member_generations SET members = 3 WHERE generation = 1");
    seal_table(raw, "member_generations");
  }
  try {
    (void)ResultsDb::open(dir, true).load_single();
    FAIL() << "read members that do not fit their count";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("is damaged: SC: the members of run 2, generation 1 do not fit their count"),
              std::string::npos) << e.what();
  }
}

// A database from before schema 8 has no member tables: it reads as it is, and gets them
// when it is opened for writing (a run carried on stores its members from then on).
TEST(ResultsDb, ASchemaSevenDatabaseGetsTheMemberTablesWhenWritten) {
  const fs::path dir = fresh_dir("upgrade-7");
  {
    ResultsDb db = ResultsDb::create(dir, spec(), {}, {});
    db.commit_generation("SC", state(1));
  }
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    test::as_schema7(raw);
  }
  EXPECT_FALSE(ResultsDb::open(dir, true).load_single().controllers.at(0).members.has_value());
  {
    ResultsDb db = ResultsDb::open(dir);
    db.commit_generation("SC", with_members(2));
  }
  const StoredController c = ResultsDb::open(dir, true).load_single().controllers.at(0);
  ASSERT_TRUE(c.members.has_value());
  EXPECT_EQ(c.members->rows.size(), 2U);
  EXPECT_EQ(c.members->rows[0].generation, 1);
}

// Schema 8: the evaluation of a run's first success, in a run in progress and a finished
// one, and carried into a run carried on; a schema-7 database (no such column, its rows
// sealed as they were) reads as it is and gets the column when opened for writing.
TEST(ResultsDb, ARunsFirstSuccessIsStoredAndASchemaSevenDatabaseGetsTheColumn) {
  const fs::path dir = fresh_dir("success");
  eval::RunState met = state(2);
  met.success_evaluation = 27;
  eval::RunResult finished{0, 5, {{0, 2.0, 1.0, 0.5, 10, 100, 0.1}}, 2.0, {0.1}, 0, 3, {7, 3}};
  finished.success_evaluation = 4;
  {
    ResultsDb db = ResultsDb::create(dir, spec(), {}, {});
    db.commit_generation("SC", state(1));
    EXPECT_FALSE(db.load_single().controllers[0].in_progress[0].success_evaluation.has_value());
    db.commit_generation("SC", met);
    db.commit_generation("SC", {0, 5, finished.generations, true, 2.0, {0.1}, 0, 3,
                                eval::OptimizerState{"es", 1, {1, 2, 3}}});
    db.commit_run("SC", finished);
  }
  {
    ResultsDb db = ResultsDb::open(dir, true);
    const StoredExperiment s = db.load_single();
    const StoredController& c = s.controllers[0];
    ASSERT_EQ(c.in_progress.size(), 1u);
    EXPECT_EQ(c.in_progress[0].success_evaluation, 27);
    ASSERT_EQ(c.finished.size(), 1u);
    EXPECT_EQ(c.finished[0].success_evaluation, 4);
    eval::ExperimentSpec longer = spec();
    longer.generations = 5;   // carried on: the finished run continues with its success
    const eval::ResumePoint p = db.resume_point(s, longer);
    ASSERT_EQ(p.in_progress.size(), 2u);
    EXPECT_EQ(p.in_progress[0].state.success_evaluation, 4);
  }
  {  // As schema 7 wrote it: the rows sealed without the column.
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    test::as_schema7(raw);
  }
  for (const StoredController& c : ResultsDb::open(dir, true).load_single().controllers) {
    EXPECT_FALSE(c.finished.at(0).success_evaluation.has_value());
    EXPECT_FALSE(c.in_progress.at(0).success_evaluation.has_value());
  }
  {
    ResultsDb db = ResultsDb::open(dir);   // upgraded, its rows sealed again with the column
    EXPECT_FALSE(db.load_single().controllers[0].finished[0].success_evaluation.has_value());
    db.commit_run("SC", finished);
  }
  sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
  auto version = raw.prepare("PRAGMA user_version");
  ASSERT_TRUE(version.step());
  EXPECT_EQ(version.int64(0), kSchemaVersion);
  EXPECT_EQ(ResultsDb::open(dir, true).load_single().controllers[0].finished[0].success_evaluation, 4);
}

// Schema 9: metrics in their generation's row, each name once. A schema-8 database (one row
// per metric in table metrics) reads the same metrics as it is, and when opened for writing
// moves them into its generations: the same names, values bit for bit, the table gone.
TEST(ResultsDb, ASchemaEightDatabasesMetricsMoveIntoTheirGenerations) {
  const fs::path dir = fresh_dir("metrics-8");
  eval::RunState other = state(1);
  other.run = 2;
  other.generations.back().metrics = {{"lambda", 12.0}, {"sigma", -0.0}};   // a name first seen here
  {
    ResultsDb db = ResultsDb::create(dir, spec(), {}, {});
    db.commit_generation("SC", state(1));
    db.commit_generation("SC", state(2));
    db.commit_generation("SC", other);
  }
  const auto metrics_of = [&dir](bool writable) {
    std::vector<std::vector<evo::Metric>> out;
    const StoredExperiment s = ResultsDb::open(dir, !writable).load_single();
    for (const eval::RunState& r : s.controllers.at(0).in_progress)
      for (const eval::GenerationStats& g : r.generations) out.push_back(g.metrics);
    return out;
  };
  const auto same = [](const std::vector<std::vector<evo::Metric>>& a, const std::vector<std::vector<evo::Metric>>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t g = 0; g < a.size(); ++g) {
      if (a[g].size() != b[g].size()) return false;
      for (std::size_t i = 0; i < a[g].size(); ++i)
        if (a[g][i].name != b[g][i].name || std::bit_cast<std::uint64_t>(a[g][i].value) !=
                                                std::bit_cast<std::uint64_t>(b[g][i].value))
          return false;
    }
    return true;
  };
  const auto written = metrics_of(false);
  ASSERT_EQ(written.size(), 3U);
  EXPECT_EQ(written[1].size(), 3U);
  EXPECT_EQ(written[2][0].name, "lambda");
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    test::as_schema8(raw);
  }
  const auto eight = metrics_of(false);
  EXPECT_EQ(eight.size(), written.size());
  EXPECT_EQ(eight[1][1], written[1][1]);
  EXPECT_TRUE(std::isnan(eight[1][2].value)) << "schema 8 kept NaN as NULL";
  EXPECT_TRUE(same(metrics_of(true), eight)) << "moved into the generations as schema 8 read them";
  sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadOnly);
  EXPECT_FALSE(raw.has_table("metrics"));
  auto names = raw.prepare("SELECT group_concat(name, ' ') FROM (SELECT name FROM metric_names ORDER BY idx)");
  ASSERT_TRUE(names.step());
  EXPECT_EQ(names.text(0), "sigma condition nothing lambda");
  auto version = raw.prepare("PRAGMA user_version");
  ASSERT_TRUE(version.step());
  EXPECT_EQ(version.int64(0), kSchemaVersion);
}

// Schema 9: a finished run's state is kept compressed, and carrying the run on reads it back
// byte for byte; compressed bytes that do not uncompress are refused, located.
TEST(ResultsDb, AFinishedRunsStateIsCompressedAndReadBackExactly) {
  const fs::path dir = fresh_dir("state-zlib");
  eval::RunState last = state(2);
  last.optimizer.bytes.assign(100000, 7);
  for (std::size_t i = 0; i < last.optimizer.bytes.size(); i += 13) last.optimizer.bytes[i] = static_cast<std::uint8_t>(i);
  eval::RunResult finished{1, last.seed, last.generations, 9.875, {0.5, 0.25, -0.125}, 1, 17, {7, 3}};
  {
    ResultsDb db = ResultsDb::create(dir, spec(), {}, {});
    db.commit_generation("SC", state(1));
    db.commit_generation("SC", last);
    db.commit_run("SC", finished);
  }
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadOnly);
    auto q = raw.prepare("SELECT length(state), raw_size FROM optimizer_state");
    ASSERT_TRUE(q.step());
    EXPECT_EQ(q.int64(1), 100000);
    EXPECT_LT(q.int64(0), 20000) << "stored compressed";
  }
  eval::ExperimentSpec longer = spec();
  longer.generations = 5;
  {
    ResultsDb db = ResultsDb::open(dir, true);
    const eval::ResumePoint p = db.resume_point(db.load_single(), longer);
    ASSERT_EQ(p.in_progress.size(), 1U);
    EXPECT_EQ(p.in_progress[0].state.optimizer, last.optimizer) << "carried on from the same bytes";
  }
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    raw.exec("UPDATE optimizer_state SET raw_size = raw_size + 1");
    seal_table(raw, "optimizer_state");
  }
  ResultsDb db = ResultsDb::open(dir, true);
  try {
    (void)db.resume_point(db.load_single(), longer);
    FAIL() << "carried on from a state of the wrong size";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("is damaged: run 2 of SC: its stored state does not uncompress to its 100001 bytes"),
              std::string::npos) << e.what();
  }
}

// A generation row naming a metric that metric_names lacks is refused, located, even with a
// checksum that matches (a row rewritten whole).
TEST(ResultsDb, AGenerationNamingAnUnstoredMetricIsDamage) {
  const fs::path dir = fresh_dir("metrics-damage");
  {
    ResultsDb db = ResultsDb::create(dir, spec(), {}, {});
    db.commit_generation("SC", state(1));
    db.commit_generation("SC", state(2));
  }
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    raw.exec("UPDATE generations SET metric_names = '0,1,9' WHERE generation = 1");
    seal_table(raw, "generations");
  }
  try {
    (void)ResultsDb::open(dir, true).load_single();
    FAIL() << "read a metric name that is not stored";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("is damaged: run 2 of SC: a metric name that is not stored"), std::string::npos)
        << e.what();
  }
}

TEST(ResultsDb, ClearErrorsForForeignDamagedAndNewerDatabases) {
  const fs::path none = fresh_dir("none");
  EXPECT_THROW((void)ResultsDb::open(none), StoreError);
  EXPECT_THROW((void)ResultsDb::open(none / "missing"), StoreError);

  const fs::path text = fresh_dir("text");
  std::ofstream(text / kDatabaseFile) << "this is not a database, but it is long enough to look like one......";
  try {
    (void)ResultsDb::open(text);
    ADD_FAILURE() << "opened a text file";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("esc.db"), std::string::npos) << e.what();
  }

  const fs::path foreign = fresh_dir("foreign");
  {
    sql::Database db(foreign / kDatabaseFile, sql::Database::Mode::Create);
    db.exec("CREATE TABLE t(x)");
  }
  try {
    (void)ResultsDb::open(foreign);
    ADD_FAILURE() << "opened a foreign database";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("not one written by esc"), std::string::npos) << e.what();
  }

  const fs::path newer = fresh_dir("newer");
  { (void)ResultsDb::create(newer, spec(), {}, {}); }
  {
    sql::Database db(newer / kDatabaseFile, sql::Database::Mode::ReadWrite);
    db.exec("PRAGMA user_version=99");
  }
  try {
    (void)ResultsDb::open(newer);
    ADD_FAILURE() << "opened a newer database";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("newer esc"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)ResultsDb::create(newer, spec(), {}, {}), StoreError);   // never overwritten
}

// A resume state is found in table optimizer_state, or, for a run an esc before schema 6
// left, in its algorithm's table; a run with none, or with a damaged one, is a damaged
// database, and the message names the run.
TEST(ResultsDb, AMissingOrDamagedStateNamesTheRun) {
  const fs::path dir = fresh_dir("damaged-state");
  { ResultsDb::create(dir, spec(), {}, {}).commit_generation("SC", state(1)); }
  const auto error = [&] {
    try {
      (void)ResultsDb::open(dir).load_single();
    } catch (const StoreError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  const auto raw = [&](const std::string& sql) {
    sql::Database db(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    db.exec(sql);
  };
  EXPECT_EQ(error(), "no error");
  raw("UPDATE optimizer_state SET state = substr(state, 9)");
  EXPECT_NE(error().find("the optimizer's state to continue from of run 2 of SC does not match its checksum"),
            std::string::npos)
      << error();
  raw("DELETE FROM optimizer_state");
  EXPECT_NE(error().find("run 2 of SC is unfinished but has no state to resume from"), std::string::npos) << error();
  // Parents as schema 5 kept them, one double short (sealed: the size check finds it).
  const std::vector<evo::Individual> parents{{std::vector<double>(spec().controllers[0].genome_size(), 0.5), {0.1}, 1.0}};
  std::vector<double> blob = pack_parents(parents);
  blob.pop_back();
  {
    sql::Database db(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    db.prepare("INSERT INTO run_state(controller_id, run, parents, genome_size, sigma_count, population) "
               "VALUES (1, 1, 1, ?, 1, ?)")
        .bind(1, static_cast<std::int64_t>(parents[0].genes.size())).bind_blob(2, blob).run();
    seal_table(db, "run_state");
  }
  EXPECT_NE(error().find("run 2 of SC: the stored population has the wrong size"), std::string::npos) << error();
}

TEST(ResultsDb, ASchemaThreeDatabaseIsReadThenSealedWhenWritten) {
  const fs::path dir = fresh_dir("upgrade-3");
  {
    ResultsDb db = ResultsDb::create(dir, spec(), {{"main.esc", "x"}}, {});
    db.commit_generation("SC", state(1));
    db.commit_generation("SC", state(2));
  }
  {  // What esc wrote before checksums.
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    test::keep_state_as_schema5(raw);
    test::drop_checksums(raw);
    raw.exec("ALTER TABLE generations DROP COLUMN saturated; DROP TABLE generation_usage; DROP TABLE choices; "
             "DROP TABLE transfers; PRAGMA user_version=3;");
  }
  const std::string before = export_json({{"d", ResultsDb::open(dir, true).load()}}).dump();
  { ResultsDb db = ResultsDb::open(dir); }   // upgraded: every row sealed as it is
  EXPECT_EQ(export_json({{"d", ResultsDb::open(dir, true).load()}}).dump(), before);
  {
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    raw.exec("UPDATE runs SET best_fitness = 9.5");
  }
  try {
    (void)ResultsDb::open(dir, true).load();
    ADD_FAILURE() << "a changed row of an upgraded database was read";
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("the run's record"), std::string::npos) << e.what();
  }
}

TEST(EsState, DamagedBlobsAreRefused) {
  const std::vector<evo::Individual> parents{{{0.5, -0.25, 1.0 / 3.0}, {0.05}, 3.25}, {{0.1, 0.2, 0.3}, {0.01}, -2.5}};
  const std::size_t genes = parents[0].genes.size();
  const std::vector<double> blob = pack_parents(parents);
  const auto back = unpack_parents(blob, 2, genes, 1);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ((*back)[1].genes, parents[1].genes);
  EXPECT_EQ((*back)[1].sigmas, parents[1].sigmas);
  EXPECT_EQ((*back)[1].fitness, parents[1].fitness);
  EXPECT_FALSE(unpack_parents(blob, 3, genes, 1).has_value());
  EXPECT_FALSE(unpack_parents(blob, 1, genes, 1).has_value());       // left-over values
  EXPECT_FALSE(unpack_parents(blob, 2, genes + 1, 1).has_value());
  EXPECT_FALSE(unpack_parents({1.0, 2.0}, 1, 0, 0).has_value());
}

TEST(ResultsDb, CampaignHashIgnoresDirectoriesAndOrder) {
  const std::vector<SourceFile> a = {{"x/main.esc", "A"}, {"/lib/k.esc", "K"}};
  const std::vector<SourceFile> b = {{"/abs/k.esc", "K"}, {"/abs/x/main.esc", "A"}};
  const std::vector<SourceFile> c = {{"x/main.esc", "A "}, {"/lib/k.esc", "K"}};
  EXPECT_EQ(campaign_hash("e", a), campaign_hash("e", b));
  EXPECT_NE(campaign_hash("e", a), campaign_hash("e", c));
  EXPECT_NE(campaign_hash("e", a), campaign_hash("f", a));
}

}  // namespace
}  // namespace esc::store
