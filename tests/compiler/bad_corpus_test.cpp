// Every file of tests/bad/ fails to compile with the located diagnostic named on its
// first line: `// expect: LINE:COL: error: MESSAGE SUBSTRING` (or `// expect: error: ...`
// when only the message is checked).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "helpers.hpp"

namespace esc::compiler {
namespace {

using test::options;
using test::rendered;
using test::source_dir;

std::vector<std::filesystem::path> corpus() {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(source_dir() / "tests/bad"))
    if (e.path().extension() == ".esc") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

TEST(BadCorpus, EveryFileGivesItsExpectedLocatedError) {
  const auto files = corpus();
  ASSERT_GE(files.size(), 40u);
  for (const auto& file : files) {
    std::ifstream in(file, std::ios::binary);
    std::string first;
    std::getline(in, first);
    const std::string tag = "// expect: ";
    ASSERT_EQ(first.rfind(tag, 0), 0u) << file << " has no `// expect:` line";
    const std::string expect = first.substr(tag.size());

    // Compile under a relative name, as a user would name it.
    const auto r = compile_file(file, options());
    const std::string out = rendered(r);
    EXPECT_FALSE(r.ok()) << file;
    bool located = false;
    for (const auto& d : r.diagnostics) located = located || (d.where.line > 0 && d.where.column > 0);
    EXPECT_TRUE(located) << file << "\n" << out;
    const std::string want = expect.rfind("error:", 0) == 0 ? expect : file.string() + ":" + expect;
    EXPECT_NE(out.find(want), std::string::npos) << "expected `" << want << "` in:\n" << out;
    EXPECT_NE(out.find("generated."), std::string::npos);
  }
}

}  // namespace
}  // namespace esc::compiler
