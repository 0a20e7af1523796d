// Exit statuses exactly as the README states, one test per kind of failure: 0 success, 1 bad
// input (script, file, setting value, impossible parameter), 2 bad command line (unknown
// command or option, a malformed option value); and seeds that come back exactly.
#include <algorithm>
#include <limits>
#include <string>

#include <gtest/gtest.h>

#include "tests/cli/esc_process.hpp"

namespace {

using namespace cli_test;

const std::string kShort = " --runs 1 --generations 1 --set epochs=1 --set steps=5 --out ";

TEST(ExitCodes, ZeroForSuccess) {
  EXPECT_EQ(esc("check " + tiny()).status, 0);
  const Outcome o = esc("run " + tiny() + kShort + scratch("exit-ok").string());
  EXPECT_EQ(o.status, 0) << o.output;
}

TEST(ExitCodes, OneForABadScript) {
  const Outcome o = esc(std::string("check ") + ESC_SOURCE_DIR + "/tests/bad/unterminated_comment.esc");
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("unterminated comment"), std::string::npos) << o.output;
}

TEST(ExitCodes, OneForAMissingFile) {
  EXPECT_EQ(esc("check /nonexistent/x.esc").status, 1);
  EXPECT_EQ(esc("report /nonexistent/dir").status, 1);
}

TEST(ExitCodes, OneForARefusedSettingValue) {
  Outcome o = esc("run " + tiny() + " --set epochs=0 --out " + scratch("exit-bad-value").string());
  EXPECT_EQ(o.status, 1) << o.output;
  o = esc("run " + tiny() + " --set bounds=[-1e308,1e308] --out " + scratch("exit-bad-bounds").string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("bounds must lie within [-1000000, 1000000]"), std::string::npos) << o.output;
  o = esc("run " + tiny() + " --set seed=-1 --out " + scratch("exit-bad-seed-set").string());
  EXPECT_EQ(o.status, 1) << o.output;
  o = esc("run " + tiny() + " --set epochs=1e400 --out " + scratch("exit-bad-huge").string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("`1e400`: the number is out of range"), std::string::npos) << o.output;
}

TEST(ExitCodes, OneForAnImpossibleSizeBeforeAnythingIsMade) {
  const fs::path out = scratch("exit-lambda");
  const Outcome o = esc("run " + tiny() + " --set lambda=1000000000 --out " + out.string());
  EXPECT_EQ(o.status, 1) << o.output;
  EXPECT_NE(o.output.find("needs about"), std::string::npos) << o.output;
  EXPECT_NE(o.output.find("of memory at once (the ES's 1000000000 offspring of "), std::string::npos) << o.output;
  EXPECT_NE(o.output.find(": lower `lambda`\n"), std::string::npos) << o.output;
  EXPECT_EQ(std::count(o.output.begin(), o.output.end(), '\n'), 1) << "one line:\n" << o.output;
  EXPECT_FALSE(fs::exists(out)) << "refused before the run directory is made";
}

TEST(ExitCodes, TwoForAnUnknownCommandOrOption) {
  EXPECT_EQ(esc("runn " + tiny()).status, 2);
  EXPECT_EQ(esc("run " + tiny() + " --bogus").status, 2);
}

TEST(ExitCodes, TwoForAMalformedSet) {
  const Outcome o = esc("run " + tiny() + " --set epochs --out " + scratch("exit-set").string());
  EXPECT_EQ(o.status, 2) << o.output;
  EXPECT_NE(o.output.find("--set expects KEY=VALUE, got `epochs`"), std::string::npos) << o.output;
}

TEST(ExitCodes, EveryCommandLineRefusalStartsWithEscError) {
  const std::vector<std::string> refused = {"run " + tiny() + " --runs 0", "run --generations", "--bogus", "runn",
                                            "run " + tiny() + " --bogus", "run " + tiny() + " --set epochs"};
  for (const std::string& args : refused) {
    const Outcome o = esc(args);
    EXPECT_EQ(o.status, 2) << args << "\n" << o.output;
    EXPECT_EQ(o.output.rfind("esc: error: ", 0), 0U) << args << "\n" << o.output;
    EXPECT_NE(o.output.find("--help"), std::string::npos) << args << "\n" << o.output;
  }
}

TEST(ExitCodes, TwoForASeedThatIsNotOne) {
  for (const char* seed : {"-1", "18446744073709551616", "1.5", "0x10"}) {
    const Outcome o = esc("run " + tiny() + " --seed " + seed + " --out " + scratch("exit-seed").string());
    EXPECT_EQ(o.status, 2) << seed << "\n" << o.output;
    EXPECT_NE(o.output.find("a seed is a whole number from 0 to 18446744073709551615"), std::string::npos)
        << o.output;
  }
}

TEST(Seeds, AboveTwoToThe53RunAsThemselvesAndReadBackExactly) {
  const fs::path out = scratch("seed-exact");
  const Outcome o = esc("run " + tiny() + " --seed 9007199254740993" + kShort + out.string());
  ASSERT_EQ(o.status, 0) << o.output;
  EXPECT_EQ(read_json(out / "summary.json")["seed"], "9007199254740993");
  const auto settings = read_json(out / "settings.json");
  EXPECT_EQ(settings["seed"], "9007199254740993");
  EXPECT_EQ(settings["settings"]["seed"], "9007199254740993");
  const auto best = read_json(out / "CC" / "run-01.best.json");
  EXPECT_TRUE(best["seed"].is_string());
  EXPECT_TRUE(best["evaluation_seed"].is_string());
  // The other seed differs in the last digit only, so its runs differ: it was not rounded.
  const fs::path other = scratch("seed-exact-other");
  ASSERT_EQ(esc("run " + tiny() + " --seed 9007199254740992" + kShort + other.string()).status, 0);
  EXPECT_NE(read_json(out / "summary.json")["controllers"]["CC"]["runs"][0]["seed"],
            read_json(other / "summary.json")["controllers"]["CC"]["runs"][0]["seed"]);
  // The largest seed, through the database and the export.
  const fs::path top = scratch("seed-top");
  ASSERT_EQ(esc("run " + tiny() + " --seed 18446744073709551615" + kShort + top.string()).status, 0);
  EXPECT_EQ(read_json(top / "summary.json")["seed"], std::to_string(std::numeric_limits<std::uint64_t>::max()));
  const fs::path exported = top / "export.json";
  ASSERT_EQ(esc("export " + top.string() + " --format json --out " + exported.string()).status, 0);
  EXPECT_EQ(read_json(exported)["experiments"][0]["seed"], "18446744073709551615");
}

}  // namespace
