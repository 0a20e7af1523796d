// Numbers and names at the edge: seeds read exactly, ES and GP limits that keep the
// arithmetic finite, hints that do not overflow, long names shortened in messages, and the
// "expected" word lists complete.
#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <map>
#include <regex>
#include <sstream>

#include "compiler/text.hpp"
#include "helpers.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::paper;
using test::rendered;
using test::source_dir;

std::string script_with(const std::string& experiment_items) {
  return "arena a { size 1m x 1m }\nfitness f { step: speed }\ncontroller c = mlp(ir[0..7] -> wheels)\n"
         "experiment e { arena a  fitness f  compare c  " + experiment_items + " }\n";
}

TEST(Seeds, AreReadExactlyFromTheirDigits) {
  auto r = compile_source(script_with("seed 18446744073709551615"), "s.esc", options());
  ASSERT_TRUE(r.ok()) << rendered(r);
  EXPECT_EQ(r.experiments[0].seed, std::numeric_limits<std::uint64_t>::max());
  r = compile_source(script_with("seed 18446744073709551616"), "s.esc", options());
  EXPECT_FALSE(r.ok());
  EXPECT_NE(rendered(r).find("`seed` is a whole number from 0 to 18446744073709551615"), std::string::npos);

  eval::ExperimentSpec x = paper();
  EXPECT_EQ(apply_setting(x, "seed", "9007199254740993"), "");
  EXPECT_EQ(x.seed, 9007199254740993u);   // a double would give ...992
  EXPECT_EQ(x.resolved_settings.at("seed"), "9007199254740993");
  EXPECT_EQ(apply_setting(x, "seed", "1e3"), "");   // accepted before: read as before
  EXPECT_EQ(x.seed, 1000u);
  for (const char* bad : {"-1", "18446744073709551616", "1.5", "1e30", "2cm"})
    EXPECT_NE(apply_setting(x, "seed", bad), "") << bad;
  EXPECT_EQ(x.seed, 1000u);
}

TEST(EsLimits, BoundsSigmaAndMinSigmaThatCouldOverflowAreRefused) {
  eval::ExperimentSpec x = paper();
  std::string m = apply_setting(x, "bounds", "[-1e308, 1e308]");
  EXPECT_NE(m.find("bounds must lie within [-1000000, 1000000], found [-1e+308, 1e+308]"), std::string::npos) << m;
  EXPECT_EQ(apply_setting(x, "bounds", "[-1e6, 1e6]"), "");
  m = apply_setting(x, "sigma", "1e300");
  EXPECT_NE(m.find("`sigma` must be at most 1000, found 1e+300"), std::string::npos) << m;
  EXPECT_EQ(apply_setting(x, "sigma", "1000"), "");
  EXPECT_EQ(apply_setting(x, "bounds", "[-1, 1]"), "");
  m = apply_setting(x, "min_sigma", "3");
  EXPECT_NE(m.find("`min_sigma` (3) is wider than the bounds (HI - LO = 2)"), std::string::npos) << m;
  m = apply_setting(x, "gp.erc_sigma", "1e9");
  EXPECT_NE(m.find("`erc_sigma` must be at most 1000"), std::string::npos) << m;
}

TEST(RuleHints, TheSubstepsHintNeverOverflows) {
  const auto r = compile_source(
      "import \"lib/khepera.esc\"\nrobot fast = khepera { max_speed 1e300 m/s }\n" + script_with("robot fast"), "s.esc", options());
  const std::string out = rendered(r);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(out.find("no `substeps` up to 1000 is enough"), std::string::npos) << out;
  EXPECT_EQ(out.find("use `substeps -"), std::string::npos) << out;
}

TEST(LongNames, AreShortenedToTheirEndsAndLength) {
  const std::string name(3'000'000, 'q');
  const std::string m = shorten_names("unknown arena `" + name + "`; did you mean `short`?");
  EXPECT_LT(m.size(), 200u) << m;
  EXPECT_NE(m.find("` (3000000 characters); did you mean `short`?"), std::string::npos) << m;
  EXPECT_EQ(shorten_names("`abc` and `" + std::string(64, 'x') + "`"), "`abc` and `" + std::string(64, 'x') + "`");
  // Cut on character boundaries: 100 two-byte characters stay valid UTF-8.
  std::string accents;
  for (int i = 0; i < 100; ++i) accents += "\xC3\xA9";
  const std::string cut = shorten_names("`" + accents + "`");
  EXPECT_NE(cut.find("(100 characters)"), std::string::npos) << cut;
  EXPECT_EQ(clean_utf8(cut).invalid.size(), 0u) << cut;
  // A command to paste keeps its long path: cut, it would name no directory.
  const std::string resume = "help: `esc run --resume /" + std::string(120, 'd') + "/run` continues it";
  EXPECT_EQ(shorten_names(resume), resume);

  const auto r = compile_source(script_with("") + "experiment g { arena " + name + " }\n", "s.esc", options());
  const std::string out = rendered(r);
  EXPECT_LT(out.size(), 4000u) << "a 3 MB name is never echoed whole";
  EXPECT_NE(out.find("(3000000 characters)"), std::string::npos);
}

// The first keyword of every alternative of the grammar's `decl` rule, read from Esc.g4: the
// declarations a script may start with.
std::vector<std::string> declaration_keywords() {
  std::ifstream in(source_dir() / "grammar/Esc.g4");
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string g = ss.str();
  std::map<std::string, std::string> literal;   // IMPORT -> import
  const std::regex token(R"(\n([A-Z_]+) : '([a-z_]+)' ;)");
  for (auto it = std::sregex_iterator(g.begin(), g.end(), token); it != std::sregex_iterator(); ++it)
    literal[(*it)[1]] = (*it)[2];
  const std::size_t decl = g.find("\ndecl\n");
  const std::string body = g.substr(decl, g.find(';', decl) - decl);
  std::vector<std::string> words;
  const std::regex alternative(R"(\b([a-z]+Decl)\b)");
  for (auto it = std::sregex_iterator(body.begin(), body.end(), alternative); it != std::sregex_iterator(); ++it) {
    // Appended, not `"\n" + ... + ...`: GCC 12 warns (-Wrestrict) on that form.
    std::string pattern = "\n";
    pattern += (*it)[1].str();
    pattern += R"(\s*:\s*([A-Z_]+))";
    const std::regex first(pattern);
    std::smatch m;
    if (std::regex_search(g, m, first)) words.push_back(literal.at(m[1]));
  }
  return words;
}

TEST(ExpectedWords, EveryDeclarationKeywordOfTheGrammarIsListed) {
  const std::vector<std::string> words = declaration_keywords();
  ASSERT_GE(words.size(), 9u);
  const auto r = compile_source("garbage\n", "s.esc", options());
  const std::string out = rendered(r);
  EXPECT_NE(out.find("expected a declaration ("), std::string::npos) << out;
  for (const std::string& w : words) EXPECT_NE(out.find("`" + w + "`"), std::string::npos) << w << "\n" << out;
}

TEST(ExpectedWords, ExperimentAndArenaItemsAreListedWhole) {
  std::string out = rendered(compile_source("experiment e { blah }\n", "s.esc", options()));
  for (const char* w : {"arena", "robot", "fitness", "epochs", "steps", "evolve", "runs", "seed", "compare", "start",
                        "evaluate"})
    EXPECT_NE(out.find(std::string("`") + w + "`"), std::string::npos) << w << "\n" << out;
  out = rendered(compile_source("arena a { blah }\n", "s.esc", options()));
  for (const char* w : {"size", "box", "cylinder", "block", "start", "light", "zone", "sweep_cell", "reach_radius"})
    EXPECT_NE(out.find(std::string("`") + w + "`"), std::string::npos) << w << "\n" << out;
}

}  // namespace
}  // namespace esc::compiler
