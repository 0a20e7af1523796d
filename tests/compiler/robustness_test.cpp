// No input crashes, hangs or throws; invalid input always gets a located error.
#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <sstream>

#include "helpers.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;
using test::source_dir;

bool located(const CompileResult& r) {
  for (const auto& d : r.diagnostics)
    if (d.severity == Severity::Error && d.where.line > 0 && d.where.column > 0) return true;
  return false;
}

void check(const std::string& text, const std::filesystem::path& name) {
  CompileResult r;
  ASSERT_NO_THROW(r = compile_source(text, name, options()));
  std::string out;
  ASSERT_NO_THROW(out = rendered(r));
  if (!r.ok()) {
    EXPECT_TRUE(located(r)) << out;
    EXPECT_TRUE(r.experiments.empty());
  }
}

std::string read(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(Robustness, EveryPrefixOfThePaperScript) {
  const auto path = source_dir() / "experiments/paper/obstacle_avoidance.esc";
  const std::string text = read(path);
  ASSERT_FALSE(text.empty());
  const std::size_t body = text.find("experiment obstacle_avoidance {");
  const std::size_t body_end = text.find("\n}\n", body);
  int invalid = 0;
  for (std::size_t n = 0; n <= text.size(); ++n) {
    const std::string prefix = text.substr(0, n);
    CompileResult r;
    ASSERT_NO_THROW(r = compile_source(prefix, path, options())) << n;
    if (!r.ok()) {
      ++invalid;
      ASSERT_TRUE(located(r)) << "prefix of " << n << " bytes\n" << rendered(r);
    }
    // Cut inside the experiment block: always an error.
    if (n > body + 12 && n <= body_end) {
      ASSERT_FALSE(r.ok()) << "prefix of " << n << " bytes";
    }
  }
  EXPECT_GT(invalid, 100);
}

TEST(Robustness, RandomBytes) {
  std::mt19937 rng(1234);
  for (int i = 0; i < 300; ++i) {
    std::string s(static_cast<std::size_t>(rng() % 400), '\0');
    for (char& c : s) c = static_cast<char>(rng() % 256);
    check(s, "garbage.esc");
  }
}

TEST(Robustness, RandomTokenSoup) {
  const std::vector<std::string> words = {
      "arena", "robot", "behavior", "fitness", "controller", "experiment", "import", "{", "}", "(", ")",
      "[", "]", ",", ";", ":", "=", "->", "..", "x", "steps", "step", "stop", "epoch", "when", "at", "radius",
      "size", "block", "cylinder", "start", "random", "mlp", "symbolic", "actions", "hidden", "wheels",
      "evolve", "es", "for", "generations", "compare", "if", "then", "else", "and", "or", "not", "+", "-",
      "*", "/", "^", "<", ">=", "==", "1", "60cm", "0.5", "m/s^2", "ir", "speed", "\"lib/khepera.esc\"",
      "1e999", "ms", "on", "off", "a", "b", "nolfi", "khepera", "forward", "\n"};
  std::mt19937 rng(99);
  for (int i = 0; i < 1000; ++i) {
    std::string s;
    const int n = static_cast<int>(rng() % 60);
    for (int k = 0; k < n; ++k) s += words[rng() % words.size()] + (rng() % 3 == 0 ? "" : " ");
    check(s, "soup.esc");
  }
}

TEST(Robustness, MutatedPaperScript) {
  const auto path = source_dir() / "experiments/paper/obstacle_avoidance.esc";
  const std::string text = read(path);
  std::mt19937 rng(7);
  for (int i = 0; i < 300; ++i) {
    std::string s = text;
    for (int k = 0; k < 3; ++k) {
      const std::size_t at = rng() % s.size();
      switch (rng() % 3) {
        case 0: s.erase(at, 1 + rng() % 5); break;
        case 1: {
          const std::string_view punct = "{}()[],;x-^\"@";
          s.insert(s.begin() + static_cast<std::ptrdiff_t>(at), punct[rng() % punct.size()]);
          break;
        }
        default: s[at] = static_cast<char>(rng() % 128); break;
      }
      if (s.empty()) s.push_back(' ');
    }
    check(s, path);
  }
}

TEST(Robustness, ExtremeInputs) {
  check("", "empty.esc");
  check(std::string(100000, '('), "parens.esc");
  check("fitness f { step: " + std::string(100000, '(') + "1" + std::string(100000, ')') + " }", "deep.esc");
  check("fitness f { step: " + std::string(50000, '-') + "1 }", "neg.esc");
  std::string sum = "fitness f { step: 1";
  for (int i = 0; i < 20000; ++i) sum += " + 1";
  check(sum + " }", "sum.esc");
  std::string pow = "fitness f { step: 2";
  for (int i = 0; i < 20000; ++i) pow += " ^ 2";
  check(pow + " }", "pow.esc");
  std::string ifs = "fitness f { step: ";
  for (int i = 0; i < 20000; ++i) ifs += "if speed then 1 else ";
  check(ifs + "0 }", "if.esc");
  check("experiment e { runs 1e999999 seed 99999999999999999999999 }", "huge.esc");
  check("arena a { size 1e308m x 1e308m }", "big.esc");
  check(std::string("arena \xff\xfe\x00 a { }", 16), "utf8.esc");
  check("\"unterminated", "str.esc");
  check("/* unterminated comment", "comment.esc");
  check(std::string(200000, 'a'), "long_ident.esc");

  const auto empty = compile_source("", "empty.esc", options());
  EXPECT_TRUE(empty.ok());
  EXPECT_TRUE(empty.experiments.empty());
  const auto missing = compile_file("/nonexistent/script.esc", options());
  EXPECT_FALSE(missing.ok());
  EXPECT_NE(render_all(missing.diagnostics, missing.sources).find("/nonexistent/script.esc"), std::string::npos);
}

TEST(Robustness, TheTwoContractCases) {
  const auto a = compile_source("experiment {\n", "missing_name.esc", options());
  ASSERT_FALSE(a.ok());
  const std::string ra = rendered(a);
  EXPECT_NE(ra.find("missing_name.esc:1:12: error:"), std::string::npos) << ra;
  const auto b = compile_source("controller c = mlp(ir[0..7] -> hiden 3 -> wheels)\n", "misspelled.esc", options());
  ASSERT_FALSE(b.ok());
  const std::string rb = rendered(b);
  EXPECT_NE(rb.find("misspelled.esc:1:32: error: unknown layer `hiden`; did you mean `hidden`?"), std::string::npos)
      << rb;
  EXPECT_NE(rb.find("1 error generated."), std::string::npos);
}

}  // namespace
}  // namespace esc::compiler
