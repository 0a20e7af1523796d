// The command line's first-hour frictions: --set takes exactly one KEY=VALUE, unknown
// commands and options get a suggestion, the live progress line fits the terminal, runs
// and generations are numbered alike in every output, esc bench colours only a terminal,
// and --version says what this esc is.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"

namespace {

using namespace cli_test;

std::string settings_epochs(const fs::path& out) {
  return read_json(out / "settings.json")["settings"]["epochs"].get<std::string>();
}

TEST(CommandLine, SetTakesOneKeyValueAndNeverTheFile) {
  const std::string common = " --runs 1 --generations 1 --out ";
  // FILE after --set, before it, and between two of them.
  const fs::path a = scratch("set-before-file");
  Outcome o = esc("run --set epochs=1 " + tiny() + common + a.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(settings_epochs(a), "1");
  const fs::path b = scratch("set-after-file");
  o = esc("run " + tiny() + " --set epochs=2" + common + b.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(settings_epochs(b), "2");
  const fs::path c = scratch("set-around-file");
  o = esc("run --set epochs=1 " + tiny() + " --set steps=20" + common + c.string());
  ASSERT_EQ(o.status, 0) << o.output;
  const auto settings = read_json(c / "settings.json")["settings"];
  EXPECT_EQ(settings["epochs"], "1");
  EXPECT_EQ(settings["steps"], "20");
  // Two values after one --set: the second is not a setting, and says so.
  o = esc("run --set epochs=1 steps=20 " + tiny() + common + scratch("set-two").string());
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("takes no further argument"), std::string::npos) << o.output;
}

TEST(CommandLine, UnknownCommandGetsDidYouMean) {
  const Outcome o = esc("runn " + tiny());
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("unknown command `runn`"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("did you mean `run`?"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("A subcommand is required"), std::string::npos) << o.output;
}

// The README shows an error as esc prints it, from a script it ships: the sample follows
// whatever the compiler's messages become.
TEST(CommandLine, TheReadmesSampleErrorIsWhatEscPrints) {
  const std::string readme = slurp(fs::path(ESC_SOURCE_DIR) / "README.md");
  const std::string command = "$ esc check examples/typo.esc\n";
  const std::size_t begin = readme.find(command);
  ASSERT_NE(begin, std::string::npos) << "the README has no sample error";
  const std::size_t end = readme.find("```", begin);
  ASSERT_NE(end, std::string::npos);
  const Outcome o =
      shell("cd " + std::string(ESC_SOURCE_DIR) + " && " + std::string(ESC_BINARY) + " check examples/typo.esc");
  EXPECT_EQ(o.status, 1);
  EXPECT_EQ(o.output, readme.substr(begin + command.size(), end - begin - command.size()));
}

TEST(CommandLine, MisspelledOptionsGetDidYouMean) {
  Outcome o = esc("run " + tiny() + " --generatons 3");
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("`esc run` has no option `--generatons`"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("did you mean `--generations`?"), std::string::npos) << o.output;
  o = esc("--verison");
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("did you mean `--version`?"), std::string::npos) << o.output;
  o = esc("replay " + scratch("nowhere").string() + " --epoch 1");
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("did you mean `--epochs`?"), std::string::npos) << o.output;
}

TEST(CommandLine, VersionSaysCommitOptionalPartsAndLibrary) {
  const Outcome o = esc("--version");
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("esc 0."), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("(commit "), std::string::npos) << o.output;
  EXPECT_NE(o.output.find(ESC_TEST_WITH_MPI ? "MPI yes" : "MPI no"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find(ESC_TEST_WITH_BENCHMARK ? "Google Benchmark (esc bench) yes" : "Google Benchmark (esc bench) no"),
            std::string::npos)
      << o.output;
  // The build tree's library is staged beside the binary, at the installed layout's place.
  const std::string marker = "standard library: ";
  const auto at = o.output.find(marker);
  ASSERT_NE(at, std::string::npos) << o.output;
  const fs::path library = o.output.substr(at + marker.size(), o.output.find('\n', at) - at - marker.size());
  EXPECT_EQ(library, (fs::path(ESC_BINARY).parent_path() / "../share/esc/experiments").lexically_normal());
  EXPECT_TRUE(fs::exists(library / "lib" / "khepera.esc")) << library;
}

// Every piece of a terminal's output between carriage returns and newlines, escape
// sequences removed.
std::vector<std::string> screen_lines(const std::string& output) {
  std::vector<std::string> lines(1);
  for (std::size_t i = 0; i < output.size(); ++i) {
    const char c = output[i];
    if (c == '\r' || c == '\n') {
      lines.emplace_back();
    } else if (c == '\033' && i + 1 < output.size() && output[i + 1] == '[') {
      for (i += 2; i < output.size() && (output[i] < 0x40 || output[i] > 0x7E); ++i) {
      }
    } else {
      lines.back() += c;
    }
  }
  return lines;
}

std::size_t code_points(const std::string& s) {
  std::size_t n = 0;
  for (const char c : s) n += (static_cast<unsigned char>(c) & 0xC0U) != 0x80U;
  return n;
}

TEST(CommandLine, LiveBarFitsEightyColumnsOfAPseudoTerminal) {
  if (shell("command -v script").status != 0) GTEST_SKIP() << "`script` (util-linux) is not installed";
  const fs::path out = scratch("bar");
  // `script` runs esc on a pseudo-terminal of 80 columns: the live line is used.
  const std::string inner = "stty cols 80 rows 24; COLUMNS=80 " + std::string(ESC_BINARY) + " run " + tiny() +
                            " --generations 4 --threads 1 --out " + out.string();
  const Outcome o = shell("script -qec '" + inner + "' /dev/null");
  ASSERT_EQ(o.status, 0) << o.output;
  ASSERT_NE(o.output.find("\033[K"), std::string::npos) << "not drawn live: " << o.output;
  // What is drawn while the campaign runs (the lines before and after, printed once, may
  // be wider: they hold paths and the final table).
  const std::size_t begin = o.output.find("\r\033[K");
  const std::size_t end = o.output.find("tiny: 2 runs");
  ASSERT_LT(begin, end) << o.output;
  const std::string progress = o.output.substr(begin, end - begin);
  std::size_t widest_bar_line = 0;
  for (const std::string& line : screen_lines(progress)) {
    EXPECT_LE(code_points(line), 79U) << "wraps at 80 columns: " << line;
    if (line.find("gen ") != std::string::npos && line.find("%") != std::string::npos)
      widest_bar_line = std::max(widest_bar_line, code_points(line));
  }
  // The progress line is there and uses the room (its full form would take more than 80).
  EXPECT_GE(widest_bar_line, 60U) << o.output;
}

TEST(CommandLine, ConsoleCountsGenerationsTablesIndexThemFromZero) {
  const fs::path out = scratch("numbering");
  const Outcome o = esc("run " + tiny() + " --generations 3 --set epochs=1 --out " + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  // Console (piped: one line per generation): generations counted as the end message counts
  // them, 1 to 3 of "3 generations".
  EXPECT_NE(o.output.find("CC       run  1/2  gen    1/3"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("CC       run  2/2  gen    3/3"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find("gen    0/"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("2 runs x 3 generations"), std::string::npos) << o.output;
  // summary.json and the genome files: runs from 1, as in the file names.
  const auto s = read_json(out / "summary.json");
  EXPECT_EQ(s["controllers"]["CC"]["runs"][0]["run"], 1);
  EXPECT_EQ(s["controllers"]["CC"]["runs"][1]["run"], 2);
  EXPECT_EQ(read_json(out / "CC" / "run-02.best.json")["run"], 2);
  // Per-run CSV and the export: generations from 0, runs from 1.
  std::ifstream csv(out / "CC" / "run-01.csv");
  std::string header, first;
  std::getline(csv, header);
  std::getline(csv, first);
  EXPECT_EQ(first.rfind("0,", 0), 0U) << first;
  const Outcome exported = esc("export " + out.string() + " --format csv");
  ASSERT_EQ(exported.status, 0) << exported.output;
  EXPECT_NE(exported.output.find("\ntiny,CC,1,"), std::string::npos) << exported.output;
  EXPECT_EQ(exported.output.find("\ntiny,CC,0,"), std::string::npos) << exported.output;
  std::istringstream rows(exported.output);
  std::string row;
  std::getline(rows, row);
  std::getline(rows, row);   // experiment,controller,run,run_seed,status,generation,...
  std::vector<std::string> cells;
  std::stringstream cut(row);
  for (std::string cell; std::getline(cut, cell, ',');) cells.push_back(cell);
  ASSERT_GT(cells.size(), 5U) << row;
  EXPECT_EQ(cells[2], "1");
  EXPECT_EQ(cells[5], "0");
}

TEST(CommandLine, BenchWritesNoColourIntoAPipe) {
  const Outcome o = esc("bench --min-time 0.01 '--benchmark=--benchmark_filter=BM_GpFlat/15$'");
  if (!ESC_TEST_WITH_BENCHMARK) {
    EXPECT_EQ(o.status, 1) << o.output;
    EXPECT_NE(o.output.find("built without Google Benchmark"), std::string::npos) << o.output;
    EXPECT_NE(o.output.find("libbenchmark-dev"), std::string::npos) << o.output;
    return;
  }
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_NE(o.output.find("BM_GpFlat/15"), std::string::npos) << o.output;
  EXPECT_EQ(o.output.find('\033'), std::string::npos) << "ANSI escape in piped output: " << o.output;
}

TEST(CommandLine, AnMpiLaunchOfAnEscWithoutMpiIsRefused) {
  if (ESC_TEST_WITH_MPI) GTEST_SKIP() << "this esc is built with MPI (tests/cli/mpi_test.cpp runs it under mpirun)";
  const Outcome o = shell("OMPI_COMM_WORLD_SIZE=2 " + std::string(ESC_BINARY) + " check " + tiny());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("built without MPI"), std::string::npos) << o.output;
}

}  // namespace
