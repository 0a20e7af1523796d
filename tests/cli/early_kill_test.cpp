// A run killed in its first milliseconds leaves one of a few states; each is either resumed or
// accepted by `esc run --out` as holding nothing, never stuck between the two (the kills
// themselves: early_kill.sh). And what a run stores once it has results is never taken for
// nothing: a finished run whose esc.db was emptied keeps every file, `esc run --out` refuses
// it naming one, and a resume does not call it a run stopped before it started.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "runtime/store/sqlite.hpp"
#include "tests/cli/esc_process.hpp"

namespace {

using namespace cli_test;
namespace sql = ::esc::store::sql;

const std::string kTwoGenerations = " --generations 2 --runs 1 --threads 1 --out ";

void expect_accepted(const fs::path& dir) {
  const Outcome o = cli_test::esc("run " + tiny() + kTwoGenerations + dir.string());
  EXPECT_EQ(o.status, 0) << o.output;
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
}

// What an esc before this one left when killed between committing the application id and
// schema version of its database and committing its tables.
void marks_without_tables(const fs::path& dir) {
  fs::create_directories(dir / "sources");
  sql::Database db(dir / "esc.db", sql::Database::Mode::Create);
  db.exec("PRAGMA journal_mode=WAL; PRAGMA application_id=1163084593; PRAGMA user_version=8;");
}

TEST(EarlyKill, AnEmptySourcesDirectoryAloneHoldsNothing) {
  const fs::path dir = scratch("early-sources");
  fs::create_directories(dir / "sources");
  expect_accepted(dir);
}

TEST(EarlyKill, AnEscDatabaseWithoutTablesHoldsNothing) {
  const fs::path dir = scratch("early-marks");
  marks_without_tables(dir);
  const Outcome resume = cli_test::esc("run --resume " + dir.string());
  EXPECT_EQ(resume.status, 1) << resume.output;
  EXPECT_NE(resume.output.find("nothing was stored to resume"), std::string::npos) << resume.output;
  EXPECT_EQ(resume.output.find("damaged"), std::string::npos) << resume.output;
  const Outcome read = cli_test::esc("export " + dir.string());
  EXPECT_EQ(read.output.find("damaged"), std::string::npos) << read.output;
  expect_accepted(dir);
}

// Killed between the CSV line of generation 0 and its commit: the database holds the
// experiment and no generation, the directory its sources, settings, an empty summary and
// that one CSV line. Nothing is lost by running into it again.
TEST(EarlyKill, TheLineOfAnUncommittedGenerationHoldsNothing) {
  const fs::path dir = scratch("early-csv");
  ASSERT_EQ(cli_test::esc("run " + tiny() + kTwoGenerations + dir.string()).status, 0);
  {
    sql::Database db(dir / "esc.db", sql::Database::Mode::ReadWrite);
    db.exec("DELETE FROM generations; DELETE FROM runs;");
  }
  for (const char* c : {"CC", "SC"}) {
    fs::remove_all(dir / c);
    fs::create_directories(dir / c);
    std::ofstream(dir / c / "run-01.csv") << "generation,best,mean,sd,evaluations,steps,seconds\n0,1,1,0,20,4800,0.1\n";
  }
  std::ofstream(dir / "summary.json") << R"({"experiment": "tiny", "seed": "3", "controllers": {}})" << "\n";
  const Outcome resume = cli_test::esc("run --resume " + dir.string());
  EXPECT_EQ(resume.status, 1) << resume.output;
  EXPECT_NE(resume.output.find("holds no committed generation"), std::string::npos) << resume.output;
  expect_accepted(dir);
  EXPECT_TRUE(fs::exists(dir / "CC" / "run-01.best.json"));
}

// A finished run whose esc.db was emptied: not a run stopped before it started.
TEST(EarlyKill, AFinishedRunsRemainsAreNeverDeleted) {
  const fs::path dir = scratch("early-truncated");
  ASSERT_EQ(cli_test::esc("run " + tiny() + kTwoGenerations + dir.string()).status, 0);
  fs::resize_file(dir / "esc.db", 0);
  fs::remove(dir / "esc.db-wal");
  const std::string genome = slurp(dir / "CC" / "run-01.best.json");

  const Outcome resume = cli_test::esc("run --resume " + dir.string());
  EXPECT_EQ(resume.status, 1) << resume.output;
  EXPECT_EQ(resume.output.find("stopped before it started"), std::string::npos) << resume.output;
  EXPECT_NE(resume.output.find("emptied or replaced"), std::string::npos) << resume.output;

  const Outcome again = cli_test::esc("run " + tiny() + kTwoGenerations + dir.string());
  EXPECT_EQ(again.status, 1) << again.output;
  EXPECT_NE(again.output.find("already exists and is not empty (it holds "), std::string::npos) << again.output;
  EXPECT_EQ(slurp(dir / "CC" / "run-01.best.json"), genome);
  EXPECT_TRUE(fs::exists(dir / "summary.json"));
  EXPECT_TRUE(fs::exists(dir / "SC" / "run-01.csv"));
  EXPECT_EQ(fs::file_size(dir / "esc.db"), 0U);

  // A summary that holds a run is kept alike, the genomes gone.
  for (const char* c : {"CC", "SC"}) fs::remove_all(dir / c);
  const Outcome summary_only = cli_test::esc("run " + tiny() + kTwoGenerations + dir.string());
  EXPECT_EQ(summary_only.status, 1) << summary_only.output;
  EXPECT_NE(summary_only.output.find("(it holds summary.json)"), std::string::npos) << summary_only.output;
  // So is a file of the user's beside an esc.db that holds nothing.
  fs::remove(dir / "summary.json");
  std::ofstream(dir / "notes.txt") << "mine\n";
  const Outcome notes = cli_test::esc("run " + tiny() + kTwoGenerations + dir.string());
  EXPECT_EQ(notes.status, 1) << notes.output;
  EXPECT_NE(notes.output.find("(it holds notes.txt)"), std::string::npos) << notes.output;
  EXPECT_TRUE(fs::exists(dir / "notes.txt"));
}

}  // namespace
