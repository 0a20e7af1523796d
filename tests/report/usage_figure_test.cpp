// The paper's Figure 2 as an SVG file: one figure per controller that chooses behaviors,
// useless behaviors (their library marked) in a panel of their own, one line per library
// when a panel would hold more than 8, nothing for a classical controller or for usage not
// stored (a database older than schema 4); the panels the report's chart draws are the same
// ones, and the line is the median over runs, the band between the quartiles (inside
// [0, 10,000] calls, where a mean ± one sd fell below zero).
#include "runtime/report/usage_figure.hpp"

#include <gtest/gtest.h>

#include <fmt/format.h>

namespace esc::report {
namespace {

// A supervisor over `go` and `copies` listings of library junk's `crash` (marked useless when
// `marked`): 2 runs of 2 generations, each best evaluation 100 steps, `go` acting in 25.
store::StoredController supervisor(std::size_t copies, bool marked, bool with_usage = true) {
  store::StoredController c;
  c.name = "SV";
  c.head = "supervisor";
  c.actions.push_back("go");
  c.choices.push_back({"go", "go", "", false, 0});
  for (std::size_t k = 0; k < copies; ++k) {
    const std::string name = k == 0 ? "crash" : fmt::format("crash_{}", k + 1);
    c.actions.push_back(name);
    c.choices.push_back({name, "junk.crash", "junk", marked, static_cast<int>(k + 1)});
  }
  for (int r = 0; r < 2; ++r) {
    eval::RunResult run;
    run.run = r;
    for (int g = 0; g < 2; ++g) {
      eval::GenerationStats s{g, 1.0, 0.5, 0.1, 4, 400, 0.0, {}};
      if (with_usage) {
        s.usage.steps_total = 100;
        s.usage.best.assign(c.actions.size(), 0);
        s.usage.best[0] = 25;
        s.usage.best[1] = 75;
        s.usage.mean.assign(c.actions.size(), 1.0);
      }
      run.generations.push_back(s);
    }
    c.finished.push_back(run);
  }
  return c;
}

store::StoredExperiment experiment(store::StoredController c) {
  store::StoredExperiment e;
  e.name = "sens";
  e.status = "finished";
  store::StoredController classical;
  classical.name = "CC";
  classical.head = "classical";
  classical.finished = c.finished;
  e.controllers = {std::move(c), std::move(classical)};
  return e;
}

TEST(UsageFigure, UselessBehaviorsApartAndOneLinePerLibraryWhenMany) {
  const std::vector<NamedFigure> f = usage_figures(experiment(supervisor(20, true)), "sens");
  ASSERT_EQ(f.size(), 1u);   // CC chooses nothing
  EXPECT_EQ(f[0].file, "sens-usage-SV.svg");
  for (const char* text : {">useful behaviors<", ">useless behaviors<", ">go<", ">junk (20 behaviors)<",
                           ">calls per 10,000 steps<", "experiment sens"})
    EXPECT_NE(f[0].svg.find(text), std::string::npos) << text;
  EXPECT_EQ(f[0].svg.find(">crash_2<"), std::string::npos);
}

TEST(UsageFigure, FewBehaviorsOneLineEachInOnePanelWhenNoneIsMarked) {
  const std::vector<NamedFigure> f = usage_figures(experiment(supervisor(4, false)), "e");
  ASSERT_EQ(f.size(), 1u);
  for (const char* text : {">behaviors<", ">go<", ">crash<", ">crash_4<"})
    EXPECT_NE(f[0].svg.find(text), std::string::npos) << text;
  EXPECT_EQ(f[0].svg.find(">useless behaviors<"), std::string::npos);
  EXPECT_EQ(f[0].svg.find("(4 behaviors)"), std::string::npos);
}

// What the report's chart reads (usage_panels in its JSON): the same grouping.
TEST(UsageFigure, ThePanelsAreWhatTheReportDraws) {
  const std::vector<UsagePanel> many = usage_panels(supervisor(20, true));
  ASSERT_EQ(many.size(), 2u);
  EXPECT_EQ(many[0].title, "useful behaviors");
  EXPECT_FALSE(many[0].by_library);
  ASSERT_EQ(many[0].lines.size(), 1u);
  EXPECT_EQ(many[0].lines[0].label, "go");
  EXPECT_EQ(many[1].title, "useless behaviors");
  EXPECT_TRUE(many[1].by_library);
  ASSERT_EQ(many[1].lines.size(), 1u);
  EXPECT_EQ(many[1].lines[0].label, "junk (20 behaviors)");
  EXPECT_EQ(many[1].lines[0].indices.size(), 20u);
  const std::vector<UsagePanel> few = usage_panels(supervisor(4, false));
  ASSERT_EQ(few.size(), 1u);
  EXPECT_EQ(few[0].title, "behaviors");
  EXPECT_EQ(few[0].lines.size(), 5u);
}

// A line whose runs differ more than its mean (a mean ± one sd would reach below 0): the
// median and the quartiles stay among the runs' values.
TEST(UsageFigure, MedianAndQuartilesNeverGoBelowZero) {
  store::StoredController c = supervisor(1, false);
  c.finished[1].generations[0].usage.best = {0, 100};   // `go` 25 and 0: mean 12.5, sd 17.7
  const std::vector<NamedFigure> f = usage_figures(experiment(c), "e");
  ASSERT_EQ(f.size(), 1u);
  // The note, wrapped to the figure's width.
  EXPECT_NE(f[0].svg.find("line: median over the finished runs; band: from the"), std::string::npos);
  EXPECT_NE(f[0].svg.find(">first to the third quartile across runs.<"), std::string::npos);
  // The axis covers the bands: no tick below 0.
  EXPECT_EQ(f[0].svg.find(">-"), std::string::npos);
  EXPECT_EQ(f[0].svg.find(">\u2212"), std::string::npos);
}

TEST(UsageFigure, NoneWithoutStoredUsage) {
  EXPECT_TRUE(usage_figures(experiment(supervisor(4, true, false)), "old").empty());
}

}  // namespace
}  // namespace esc::report
