// Tree controllers in the results store: a GP population committed every generation loads
// back bit for bit (the state a killed GP run resumes from), a finished run keeps its best
// tree as script code, and the run directory writes that tree where a user can paste it.
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "runtime/genome/tree/codec.hpp"
#include "runtime/evo/gp/gp_optimizer.hpp"
#include "runtime/genome/tree/print.hpp"
#include "runtime/store/results_db.hpp"
#include "runtime/store/row_checksum.hpp"
#include "runtime/store/run_directory.hpp"
#include "runtime/store/sqlite.hpp"
#include "runtime/store/tree_state.hpp"
#include "tests/eval/gp_experiment.hpp"
#include "tests/store/older_schema.hpp"
#include "tests/store/scratch.hpp"

namespace esc::store {
namespace {

namespace fs = std::filesystem;

using test::slurp;

// An empty directory for a database.
fs::path fresh_dir(const std::string& name) {
  const fs::path d = test::fresh_dir("tree-" + name);
  fs::create_directories(d);
  return d;
}

// A real initial population of the Wheels tree, with fitness that no text could round.
std::vector<evo::gp::Individual> population(const eval::ExperimentSpec& e) {
  const evo::gp::GeneticProgramming gp(*e.tree_operators(), *e.controllers[0].primitives);
  Rng rng(99);
  std::vector<evo::gp::Individual> pop = gp.initial(rng);
  for (std::size_t i = 0; i < pop.size(); ++i) pop[i].fitness = 1.0 / (3.0 + static_cast<double>(i));
  return pop;
}

// What GP saves comes back byte for byte; a population that results schema 5 kept in table
// tree_state comes back as GP would have saved it.
TEST(TreeState, AGpPopulationRoundTripsBitForBit) {
  const eval::ExperimentSpec e = testing::gp_experiment();
  eval::RunState st;
  st.run = 1;
  st.seed = 0xfedcba9876543210ULL;
  st.generations.push_back({0, 2.5, 1.0 / 3.0, 0.5, 24, 999, 0.1});
  const std::vector<evo::gp::Individual> pop = population(e);
  st.optimizer = {"gp", 1, evo::gp::gp_state(pop)};
  st.has_best = true;
  st.best_fitness = 2.5;
  st.best_genome = genome::tree::encode(pop[3].tree);
  for (const bool legacy : {false, true}) {
    const fs::path dir = fresh_dir(legacy ? "population-schema5" : "population");
    {
      ResultsDb db = ResultsDb::create(dir, e, {}, {});
      db.commit_generation("GW", st);
    }
    if (legacy) {
      sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
      raw.exec("DELETE FROM optimizer_state");
      raw.prepare("INSERT INTO tree_state(controller_id, run, individuals, population) VALUES (1, 1, ?, ?)")
          .bind(1, static_cast<std::int64_t>(pop.size())).bind_blob(2, pack_trees(pop)).run();
      seal_table(raw, "tree_state");
    }
    ResultsDb db = ResultsDb::open(dir);
    const StoredExperiment s = db.load_single();
    EXPECT_EQ(s.generations, 6);
    const StoredController& c = s.controllers.at(0);
    EXPECT_EQ(c.head, "tree");
    EXPECT_EQ(c.architecture, "tree wheels");
    EXPECT_EQ(c.genome_size, 40u);   // max_size
    ASSERT_EQ(c.in_progress.size(), 1u);
    const eval::RunState& got = c.in_progress[0];
    EXPECT_EQ(got.optimizer, st.optimizer) << (legacy ? "schema 5" : "schema 6");
    EXPECT_EQ(got.best_genome, st.best_genome);
  }
}

TEST(TreeState, AFinishedRunKeepsItsBestTreeAndDropsItsState) {
  const fs::path dir = fresh_dir("finished");
  const eval::ExperimentSpec e = testing::gp_experiment();
  const auto pop = population(e);
  const genome::tree::PrimitiveSet& set = *e.controllers[0].primitives;
  eval::RunState st;
  st.generations.push_back({0, 2.5, 1.0, 0.5, 24, 999, 0.1});
  st.optimizer = {"gp", 1, evo::gp::gp_state(pop)};
  eval::RunResult r;
  r.generations = st.generations;
  r.best_fitness = 2.5;
  r.best_genome = genome::tree::encode(pop[0].tree);
  r.best_tree = genome::tree::to_script(pop[0].tree, set);
  r.best_behavior = r.best_tree;   // a Wheels tree is its own behavior body
  {
    RunDirectory rd(dir / "out", e, {});
    rd.checkpoint(e.controllers[0], st);
    rd.run_done(e.controllers[0], r);
  }
  const StoredExperiment s = ResultsDb::open(dir / "out").load_single();
  const StoredController& c = s.controllers.at(0);
  EXPECT_TRUE(c.in_progress.empty());
  ASSERT_EQ(c.finished.size(), 1u);
  EXPECT_EQ(c.finished[0].best_tree, r.best_tree);
  EXPECT_EQ(c.finished[0].best_behavior, r.best_behavior);
  EXPECT_EQ(genome::tree::decode(c.finished[0].best_genome, set), pop[0].tree);
  const std::string esc = slurp(dir / "out" / "GW" / "run-01.best.esc");
  EXPECT_NE(esc.find("behavior GW_run01() { " + r.best_tree + " }"), std::string::npos) << esc;
  EXPECT_NE(slurp(dir / "out" / "summary.json").find("\"best_tree\""), std::string::npos);
  EXPECT_NE(slurp(dir / "out" / "summary.json").find("\"genome_size\": 40"), std::string::npos);
}

TEST(TreeState, ASchemaOneDatabaseIsReadAndUpgradedWhenWritten) {
  const fs::path dir = fresh_dir("upgrade");
  eval::ExperimentSpec e = testing::small_experiment();
  eval::RunResult r;
  r.generations.push_back({0, 2.5, 1.0, 0.5, 24, 999, 0.1});
  r.best_fitness = 2.5;
  r.best_genome = {0.25};
  const auto commit = [&](ResultsDb& db) {
    eval::RunState st;
    st.run = r.run;
    st.generations = r.generations;
    db.commit_generation("CC", st);
    db.commit_run("CC", r);
  };
  {
    ResultsDb db = ResultsDb::create(dir, e, {}, {});
    commit(db);
  }
  {  // What esc wrote before GP.
    sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadWrite);
    test::keep_state_as_schema5(raw);
    raw.exec("DROP TABLE generation_usage; DROP TABLE choices; DROP TABLE transfers; "
             "DROP TABLE condition_settings; DROP TABLE conditions; DROP TABLE studies; "
             "ALTER TABLE runs DROP COLUMN best_behavior; DROP TABLE tree_state; PRAGMA user_version=1;");
  }
  EXPECT_EQ(ResultsDb::open(dir, true).load_single().controllers.at(0).finished.at(0).best_fitness, 2.5);
  {
    ResultsDb db = ResultsDb::open(dir);
    r.run = 1;
    commit(db);
  }
  sql::Database raw(dir / kDatabaseFile, sql::Database::Mode::ReadOnly);
  auto version = raw.prepare("PRAGMA user_version");
  ASSERT_TRUE(version.step());
  EXPECT_EQ(version.int64(0), kSchemaVersion);
  EXPECT_EQ(ResultsDb::open(dir, true).load_single().controllers.at(0).finished.size(), 2u);
}

TEST(TreeState, DamagedBlobsAreRefused) {
  const eval::ExperimentSpec e = testing::gp_experiment();
  const auto pop = population(e);
  const std::vector<double> blob = pack_trees(pop);
  ASSERT_TRUE(unpack_trees(blob, pop.size()).has_value());
  EXPECT_FALSE(unpack_trees(blob, pop.size() + 1).has_value());
  EXPECT_FALSE(unpack_trees(blob, pop.size() - 1).has_value());   // left-over values
  std::vector<double> bad = blob;
  bad[1] = 1e9;   // a node count beyond the blob
  EXPECT_FALSE(unpack_trees(bad, pop.size()).has_value());
  bad = blob;
  bad[2] = 0.5;   // a primitive id that is not whole
  EXPECT_FALSE(unpack_trees(bad, pop.size()).has_value());
  bad = blob;
  bad[4] = 9;     // no such type
  EXPECT_FALSE(unpack_trees(bad, pop.size()).has_value());
}

}  // namespace
}  // namespace esc::store
