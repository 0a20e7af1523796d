// Results written by the esc before optimizers became components (results schema 5: the ES's
// parents and GP's trees each in a table of their own), kept as tests/store/data/schema5:
// they still export as they did (with the algorithm of each row added), report, and carry on
// to the run the current esc makes from the start (README there says how it was made).
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"
#include "tests/cli/results_support.hpp"

namespace {

using namespace cli_test;

const fs::path kData = fs::path(ESC_SOURCE_DIR) / "tests" / "store" / "data";

// The fixture, copied: a test never writes into the source tree.
fs::path copy_of_schema5(const std::string& name) {
  const fs::path dir = scratch(name);
  fs::copy(kData / "schema5", dir, fs::copy_options::recursive);
  return dir;
}

// The first 14 fields of each CSV line: the export's columns up to the directory (which
// depends on where it was read), no field holding a comma.
std::string before_directory(const std::string& csv) {
  std::stringstream in(csv);
  std::string out;
  for (std::string line; std::getline(in, line);) {
    std::size_t at = 0;
    for (int i = 0; i < 14 && at != std::string::npos; ++i) at = line.find(',', at + 1);
    out += line.substr(0, at) + "\n";
  }
  return out;
}

TEST(OlderResults, ASchema5DirectoryExportsAsItDidAndReports) {
  const fs::path dir = copy_of_schema5("schema5-read");
  const Outcome exported = esc("export " + dir.string() + " --format csv");
  ASSERT_EQ(exported.status, 0) << exported.output;
  // As it did, then the algorithm: the ES for the network, GP for the tree.
  EXPECT_EQ(before_directory(exported.output), before_directory(slurp(kData / "schema5-export.csv")));
  EXPECT_NE(exported.output.find(",SC_8_14_6,1,"), std::string::npos);
  std::stringstream rows(exported.output);
  std::string line;
  std::getline(rows, line);
  EXPECT_TRUE(line.ends_with(",directory,algorithm")) << line;
  while (std::getline(rows, line))
    EXPECT_TRUE(line.ends_with(line.find(",GP_SC,") != std::string::npos ? ",gp" : ",es")) << line;
  const Outcome report = esc("report " + dir.string() + " --out " + (dir / "report" / "report.html").string());
  EXPECT_EQ(report.status, 0) << report.output;
  EXPECT_TRUE(fs::exists(dir / "report" / "report.html"));
}

// Its ES and GP runs resume from the states schema 5 kept, and end as a fresh run asked for
// the longer run.
TEST(OlderResults, ASchema5DirectoryCarriesOnToTheFreshLongerRun) {
  const fs::path dir = copy_of_schema5("schema5-carry");
  // The directory names the script where it was made (another machine's source tree): its
  // place here is given, as esc advises when that path is gone.
  const std::string script = std::string(ESC_SOURCE_DIR) + "/experiments/gp/nn_vs_gp.esc";
  const Outcome on = esc("run " + script + " --resume " + dir.string() + " --generations 4");
  ASSERT_EQ(on.status, 0) << on.output;
  const fs::path fresh = scratch("schema5-fresh");
  const Outcome four = esc("run " + script + " --runs 2 --generations 4 --set epochs=2 --set steps=150 "
                           "--set mu=4 --set lambda=12 --set gp.population=12 --seed 5 --out " + fresh.string());
  ASSERT_EQ(four.status, 0) << four.output;
  expect_same_results(dir, fresh, {"SC_8_14_6", "GP_SC"}, 2);
}

}  // namespace
