// Integrity of a stopped run's database: a single bit flipped anywhere in it, in the rows
// resume reads (experiment, settings, controllers, runs and their seeds, statistics, the
// population to continue from, behavior usage, the replay) or in SQLite's own pages, is
// refused when the database is loaded, or provably harmless: everything that loads is
// exactly what was stored, so the resumed run cannot differ. A bit flipped in a killed run's
// log (esc.db-wal) is said (what SQLite dropped), refused, or harmless.
#include <bit>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "runtime/evo/es/es_optimizer.hpp"
#include "runtime/store/export.hpp"
#include "runtime/store/results_db.hpp"
#include "runtime/store/untouched_load.hpp"
#include "runtime/store/write_ahead_log.hpp"
#include "tests/store/scratch.hpp"
#include "tests/algorithm_settings.hpp"

namespace esc::store {
namespace {

namespace fs = std::filesystem;
using test::fresh_dir;

eval::ExperimentSpec spec() {
  eval::ExperimentSpec e;
  e.name = "flips";
  e.seed = 77;
  e.runs = 2;
  e.generations = 5;
  e.resolved_settings = {{"epochs", "10"}, {"steps", "150"}};
  control::ControllerSpec c;   // a classical head: usage is stored all the same
  c.name = "SC";
  c.mlp.inputs = {0, 1, 2};
  e.controllers.push_back(c);
  return e;
}

eval::RunState state(int run, int generations) {
  eval::RunState s;
  s.run = run;
  s.seed = 0x0123456789abcdefULL + static_cast<std::uint64_t>(run);
  for (int g = 0; g < generations; ++g) s.generations.push_back({g, 2.0 / 3.0 + g, 0.1 * g, 0.5, 20, 1234, 0.25, {}, 0});
  const std::size_t n = spec().controllers[0].genome_size();
  std::vector<double> a(n);
  for (std::size_t i = 0; i < n; ++i) a[i] = static_cast<double>(i) / 7.0 - 0.5 + run;
  const std::vector<evo::Individual> parents{{a, {0.05}, 3.25}, {a, {0.01}, -2.5}};
  s.optimizer = {"es", 1, evo::es_state(parents)};
  s.has_best = true;
  s.best_fitness = 9.875 + run;
  s.best_genome = a;
  for (double& g : s.best_genome) g += 100.0;   // other bytes than the population's
  s.best_generation = generations - 1;
  s.best_index = 3;
  return s;
}

// A database as a killed run leaves it: run 1 finished (with its replay and usage), run 2
// in progress after 3 generations. With `killed`, its esc.db and esc.db-wal are copied
// there while the connection is open, as a kill leaves them (closing folds the log in).
fs::path stopped_run(const fs::path& killed = {}) {
  const fs::path dir = fresh_dir("stopped");
  fs::create_directories(dir);
  ResultsDb db = ResultsDb::create(dir, spec(), {{"main.esc", "experiment flips { runs 2 }"}}, {"/x/main.esc", {}, "1"});
  for (int g = 1; g <= 5; ++g) db.commit_generation("SC", state(0, g));
  eval::RunResult done;
  const eval::RunState last = state(0, 5);
  done.run = 0;
  done.seed = last.seed;
  done.generations = last.generations;
  done.best_fitness = last.best_fitness;
  done.best_genome = last.best_genome;
  done.best_generation = last.best_generation;
  done.best_index = last.best_index;
  done.action_usage = {700, 800};
  std::vector<eval::TraceStep> trace(40);
  for (std::size_t i = 0; i < trace.size(); ++i) {
    trace[i].step = static_cast<int>(i);
    trace[i].pose = {0.01 * static_cast<double>(i), -0.02, 1.5};
    trace[i].fitness = 0.125 * static_cast<double>(i);
  }
  db.commit_replay("SC", done, trace);
  db.commit_run("SC", done);
  for (int g = 1; g <= 3; ++g) db.commit_generation("SC", state(1, g));
  if (!killed.empty()) {
    fs::create_directories(killed);
    for (const std::string suffix : {"", "-wal"})
      fs::copy_file(dir / (kDatabaseFile + suffix), killed / (kDatabaseFile + suffix));
  }
  return dir;   // the connection closes: the log is folded into esc.db
}

void bits(std::string& out, double x) { out += fmt::format("{:016x} ", std::bit_cast<std::uint64_t>(x)); }

// Everything a resume uses, as text: the export (experiment, settings, sources, every run's
// seed, statistics and best genome) and, bit for bit, each population and replay.
std::string loaded(const fs::path& dir) {
  std::vector<StoredExperiment> all = ResultsDb::open(dir, true).load();
  std::string out = export_json({{"d", all}}).dump();
  for (const StoredExperiment& e : all)
    for (const StoredController& c : e.controllers) {
      for (const eval::RunState& s : c.in_progress)
        out.append(s.optimizer.bytes.begin(), s.optimizer.bytes.end());
      for (const eval::RunResult& r : c.finished)
        for (double g : r.best_genome) bits(out, g);
      if (c.replay) {
        out += fmt::format("replay {} {} ", c.replay->run, c.replay->seed);
        bits(out, c.replay->fitness);
        for (const eval::TraceStep& t : c.replay->steps) {
          for (double v : {t.pose.x_m, t.pose.y_m, t.pose.heading_rad, t.fitness, t.energy}) bits(out, v);
          out += fmt::format("{} {} {} ", t.step, t.action, t.collided);
        }
      }
    }
  return out;
}

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

enum class Verdict { Refused, Harmless, Different };

// A copy of `dir` with bit `bit` of esc.db flipped, loaded.
Verdict flip(const fs::path& dir, std::size_t bit, const std::string& reference, std::string* message) {
  const fs::path copy = fresh_dir("flipped");
  fs::copy(dir, copy, fs::copy_options::recursive);
  std::string db = read_bytes(copy / kDatabaseFile);
  db[bit / 8] = static_cast<char>(db[bit / 8] ^ (1 << (bit % 8)));
  std::ofstream(copy / kDatabaseFile, std::ios::binary | std::ios::trunc) << db;
  Verdict v = Verdict::Different;
  try {
    v = loaded(copy) == reference ? Verdict::Harmless : Verdict::Different;
  } catch (const StoreError& e) {
    *message = e.what();
    v = Verdict::Refused;
  }
  fs::remove_all(copy);
  return v;
}

TEST(BitFlip, EveryFlipIsRefusedOrHarmless) {
  const fs::path dir = stopped_run();
  ASSERT_FALSE(fs::exists(dir / "esc.db-wal") && fs::file_size(dir / "esc.db-wal") > 0);
  const std::string reference = loaded(dir);
  const std::string db = read_bytes(dir / kDatabaseFile);

  // Bits inside values of each table resume reads, found by their bytes in the file; a
  // flip in any of them changes a value, so each must be refused.
  std::string genes(8, '\0');
  const double gene = 1.0 / 7.0 - 0.5 + 1;   // run 2's second gene, in its population
  std::memcpy(genes.data(), &gene, 8);
  std::string third(8, '\0');
  const double stat = 2.0 / 3.0 + 2;   // generation 2's best
  std::memcpy(third.data(), &stat, 8);
  const std::vector<std::pair<std::string, std::string>> values = {
      {"experiments", R"("cylinders")"},   // in the arena's JSON
      {"sources", "experiment flips { runs 2 }"},
      {"settings", "150"},
      {"controllers", "classical"},
      {"runs", std::to_string(0x0123456789abcdefULL + 1)},
      {"generations", third},
      {"optimizer_state", genes},
  };
  int targeted = 0;
  for (const auto& [table, bytes] : values) {
    const std::size_t at = db.rfind(bytes);
    if (at == std::string::npos) continue;
    for (std::size_t k = 0; k < bytes.size(); k += 3) {
      std::string message;
      const Verdict v = flip(dir, (at + k) * 8 + k % 8, reference, &message);
      EXPECT_NE(v, Verdict::Different) << table << " byte " << k;
      if (v == Verdict::Refused) {
        ++targeted;
        EXPECT_NE(message.find("is damaged"), std::string::npos) << message;
      }
    }
  }
  EXPECT_GE(targeted, 12);

  // Bits spread over the whole file: headers, b-tree pages, free space.
  int refused = 0;
  int harmless = 0;
  constexpr std::size_t kSpread = 96;
  for (std::size_t i = 0; i < kSpread; ++i) {
    std::string message;
    const std::size_t bit = (db.size() * 8 / kSpread) * i + (i * 5) % 8 + 8 * (i % 7);
    switch (flip(dir, bit, reference, &message)) {
      case Verdict::Refused: ++refused; break;
      case Verdict::Harmless: ++harmless; break;
      case Verdict::Different: ADD_FAILURE() << "bit " << bit << " changed what loads without being refused"; break;
    }
  }
  EXPECT_GT(refused, 0);
  EXPECT_EQ(refused + harmless, static_cast<int>(kSpread));
  fs::remove_all(dir);
}

TEST(BitFlip, DamagedPopulationNamesTheRun) {
  const fs::path dir = stopped_run();
  const std::string reference = loaded(dir);
  const std::string db = read_bytes(dir / kDatabaseFile);
  std::string genes(8, '\0');
  const double gene = 1.0 / 7.0 - 0.5 + 1;
  std::memcpy(genes.data(), &gene, 8);
  const std::size_t at = db.rfind(genes);
  ASSERT_NE(at, std::string::npos);
  std::string message;
  ASSERT_EQ(flip(dir, at * 8 + 3, reference, &message), Verdict::Refused);
  EXPECT_NE(message.find("the optimizer's state to continue from"), std::string::npos) << message;
  EXPECT_NE(message.find("of run 2 of SC"), std::string::npos) << message;
  fs::remove_all(dir);
}

// A killed run's log (esc.db-wal) with one bit flipped, anywhere: SQLite drops the frames
// from the flip on and would show an earlier commit without a word. Every flip is said (the
// log is damaged: what was lost), refused, or harmless (all that was committed loads).
TEST(BitFlip, EveryFlipInALogIsSaidOrHarmless) {
  const fs::path killed = fresh_dir("killed");
  const fs::path folded = stopped_run(killed);
  const std::string reference = loaded(folded);
  ASSERT_EQ(loaded(killed), reference);   // everything committed is read through the log
  ASSERT_FALSE(ResultsDb::open(killed, true).log_damage());
  const std::string log = read_bytes(killed / (std::string(kDatabaseFile) + "-wal"));
  ASSERT_GT(log.size(), 32U + 5 * (24 + 4096));

  int said = 0;
  int harmless = 0;
  // The header's bytes, the first frame's header, then bits spread over the whole log.
  std::vector<std::size_t> bits;
  for (std::size_t byte = 0; byte < 32 + 24; byte += 3) bits.push_back(byte * 8 + byte % 8);
  constexpr std::size_t kSpread = 60;
  for (std::size_t i = 0; i < kSpread; ++i) bits.push_back((log.size() * 8 / kSpread) * i + (i * 3) % 8 + 8 * (i % 5));
  for (const std::size_t bit : bits) {
    const fs::path copy = fresh_dir("flipped-log");
    fs::copy(killed, copy, fs::copy_options::recursive);
    std::string flipped = log;
    flipped[bit / 8] = static_cast<char>(flipped[bit / 8] ^ (1 << (bit % 8)));
    std::ofstream(copy / (std::string(kDatabaseFile) + "-wal"), std::ios::binary | std::ios::trunc) << flipped;
    try {
      const std::optional<LogScan> damage = ResultsDb::open(copy, true).log_damage();
      if (damage) {
        ++said;
        EXPECT_GT(damage->lost, 0) << "bit " << bit;
      } else {
        EXPECT_EQ(loaded(copy), reference) << "bit " << bit << " lost commits without a word";
        ++harmless;
      }
    } catch (const StoreError& e) {   // nothing readable before the flip: said so
      ++said;
      EXPECT_NE(std::string(e.what()).find("(a damaged write-ahead log)"), std::string::npos) << e.what();
    }
    fs::remove_all(copy);
  }
  EXPECT_EQ(said + harmless, static_cast<int>(bits.size()));
  EXPECT_GT(said, static_cast<int>(bits.size()) / 2);
  fs::remove_all(killed);
  fs::remove_all(folded);
}

// A resume (the database opened for writing) starts from the damaged log's last valid
// commit and empties the log: what it then writes cannot be mistaken for damage later.
TEST(BitFlip, WritingAfterADamagedLogEmptiesIt) {
  const fs::path killed = fresh_dir("killed-written");
  const fs::path folded = stopped_run(killed);
  const fs::path wal = killed / (std::string(kDatabaseFile) + "-wal");
  std::string log = read_bytes(wal);
  log[log.size() - 100] = static_cast<char>(log[log.size() - 100] ^ 1);   // in the last commit
  std::ofstream(wal, std::ios::binary | std::ios::trunc) << log;
  {
    ResultsDb db = ResultsDb::open(killed);
    ASSERT_TRUE(db.log_damage());
    EXPECT_EQ(fs::file_size(wal), 0U);
    db.commit_generation("SC", state(1, 3));   // the generation the damage lost, again
    EXPECT_FALSE(log_damage(killed / kDatabaseFile));
  }
  EXPECT_FALSE(ResultsDb::open(killed, true).log_damage());
  fs::remove_all(killed);
  fs::remove_all(folded);
}

// A killed run's esc.db cut to nothing beside its log: not a run stopped before it started
// (whose directory `esc run --out` would reuse, deleting the log), but a damaged database.
TEST(BitFlip, AnEmptyDatabaseBesideItsLogIsDamaged) {
  const fs::path killed = fresh_dir("killed-emptied");
  const fs::path folded = stopped_run(killed);
  fs::resize_file(killed / kDatabaseFile, 0);
  try {
    (void)ResultsDb::open(killed, true);
    ADD_FAILURE() << "an empty esc.db beside its log was read";
  } catch (const NothingStored& e) {
    ADD_FAILURE() << e.what();
  } catch (const StoreError& e) {
    EXPECT_NE(std::string(e.what()).find("esc.db is empty but "), std::string::npos) << e.what();
  }
  EXPECT_FALSE(holds_nothing_stored(killed));
  fs::remove_all(killed);
  fs::remove_all(folded);
}

}  // namespace
}  // namespace esc::store
