// End-to-end integrity of stored runs: a bit flipped in a killed run's stored population
// (ES parents or GP trees) is refused on resume, naming the run and what is damaged; every
// kind of refused resume or carry-on (damaged state, changed script, nothing stored, a
// run stopped in its dependencies, a directory in use) leaves every byte of the directory
// as it was and says why in one line (details with --verbose); a directory whose esc.db
// holds nothing can be run into again, unless another esc process is writing into it. A
// bit flipped in a killed run's log is said by every reader and run again by the resume; a
// database damaged in SQLite's pages is refused in one line.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "runtime/store/sqlite.hpp"
#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

namespace fs = std::filesystem;
using namespace cli_test;

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Every file under `dir` with its bytes.
std::map<std::string, std::string> contents(const fs::path& dir) {
  std::map<std::string, std::string> all;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) all[fs::relative(e.path(), dir).string()] = bytes_of(e.path());
  return all;
}

// Resumes `dir` (with `more` arguments), expecting a refusal (exit 1, naming `why` in one
// line, or in `lines` with --verbose) that changes nothing. Returns what it printed.
std::string expect_refused_untouched(const fs::path& dir, const std::string& why, const std::string& more = "",
                                     long lines = 1) {
  const auto before = contents(dir);
  const Outcome o = cli_test::esc("run --resume " + dir.string() + more);
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find(why), std::string::npos) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), lines) << o.output;
  const auto after = contents(dir);
  EXPECT_EQ(before.size(), after.size());
  for (const auto& [name, text] : before) EXPECT_TRUE(after.count(name) && after.at(name) == text) << name;
  return o.output;
}

// Flips one bit, `offset` bytes into the first optimizer state (ES parents, GP trees) in a
// killed run's database; returns which run it belongs to.
std::string flip_population_bit(const fs::path& killed, std::size_t offset) {
  std::string population;
  std::string which;
  {
    // The last connection folds the killed run's log into esc.db (what a copy of the
    // directory would hold after any esc command read it).
    esc::store::sql::Database db(killed / "esc.db", esc::store::sql::Database::Mode::ReadWrite);
    auto q = db.prepare("SELECT c.name, s.run, s.state FROM optimizer_state s JOIN controllers c "
                        "ON c.id = s.controller_id ORDER BY s.controller_id, s.run LIMIT 1");
    EXPECT_TRUE(q.step());
    which = "of run " + std::to_string(q.int64(1) + 1) + " of " + q.text(0);
    population = std::string(q.bytes(2));
  }
  EXPECT_GT(population.size(), offset);
  std::string db = bytes_of(killed / "esc.db");
  // The blob's start: a long one continues on overflow pages elsewhere in the file.
  const std::size_t at = db.rfind(population.substr(0, offset + 16));
  EXPECT_NE(at, std::string::npos);
  if (at == std::string::npos || population.size() <= offset) return which;
  db[at + offset] = static_cast<char>(db[at + offset] ^ 0x10);
  std::ofstream(killed / "esc.db", std::ios::binary | std::ios::trunc) << db;
  return which;
}

TEST(Integrity, FlippedPopulationBitIsRefusedAndChangesNothing) {
  const fs::path killed = scratch("integrity-killed");
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tiny(), killed, 20, 400));
  const std::string which = flip_population_bit(killed, 44);   // a gene's mantissa

  expect_refused_untouched(killed, "does not match its checksum");
  const Outcome o = cli_test::esc("run --resume " + killed.string());
  EXPECT_NE(o.output.find("the optimizer's state to continue from"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find(which), std::string::npos) << o.output;
  // Report and export refuse it too.
  EXPECT_EQ(cli_test::esc("export " + killed.string() + " --format csv").status, 1);
  EXPECT_EQ(cli_test::esc("report " + killed.string()).status, 1);
}

// The same for a GP run's stored trees.
TEST(Integrity, FlippedTreePopulationBitIsRefused) {
  const fs::path killed = scratch("integrity-killed-gp");
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tiny_gp(), killed, 240, 600));
  const std::string which = flip_population_bit(killed, 40);
  const std::string refused = expect_refused_untouched(killed, "does not match its checksum");
  EXPECT_NE(refused.find("the optimizer's state to continue from"), std::string::npos) << refused;
  EXPECT_NE(refused.find(which), std::string::npos) << refused;
}

TEST(Integrity, ChangedScriptRefusalChangesNothing) {
  const fs::path src = scratch("integrity-src");
  fs::create_directories(src);
  fs::copy_file(tiny(), src / "tiny.esc");
  const fs::path changed = scratch("integrity-changed");
  const pid_t child = spawn_esc(
      {"run", (src / "tiny.esc").string(), "--generations", "200", "--threads", "1", "--out", changed.string()});
  ASSERT_GE(child, 0);
  ASSERT_GE(kill_when_committed(child, changed, 3).seen, 3);
  std::ofstream(src / "tiny.esc", std::ios::app) << "\n// an edit\n";
  EXPECT_NE(expect_refused_untouched(changed, "has changed").find("--verbose names the files"), std::string::npos);
  // --verbose names the file and the hashes; a carry-on is refused alike.
  const std::string verbose = expect_refused_untouched(changed, "has changed", " --verbose", 4);
  EXPECT_NE(verbose.find("changed or new: " + (src / "tiny.esc").string()), std::string::npos) << verbose;
  EXPECT_NE(verbose.find("content hash"), std::string::npos) << verbose;
  expect_refused_untouched(changed, "has changed", " --generations 300");
  // A script that no longer compiles: one line, its diagnostics with --verbose.
  std::ofstream(src / "tiny.esc", std::ios::app) << "experiment broken {\n";
  EXPECT_NE(expect_refused_untouched(changed, "no longer compiles: unexpected end of file: missing `}` (1 error, all "
                                              "shown with --verbose)")
                .find("resumes only"),
            std::string::npos);
  const std::string diagnostics = expect_refused_untouched(changed, "missing `}` (1 error)", " --verbose", 8);
  EXPECT_NE(diagnostics.find("missing `}`"), std::string::npos) << diagnostics;
}

// A carry-on that cannot be done (fewer generations than the run has) is refused before
// anything is written.
TEST(Integrity, RefusedCarryOnChangesNothing) {
  const fs::path dir = scratch("integrity-carry-on");
  ASSERT_EQ(cli_test::esc("run " + tiny() + " --generations 3 --out " + dir.string()).status, 0);
  const auto before = contents(dir);
  const Outcome o = cli_test::esc("run --resume " + dir.string() + " --generations 2");
  EXPECT_NE(o.status, 0) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << o.output;
  EXPECT_EQ(contents(dir), before);
}

TEST(Integrity, EmptyDatabaseHoldsNothingAndCanBeReused) {
  const fs::path dir = scratch("integrity-empty");
  fs::create_directories(dir);
  std::ofstream(dir / "esc.db").flush();   // created, then killed before anything was written
  expect_refused_untouched(dir, "nothing was stored to resume");
  const Outcome run = cli_test::esc("run " + tiny() + " --generations 2 --out " + dir.string());
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_GT(fs::file_size(dir / "esc.db"), 0U);
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
  // A directory that holds results is still never overwritten.
  const Outcome again = cli_test::esc("run " + tiny() + " --generations 2 --out " + dir.string());
  EXPECT_EQ(again.status, 1) << again.output;
  EXPECT_NE(again.output.find("already exists"), std::string::npos) << again.output;
}

// Killed while its dependencies ran: the directory holds deps/ alone. Resuming says how to
// go on (run the script into it again, which reuses deps/), and that run is accepted.
TEST(Integrity, StoppedInItsDependenciesSaysHowToGoOn) {
  const fs::path dir = scratch("integrity-deps-only");
  fs::create_directories(dir / "deps");
  std::ofstream(dir / "deps" / "kept").flush();
  const std::string said = expect_refused_untouched(dir, "holds only its dependencies (deps/)");
  EXPECT_NE(said.find("start it again with `esc run FILE --out " + dir.string()), std::string::npos) << said;
  const Outcome run = cli_test::esc("run " + tiny() + " --generations 2 --out " + dir.string());
  EXPECT_EQ(run.status, 0) << run.output;
  EXPECT_TRUE(fs::exists(dir / "deps" / "kept"));
}

// A run that has just started into a directory (its esc.db still empty) holds it: another
// `esc run --out` there is refused instead of deleting its files, and so is a resume; once
// it ends (here: the lock this test holds is released), the directory can be reused.
TEST(Integrity, ADirectoryInUseIsNeitherReusedNorResumed) {
  const fs::path dir = scratch("integrity-in-use");
  fs::create_directories(dir / "sources");
  std::ofstream(dir / "esc.db").flush();
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const auto before = contents(dir);
  Outcome o = cli_test::esc("run " + tiny() + " --generations 2 --out " + dir.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("is in use by another esc process"), std::string::npos) << o.output;
  o = cli_test::esc("run --resume " + dir.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("is in use by another esc process"), std::string::npos) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << o.output;
  EXPECT_EQ(contents(dir), before);
  EXPECT_TRUE(fs::exists(dir / "sources"));
  ::close(fd);
  o = cli_test::esc("run " + tiny() + " --generations 2 --out " + dir.string());
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
}

// A bit flipped in a killed run's log (esc.db-wal): SQLite would show the commit before it as
// the last. Export, report and replay say what is lost in one line and go on; the resume
// says it, runs the lost generations again and ends as a run never stopped.
TEST(Integrity, DamagedLogIsSaidAndResumedAsUninterrupted) {
  const fs::path killed = scratch("integrity-log");
  ASSERT_NO_FATAL_FAILURE(run_killed_halfway(tiny(), killed, 20, 400));
  const fs::path wal = killed / "esc.db-wal";
  std::string log = bytes_of(wal);
  constexpr std::size_t kFrame = 24 + 4096;
  ASSERT_GT(log.size(), 32 + 10 * kFrame);
  const std::size_t at = 32 + ((log.size() - 32) / kFrame / 2) * kFrame + 24 + 1000;   // a page mid-log
  log[at] = static_cast<char>(log[at] ^ 0x08);
  std::ofstream(wal, std::ios::binary | std::ios::trunc) << log;
  const std::string said = "esc.db-wal holds ";
  const std::string lost = " frames past its last valid commit (a damaged write-ahead log)";

  Outcome o = cli_test::esc("export " + killed.string() + " --format csv --out " + (killed.parent_path() / "log.csv").string());
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(o.output.rfind("esc: " + (killed / said).string(), 0), 0U) << o.output;
  EXPECT_NE(o.output.find(lost + ": the generations they held are not read; `esc run --resume " + killed.string() +
                          "` runs them again\n"),
            std::string::npos) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 2) << o.output;   // and "wrote"
  o = cli_test::esc("report " + killed.string() + " --out " + (killed.parent_path() / "log-report" / "r.html").string());
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find(lost), std::string::npos) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 2) << o.output;

  o = cli_test::esc("replay " + killed.string() + " --out " + (killed.parent_path() / "log-replay").string());
  EXPECT_NE(o.output.find(lost), std::string::npos) << o.output;   // (no run has finished to replay)
  EXPECT_LE(std::count(o.output.begin(), o.output.end(), '\n'), 3) << o.output;

  o = cli_test::esc("run --resume " + killed.string());
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(o.output.rfind("esc: " + (killed / said).string(), 0), 0U) << o.output;
  EXPECT_NE(o.output.find(lost + ": the generations they held are run again\n"), std::string::npos) << o.output;
  const fs::path whole = scratch("integrity-log-whole");
  ASSERT_EQ(cli_test::esc("run " + tiny() + " --generations 100 --seed 5 --threads 1 --out " + whole.string()).status, 0);
  expect_same_summary(killed, whole);
  o = cli_test::esc("export " + killed.string() + " --format csv --out " + (killed.parent_path() / "log.csv").string());
  EXPECT_EQ(o.output.find(lost), std::string::npos) << o.output;
}

// A database damaged in SQLite's own pages (cut short at several sizes, its free list lost:
// a "Page N is never used" for every free page) is refused by resume, export and report in
// one line; SQLite's problems beyond the first are listed in the file the line names.
TEST(Integrity, DamagedDatabaseIsRefusedInOneLine) {
  const fs::path finished = scratch("integrity-pages");
  ASSERT_EQ(cli_test::esc("run " + tiny() + " --generations 30 --out " + finished.string()).status, 0);
  const std::string db = bytes_of(finished / "esc.db");
  const auto refused_in_one_line = [&](const std::string& damaged, const std::string& why) {
    const fs::path dir = scratch("integrity-pages-damaged");
    fs::copy(finished, dir, fs::copy_options::recursive);
    std::ofstream(dir / "esc.db", std::ios::binary | std::ios::trunc) << damaged;
    const std::string said = expect_refused_untouched(dir, why);
    for (const std::string& command : {"export " + dir.string(), "report " + dir.string()}) {
      const Outcome o = cli_test::esc(command);
      EXPECT_EQ(o.status, 1) << command << o.output;
      EXPECT_NE(o.output.find(why), std::string::npos) << command << o.output;
      EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << command << o.output;
    }
    return said;
  };
  for (const std::size_t size : {db.size() / 4, db.size() / 2, db.size() * 3 / 4, db.size() - 4096 - 100})
    refused_in_one_line(db.substr(0, size), (finished.parent_path() / "integrity-pages-damaged" / "esc.db").string());
  std::string free_list_lost = db;
  const auto free_pages = static_cast<unsigned char>(db[39]);   // the free list's count, big-endian
  ASSERT_GE(free_pages, 2) << "no free pages to lose";
  std::fill(free_list_lost.begin() + 32, free_list_lost.begin() + 40, '\0');
  const std::string said = refused_in_one_line(free_list_lost, " is never used (");
  const std::size_t from = said.find(" listed in ") + 11;
  const std::string listing = said.substr(from, said.find(")\n", from) - from);
  const std::string listed = bytes_of(listing);
  EXPECT_EQ(std::count(listed.begin(), listed.end(), '\n'), free_pages + 1) << listed;   // and SQLite's heading
  fs::remove(listing);
}

}  // namespace
