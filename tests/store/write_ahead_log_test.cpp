// The write-ahead log's scan (write_ahead_log.hpp) on logs SQLite wrote and then damaged
// by hand: what it reads, what is damage (a frame of the log's current contents past what
// SQLite reads) and what is not (stale frames from before a restart, a partial frame); and
// SQLite's page check said in one line, all its problems in the file it names.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "runtime/store/page_check.hpp"
#include "runtime/store/sqlite.hpp"
#include "runtime/store/write_ahead_log.hpp"
#include "tests/store/scratch.hpp"

namespace esc::store {
namespace {

namespace fs = std::filesystem;
using test::fresh_dir;

constexpr std::size_t kPage = 4096;
constexpr std::size_t kFrame = 24 + kPage;

std::vector<std::uint8_t> bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

LogScan scan(const std::vector<std::uint8_t>& log) { return scan_log(std::span(log), kPage); }

// Byte `at` of frame `frame` (from 1).
std::size_t in_frame(std::size_t frame, std::size_t at) { return 32 + (frame - 1) * kFrame + at; }

std::vector<std::uint8_t> flipped(std::vector<std::uint8_t> log, std::size_t byte) {
  log[byte] ^= 0x04;
  return log;
}

// A log of 12 commits restarted by a checkpoint and written again by 2: its first frames
// the current contents, the rest stale (the old salts), as SQLite leaves a log it reuses.
std::vector<std::uint8_t> restarted_log() {
  const fs::path dir = fresh_dir("restarted-log");
  fs::create_directories(dir);
  std::vector<std::uint8_t> log;
  {
    sql::Database db(dir / "t.db", sql::Database::Mode::Create);
    db.exec("PRAGMA journal_mode=WAL; CREATE TABLE t(x BLOB);");
    for (int i = 0; i < 12; ++i) db.exec("INSERT INTO t VALUES (zeroblob(3000));");
    db.exec("PRAGMA wal_checkpoint(RESTART);");
    for (int i = 0; i < 2; ++i) db.exec("INSERT INTO t VALUES (zeroblob(3000));");
    log = bytes_of(dir / "t.db-wal");   // before the connection closes and folds it in
  }
  fs::remove_all(dir);
  return log;
}

TEST(WriteAheadLog, ReadsWhatSqliteReads) {
  const std::vector<std::uint8_t> log = restarted_log();
  const LogScan s = scan(log);
  EXPECT_GT(s.frames, s.valid);   // stale frames beyond
  EXPECT_GT(s.valid, 0);
  EXPECT_EQ(s.committed, s.valid);
  EXPECT_EQ(s.lost, 0);
  EXPECT_FALSE(s.damaged);
  // A write cut short by a kill: part of a frame at the end.
  std::vector<std::uint8_t> partial = log;
  partial.resize(partial.size() + 24 + 100, 0x5a);
  EXPECT_FALSE(scan(partial).damaged);
  // No log, or a header alone: nothing to lose.
  EXPECT_FALSE(scan({}).damaged);
  EXPECT_FALSE(scan(std::vector<std::uint8_t>(log.begin(), log.begin() + 32)).damaged);
}

TEST(WriteAheadLog, StaleFramesAreNotDamage) {
  const std::vector<std::uint8_t> log = restarted_log();
  const LogScan s = scan(log);
  for (std::size_t frame = static_cast<std::size_t>(s.valid) + 1; frame <= static_cast<std::size_t>(s.frames); ++frame)
    for (const std::size_t at : {std::size_t{0}, std::size_t{8}, std::size_t{12}, std::size_t{20}, 24 + kPage / 2}) {
      const LogScan f = scan(flipped(log, in_frame(frame, at)));
      EXPECT_FALSE(f.damaged) << "stale frame " << frame << " byte " << at;
      EXPECT_EQ(f.committed, s.committed);
    }
}

TEST(WriteAheadLog, AFlipInTheCurrentContentsIsDamage) {
  const std::vector<std::uint8_t> log = restarted_log();
  const LogScan s = scan(log);
  const auto last = static_cast<std::size_t>(s.valid);
  // Every part of the last commit frame: page number, database size, each salt, each
  // checksum, its page.
  for (const std::size_t at : {std::size_t{1}, std::size_t{7}, std::size_t{9}, std::size_t{14}, std::size_t{17},
                               std::size_t{23}, std::size_t{24}, 24 + kPage - 1}) {
    const LogScan f = scan(flipped(log, in_frame(last, at)));
    EXPECT_TRUE(f.damaged) << "byte " << at;
    EXPECT_LT(f.committed, s.committed) << "byte " << at;
    EXPECT_GE(f.lost, 1) << "byte " << at;
  }
  // The first frame: every frame of the current contents is lost.
  const LogScan first = scan(flipped(log, in_frame(1, 24 + 10)));
  EXPECT_TRUE(first.damaged);
  EXPECT_EQ(first.committed, 0);
  EXPECT_EQ(first.lost, s.valid);
}

TEST(WriteAheadLog, ADamagedHeaderLosesEveryCurrentFrame) {
  const std::vector<std::uint8_t> log = restarted_log();
  const LogScan s = scan(log);
  // Magic, version, page size, checkpoint sequence, salt-1, salt-2, both checksums.
  for (const std::size_t at : {3, 6, 10, 15, 17, 22, 25, 31}) {
    const LogScan f = scan(flipped(log, at));
    EXPECT_TRUE(f.damaged) << "header byte " << at;
    EXPECT_EQ(f.committed, 0) << "header byte " << at;
    EXPECT_EQ(f.lost, s.valid) << "header byte " << at;
  }
}

TEST(WriteAheadLog, ReadFromBesideTheDatabase) {
  const fs::path dir = fresh_dir("beside");
  fs::create_directories(dir);
  EXPECT_FALSE(log_damage(dir / "t.db"));   // no log
  const std::vector<std::uint8_t> log = flipped(restarted_log(), in_frame(1, 30));
  std::ofstream(dir / "t.db-wal", std::ios::binary).write(reinterpret_cast<const char*>(log.data()),
                                                           static_cast<std::streamsize>(log.size()));
  const std::optional<LogScan> damage = log_damage(dir / "t.db");
  ASSERT_TRUE(damage);
  EXPECT_EQ(log_damage_text(dir / "t.db", *damage),
            (dir / "t.db").string() + "-wal holds " + std::to_string(damage->lost) +
                " frames past its last valid commit (a damaged write-ahead log)");
  fs::remove_all(dir);
}

// Pages no b-tree uses (the free list's head cut off): SQLite lists one problem a page.
TEST(PageCheck, ManyProblemsInOneLineAndAFile) {
  const fs::path dir = fresh_dir("page-check");
  fs::create_directories(dir);
  {
    sql::Database db(dir / "t.db", sql::Database::Mode::Create);
    db.exec("CREATE TABLE t(x BLOB);");
    for (int i = 0; i < 40; ++i) db.exec("INSERT INTO t VALUES (zeroblob(3000));");
    db.exec("DELETE FROM t;");
    EXPECT_FALSE(page_check_problem(db));
  }
  std::vector<std::uint8_t> file = bytes_of(dir / "t.db");
  std::fill(file.begin() + 32, file.begin() + 40, 0);   // the free list's first page and count
  std::ofstream(dir / "t.db", std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(file.data()), static_cast<std::streamsize>(file.size()));
  sql::Database db(dir / "t.db", sql::Database::Mode::ReadOnly);
  const std::optional<std::string> problem = page_check_problem(db);
  ASSERT_TRUE(problem);
  EXPECT_EQ(problem->find('\n'), std::string::npos) << *problem;
  EXPECT_EQ(problem->rfind("Page 3 is never used (40 problems in all, listed in ", 0), 0U) << *problem;
  const std::string listing_file = problem->substr(problem->find(" listed in ") + 11, std::string::npos);
  const fs::path listing = listing_file.substr(0, listing_file.size() - 1);   // without ")"
  const std::string listed = test::slurp(listing);
  EXPECT_EQ(std::count(listed.begin(), listed.end(), '\n'), 41) << listed;   // and SQLite's heading
  EXPECT_NE(listed.find("Page 42 is never used"), std::string::npos);
  fs::remove(listing);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace esc::store
