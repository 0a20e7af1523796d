// The report's figures: the paper's Figure 1 for an experiment (maximum, mean and best so
// far over runs, per controller), box plots, a study's box plots by condition, and a sweep's
// final fitness against the swept value (numeric when the values are numbers in one unit,
// categorical otherwise); and a report over a study names every figure once.
#include "runtime/report/figures.hpp"

#include <gtest/gtest.h>

#include "runtime/report/html_report.hpp"

namespace esc::report {
namespace {

store::StoredController controller(const std::string& name, double offset) {
  store::StoredController c;
  c.name = name;
  c.head = "classical";
  for (int r = 0; r < 2; ++r) {
    eval::RunResult run;
    run.run = r;
    // Run 1's best falls in generation 2: the best so far stays at generation 1's.
    run.generations = {{0, offset + r, 0, 0, 1, 1, 0}, {1, offset + 10 + r, 0, 0, 1, 1, 0},
                       {2, offset + 5 + r, 0, 0, 1, 1, 0}};
    run.best_fitness = offset + 10 + r;
    c.finished.push_back(run);
  }
  return c;
}

store::StoredExperiment point(const std::string& value, std::optional<double> x, int index, double offset) {
  store::StoredExperiment e;
  e.name = "base";
  e.status = "finished";
  e.controllers = {controller("SC", offset), controller("CC", offset / 2)};
  e.condition = store::StoredCondition{"st", 1, index, "time_constant=" + value, "time_constant=" + value, 0,
                                       {{"robot.time_constant", value, true, x, x ? "ms" : ""}}};
  return e;
}

TEST(Figures, AnExperimentsFitnessCurvesAndBoxPlot) {
  const store::StoredExperiment e = point("50ms", 50.0, 0, 100.0);
  const std::vector<NamedFigure> f = experiment_figures(e, "st-x");
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].file, "st-x-fitness.svg");
  EXPECT_EQ(f[1].file, "st-x-best.svg");
  for (const char* panel : {">maximum over runs<", ">mean over runs<", ">best so far (mean over runs)<"})
    EXPECT_NE(f[0].svg.find(panel), std::string::npos) << panel;
  EXPECT_NE(f[0].svg.find("condition time_constant=50ms of study st"), std::string::npos);
  // On the data's scale: SC's runs are 110 and 111, CC's 60 and 61.
  EXPECT_EQ(f[1].svg.find(">0</text>"), std::string::npos);
}

TEST(Figures, ASweepIsDrawnAgainstItsValues) {
  const store::StoredExperiment a = point("200ms", 200.0, 1, 50.0), b = point("50ms", 50.0, 0, 100.0);
  const std::vector<NamedFigure> f = study_figures({&b, &a}, "st");
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f[0].file, "st-best-by-condition.svg");
  EXPECT_EQ(f[1].file, "st-sweep.svg");
  EXPECT_NE(f[1].svg.find(">robot.time_constant (ms)<"), std::string::npos);
  EXPECT_NE(f[1].svg.find(">200</text>"), std::string::npos);
  // Words: a categorical axis, in the order given.
  const store::StoredExperiment w1 = point("fast", std::nullopt, 0, 1.0), w2 = point("slow", std::nullopt, 1, 2.0);
  const std::vector<NamedFigure> g = study_figures({&w1, &w2}, "w");
  ASSERT_EQ(g.size(), 2u);
  EXPECT_NE(g[1].svg.find(">fast</text>"), std::string::npos);
  EXPECT_NE(g[1].svg.find(">robot.time_constant<"), std::string::npos);
}

TEST(Figures, AReportOverAStudyNamesEveryFigureOnce) {
  const Report r = make_report({{"dir", {point("50ms", 50.0, 0, 100.0), point("200ms", 200.0, 1, 50.0)}},
                                {"dir2", {point("50ms", 50.0, 0, 100.0)}}});
  std::set<std::string> files;
  for (const NamedFigure& f : r.figures) EXPECT_TRUE(files.insert(f.file).second) << f.file;
  EXPECT_TRUE(files.count("st-sweep.svg"));
  EXPECT_TRUE(files.count("st-2-sweep.svg"));
  ASSERT_EQ(r.data["studies"].size(), 2u);
  EXPECT_EQ(r.data["studies"][0]["conditions"].size(), 2u);
  EXPECT_EQ(r.data["studies"][0]["pairs"].size(), 4u);   // 2 within, 2 across
  EXPECT_EQ(r.data["experiments"][1]["condition"], "time_constant=200ms");
  EXPECT_EQ(r.data["experiments"][2]["directory"], "dir2");
}

}  // namespace
}  // namespace esc::report
